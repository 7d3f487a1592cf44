#include <luxplan/lightsamplers/path_cache.h>

#include <algorithm>

#include <luxplan/emitters/emitter_shape.h>

namespace luxplan {
namespace {

bool same(const Transform& a, const Transform& b) { return a.m == b.m && a.t.x == b.t.x && a.t.y == b.t.y && a.t.z == b.t.z; }

Bounds3 worldBounds(const Transform& world, const Bounds3& local) {
    Bounds3 b;
    for (int corner = 0; corner < 8; ++corner)
        b.extend(world.applyPoint({corner & 1 ? local.hi.x : local.lo.x, corner & 2 ? local.hi.y : local.lo.y,
                                   corner & 4 ? local.hi.z : local.lo.z}));
    return b;
}

// Embree traces in float and pane crossings step 0.1 mm off the line: a margin well
// above both, growing with the coordinates.
Bounds3 widened(const Bounds3& b) {
    const double scale = std::max({std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z), std::abs(b.hi.x), std::abs(b.hi.y),
                                   std::abs(b.hi.z)});
    const double margin = 1e-3 + 1e-6 * scale;
    return {b.lo - Vec3(margin, margin, margin), b.hi + Vec3(margin, margin, margin)};
}

}  // namespace

PathCache::PathCache(const Scene& scene, size_t maxSegments) : scene_(scene), maxSegments_(maxSegments) {
    localBounds_.resize(scene.entities.size());
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& e = scene.entities[i];
        if (e.hasGeometry()) localBounds_[i].extend(e.mesh.bounds());
        for (int em : e.emitters) {
            const EmitterShape& shape = *scene.emitters[size_t(em)].shape;
            const double r = shape.reach();
            localBounds_[i].extend(Bounds3(shape.center() - Vec3(r, r, r), shape.center() + Vec3(r, r, r)));
        }
    }
}

void PathCache::begin(const EmbreeScene& rt, const std::vector<int>& workSampler, uint64_t seed) {
    const size_t entities = scene_.entities.size();
    newWorld_.resize(entities);
    for (size_t i = 0; i < entities; ++i) newWorld_[i] = rt.worldFromEntity(int(i));
    if (!hasCommitted_ || seed != seed_ || records_.size() != workSampler.size()) {
        records_.assign(workSampler.size(), {});
        committedSegments_ = 0;
        hasCommitted_ = false;
        seed_ = seed;
    }

    moved_.clear();
    emittersMoved_ = false;
    std::vector<char> entityMoved(entities, 0);
    if (hasCommitted_)
        for (size_t i = 0; i < entities; ++i) {
            if (same(world_[i], newWorld_[i])) continue;
            entityMoved[i] = 1;
            if (!localBounds_[i].empty()) {
                moved_.push_back(widened(worldBounds(world_[i], localBounds_[i])));
                moved_.push_back(widened(worldBounds(newWorld_[i], localBounds_[i])));
            }
            if (!scene_.entities[i].emitters.empty()) emittersMoved_ = true;
        }
    workMoved_.assign(workSampler.size(), 0);
    for (size_t w = 0; w < workSampler.size(); ++w) {
        const int entity = scene_.samplers[size_t(workSampler[w])].entity;
        workMoved_[w] = entity >= 0 && entityMoved[size_t(entity)];
    }
    pending_.assign(workSampler.size(), {});
    pendingSegments_ = 0;
    reusedNow_ = 0;
    measuring_ = true;
}

bool PathCache::stillHolds(size_t work, const Record& r) const {
    if (workMoved_[work]) return false;
    if (emittersMoved_ && r.footprint.usedEmitterChoice) return false;
    for (const Segment& s : r.footprint.segments)
        for (const Bounds3& b : moved_)
            if (meets(s, b, 0)) return false;
    return true;
}

const PathCache::Record* PathCache::reuse(size_t work, int path) {
    Pending& p = pending_[work];
    p.visited = std::max(p.visited, path + 1);
    const auto& records = records_[work];
    if (size_t(path) >= records.size() || !records[size_t(path)]) return nullptr;
    const Record& r = *records[size_t(path)];
    if (!stillHolds(work, r)) return nullptr;
    ++reusedNow_;
    return &r;
}

void PathCache::keep(size_t work, int path, Record&& record) {
    const size_t n = record.footprint.segments.size();
    const bool fits = committedSegments_ + pendingSegments_.fetch_add(n) + n <= maxSegments_;
    pending_[work].traced.emplace_back(path, fits ? std::optional<Record>(std::move(record)) : std::nullopt);
}

void PathCache::commit() {
    if (!measuring_) return;
    for (size_t w = 0; w < records_.size(); ++w) {
        Pending& p = pending_[w];
        auto& records = records_[w];
        // Paths this measurement did not ask for were not checked against the move.
        records.resize(size_t(p.visited));
        for (auto& [path, record] : p.traced) records[size_t(path)] = std::move(record);
    }
    committedSegments_ = 0;
    for (const auto& records : records_)
        for (const auto& r : records)
            if (r) committedSegments_ += r->footprint.segments.size();
    world_ = newWorld_;
    hasCommitted_ = true;
    discard();
}

void PathCache::discard() {
    measuring_ = false;
    for (Pending& p : pending_) p = Pending();
    pendingSegments_ = 0;
}

}  // namespace luxplan
