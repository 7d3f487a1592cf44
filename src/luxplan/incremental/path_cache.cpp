#include <luxplan/incremental/path_cache.h>

#include <algorithm>
#include <bit>
#include <limits>
#include <map>

#include <luxplan/core/parallel.h>
#include <luxplan/lightsamplers/fresh_paths.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {


constexpr float kInfF = std::numeric_limits<float>::infinity();
constexpr double kBoxPad = 1e-4;      // over the clipping's rounding (moved boxes carry 1 mm: EntityClusters::moveBetween)
constexpr double kReachMargin = 0.5;  // m around the room's box: where moves happen (reach_)
constexpr double kHeightPad = 0.01;   // m around the heights of what moves, far over moved boxes' margin

// The next float below and above x (finite), as std::nextafter towards -inf and +inf
// gives, without a call into the maths library.
float floatBelow(float x) {
    if (x == 0) return -std::numeric_limits<float>::denorm_min();
    const uint32_t bits = std::bit_cast<uint32_t>(x);
    return std::bit_cast<float>(x > 0 ? bits - 1 : bits + 1);
}
float floatAbove(float x) { return -floatBelow(-x); }

// How much of a path's footprint prefetchAfter() asks for ahead (a path's segments
// number about ten, 240 bytes).
constexpr size_t kPrefetchBytes = 512;
constexpr size_t kPrefetchPaths = 2;  // how far ahead

}  // namespace

PathCache::PathCache(const Scene& scene, size_t maxSegments) : scene_(scene), maxSegments_(maxSegments), clusters_(scene) {
    reach_ = Bounds3(Vec3(-kInf, -kInf, -kInf), Vec3(kInf, kInf, kInf));
    if (const RoomShell* room = scene.room()) {
        const Vec3 pad(kReachMargin, kReachMargin, kReachMargin);
        reach_ = Bounds3(room->box.lo - pad, room->box.hi + pad);
        // No move changes a height: every move keeps each placement's z and turns it
        // about the vertical (scene/layout.h, optimizer/moves.h), so what can move spans
        // the same heights in every layout. Rays above the desks and monitors (to the
        // ceiling, from it to a window) then leave a path's box, which misses every move.
        const Bounds3 moving = movingBounds(scene);
        if (!moving.empty()) {
            reach_.lo.z = std::max(reach_.lo.z, moving.lo.z - kHeightPad);
            reach_.hi.z = std::min(reach_.hi.z, moving.hi.z + kHeightPad);
        }
    }
    reachParts_ = PartsInside(reach_);
}

Bounds3 PathCache::movingBounds(const Scene& scene) const {
    const std::vector<Transform> world = worldTransforms(scene, initialLayout(scene));
    std::vector<char> moves(scene.entities.size(), 0);
    Bounds3 all;
    for (size_t i = 0; i < scene.entities.size(); ++i) {  // parents come before their children
        const Entity& e = scene.entities[i];
        moves[i] = e.movable() || (e.parent >= 0 && moves[size_t(e.parent)]);
        if (!moves[i]) continue;
        for (const Bounds3& b : clusters_.boxes(i))
            for (int corner = 0; corner < 8; ++corner)
                all.extend(world[i].applyPoint(
                    {corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y, corner & 4 ? b.hi.z : b.lo.z}));
    }
    return all;
}

void PathCache::begin(const EmbreeScene& rt, const std::vector<int>& workSampler, uint64_t streams) {
    rt_ = &rt;
    const size_t entities = scene_.entities.size();
    newWorld_.resize(entities);
    for (size_t i = 0; i < entities; ++i) newWorld_[i] = rt.worldFromEntity(int(i));
    if (!hasCommitted_ || streams != streams_ || committed_.size() != workSampler.size()) {
        committed_.assign(workSampler.size(), {});
        committedSegments_ = 0;
        hasCommitted_ = false;
        streams_ = streams;
    }

    Move move = clusters_.moveBetween(scene_, hasCommitted_ ? world_ : std::vector<Transform>{}, newWorld_);
    moved_ = std::move(move.boxes);
    movedUnion_ = move.bounds;
    emittersMoved_ = move.emittersMoved;
    const std::vector<char>& entityMoved = move.entityMoved;
    movedFilter_ = SegmentBoxFilter(movedUnion_);
    movedInReach_ = movedUnion_.empty() || (reach_.contains(movedUnion_.lo) && reach_.contains(movedUnion_.hi));
    workMoved_.assign(workSampler.size(), 0);
    for (size_t w = 0; w < workSampler.size(); ++w) {
        const int entity = scene_.samplers[size_t(workSampler[w])].entity;
        workMoved_[w] = entity >= 0 && entityMoved[size_t(entity)];
    }
    pending_.resize(workSampler.size());
    for (Pending& p : pending_) p.clear();
    pendingSegments_ = 0;
    reusedLast_ = askedAgainLast_ = 0;
    measuring_ = true;
}

PathCache::Verdict PathCache::check(size_t work, const Record& r, const Paths& in, bool requery) const {
    if (workMoved_[work]) return Verdict::Changed;
    if (emittersMoved_ && r.usedEmitterChoice) return Verdict::Changed;
    if (moved_.empty()) return Verdict::Missed;
    const Bounds3& u = movedUnion_;
    if (movedInReach_ && (r.hi[0] < u.lo.x || r.lo[0] > u.hi.x || r.hi[1] < u.lo.y || r.lo[1] > u.hi.y ||
                          r.hi[2] < u.lo.z || r.lo[2] > u.hi.z))
        return Verdict::Missed;
    const Segment* segments = in.segments.data() + r.firstSegment;
    const OcclusionTest* tests = in.tests.data() + r.firstTest;
    uint32_t test = 0;  // the first test whose segment is at or after the current one
    thread_local std::vector<const OcclusionTest*> again;
    again.clear();
    for (uint32_t first = 0; first < r.segmentCount; first += 32) {
        // The segments that may meet the move, 32 at a time, in order.
        for (uint32_t may = movedFilter_.mayMeet(segments + first, std::min(32u, r.segmentCount - first)); may != 0;
             may &= may - 1) {
            const uint32_t index = first + uint32_t(std::countr_zero(may));
            const Segment& s = segments[index];
            const SegmentProbe probe(s);
            bool meets = false;
            for (const PlacedBoxes& b : moved_)
                if (b.meets(s, probe)) {
                    meets = true;
                    break;
                }
            if (!meets) continue;
            if (!requery) return Verdict::Changed;
            while (test < r.testCount && tests[test].segment < index) ++test;
            if (test == r.testCount || tests[test].segment != index) return Verdict::Changed;
            again.push_back(&tests[test]);
        }
    }
    for (const OcclusionTest* t : again) {
        const Ray ray{Vec3(t->origin[0], t->origin[1], t->origin[2]), Vec3(t->direction[0], t->direction[1], t->direction[2]),
                      double(t->tNear), double(t->tFar), t->mask};
        if (rt_->occluded(ray) != t->blocked) return Verdict::Changed;
    }
    return again.empty() ? Verdict::Missed : Verdict::SameAnswers;
}

PathCache::Record PathCache::Paths::append(const Record& r, const Paths& from) {
    Record out = r;
    out.firstSegment = uint32_t(segments.size());
    out.firstTest = uint32_t(tests.size());
    segments.insert(segments.end(), from.segments.begin() + r.firstSegment, from.segments.begin() + r.firstSegment + r.segmentCount);
    tests.insert(tests.end(), from.tests.begin() + r.firstTest, from.tests.begin() + r.firstTest + r.testCount);
    return out;
}

void PathCache::prefetchAfter(const Paths& paths, size_t path) {
    // A work item's paths are asked for one after another, and a check waits on memory
    // for the path's segments (the kept paths take megabytes, the core's cache one):
    // those of the path after next are fetched while this one is checked or traced (the
    // next one's came with the last call; most checks take less than a fetch from
    // memory), and the record two further on, whose segments the call after next fetches.
    const auto& records = paths.records;
    if (path + kPrefetchPaths + 2 < records.size()) {
        const char* ahead = reinterpret_cast<const char*>(&records[path + kPrefetchPaths + 2]);
        __builtin_prefetch(ahead), __builtin_prefetch(ahead + sizeof(Record) - 1);
    }
    if (path + kPrefetchPaths < records.size() && records[path + kPrefetchPaths].kept) {
        const Record& n = records[path + kPrefetchPaths];
        const char* from = reinterpret_cast<const char*>(paths.segments.data() + n.firstSegment);
        const size_t bytes = std::min(size_t(n.segmentCount) * sizeof(Segment), kPrefetchBytes);
        for (size_t b = 0; b < bytes; b += 64) __builtin_prefetch(from + b);
    }
}

PathSource::Path PathCache::get(size_t work, int path, RayStats& stats, FreshPaths& fresh) {
    bool askedAgain = false;
    if (const PathContributions* kept = holds(work, path, askedAgain)) return {kept, true, askedAgain};
    return {&fresh.trace(work, path, stats, true), false, false};
}

void PathCache::used(size_t work, int path, const Path& p, const FootprintView& footprint) {
    visit(work, path, p.reused, p.askedAgain);
    if (!p.reused) keep(work, path, *p.contributions, footprint);
}

const PathContributions* PathCache::holds(size_t work, int path, bool& askedAgain) const {
    askedAgain = false;
    const Paths& committed = committed_[work];
    if (size_t(path) >= committed.records.size() || !committed.records[size_t(path)].kept) return nullptr;
    const Record& r = committed.records[size_t(path)];
    prefetchAfter(committed, size_t(path));
    const Verdict v = check(work, r, committed, true);
    if (v == Verdict::Changed) return nullptr;
    askedAgain = v == Verdict::SameAnswers;
    return &r.contributions;
}

void PathCache::visit(size_t work, int path, bool reused, bool askedAgain) {
    Pending& p = pending_[work];
    p.visited = std::max(p.visited, path + 1);
    p.reused += reused;
    p.askedAgain += reused && askedAgain;
}

void PathCache::keep(size_t work, int path, const PathContributions& contributions, const FootprintView& footprint) {
    const size_t n = footprint.segments.size();
    Pending& p = pending_[work];
    const bool fits = reserve(p, n);
    Record r;
    r.contributions = contributions;
    if (fits) {
        r.kept = true;
        r.usedEmitterChoice = footprint.usedEmitterChoice;
        r.firstSegment = uint32_t(p.traced.segments.size()), r.segmentCount = uint32_t(n);
        r.firstTest = uint32_t(p.traced.tests.size()), r.testCount = uint32_t(footprint.tests.size());
        p.traced.segments.insert(p.traced.segments.end(), footprint.segments.begin(), footprint.segments.end());
        const Bounds3 box = reachParts_.of(footprint.segments);
        for (int a = 0; a < 3; ++a) {  // padded, and rounded outwards to float
            r.lo[a] = box.empty() ? kInfF : floatBelow(float(box.lo[a] - kBoxPad));
            r.hi[a] = box.empty() ? -kInfF : floatAbove(float(box.hi[a] + kBoxPad));
        }
        p.traced.tests.insert(p.traced.tests.end(), footprint.tests.begin(), footprint.tests.end());
    }
    p.tracedPaths.push_back(path);
    p.traced.records.push_back(r);
}

bool PathCache::reserve(Pending& p, size_t n) {
    // Segments: a few hundred paths, but grants left unused at the end of a measurement
    // (at most one per work item) never hold back more than half of the bound.
    const size_t grant = std::min(size_t(4096), maxSegments_ / (2 * std::max(size_t(1), pending_.size())));
    if (p.granted < n) {
        size_t total = pendingSegments_.load(std::memory_order_relaxed);
        for (;;) {
            // A whole grant where it fits, else just n (a small bound is filled exactly).
            size_t want = std::max(n, grant);
            if (committedSegments_ + total + want > maxSegments_) want = n;
            if (committedSegments_ + total + want > maxSegments_) return false;
            if (pendingSegments_.compare_exchange_weak(total, total + want, std::memory_order_relaxed)) {
                p.granted += want;
                break;
            }
        }
    }
    p.granted -= n;
    return true;
}

std::span<const Segment> PathCache::segmentsOf(size_t work, int path) const {
    const Paths& committed = committed_[work];
    const Record& r = committed.records[size_t(path)];
    return {committed.segments.data() + r.firstSegment, r.segmentCount};
}

uint64_t PathCache::reused() const {
    if (!measuring_) return reusedLast_;
    uint64_t sum = 0;
    for (const Pending& p : pending_) sum += p.reused;
    return sum;
}

uint64_t PathCache::askedAgain() const {
    if (!measuring_) return askedAgainLast_;
    uint64_t sum = 0;
    for (const Pending& p : pending_) sum += p.askedAgain;
    return sum;
}

size_t PathCache::longestPath() const {
    size_t most = 0;
    for (const Paths& c : committed_)
        for (const Record& r : c.records)
            if (r.kept) most = std::max(most, size_t(r.segmentCount));
    return most;
}

void PathCache::commit() {
    if (!measuring_) return;
    parallelFor(committed_.size(), [&](size_t w) {
        Pending& p = pending_[w];
        Paths& committed = committed_[w];
        auto drop = [&](Record& r) {
            if (r.kept) committed.garbage += r.segmentCount, r = Record();
        };
        // Paths this measurement did not ask for hold for the new layout if the move
        // missed them (their shadow queries are not asked again: the scene may have been
        // set to another layout since, for a measurement outside the cache). Only as
        // many as it asked for are checked (the next measurement seldom needs more than
        // twice as many), so that a commit costs no more than the measurement's own
        // checks; the rest are dropped.
        auto& records = committed.records;
        const size_t visited = size_t(p.visited), checked = std::min(records.size(), 2 * visited);
        for (size_t path = visited; path < records.size(); ++path) {
            if (path < checked) prefetchAfter(committed, path);
            if (records[path].kept && (path >= checked || check(w, records[path], committed, false) == Verdict::Changed))
                drop(records[path]);
        }
        records.resize(std::max(checked, visited));
        // Every path asked for traced afresh, in order, and none kept beyond them (a
        // moved sampler's work item): the traced arrays become the committed ones as
        // they are, and the old ones go to the next measurement to fill (endMeasurement
        // clears them, keeping their memory). No copy, no allocation.
        bool tracedAll = p.tracedPaths.size() == visited;
        for (size_t i = 0; tracedAll && i < visited; ++i) tracedAll = size_t(p.tracedPaths[i]) == i;
        for (size_t path = visited; tracedAll && path < records.size(); ++path) tracedAll = !records[path].kept;
        if (tracedAll) {
            std::swap(committed, p.traced);
            committed.garbage = 0;
            return;
        }
        // The paths traced go to the end of the arrays; what they replace stays there
        // as garbage until it outweighs the rest.
        for (size_t i = 0; i < p.tracedPaths.size(); ++i) {
            Record& r = records[size_t(p.tracedPaths[i])];
            drop(r);
            if (p.traced.records[i].kept) r = committed.append(p.traced.records[i], p.traced);
        }
        if (2 * committed.garbage > committed.segments.size()) {
            // Into arrays of their own size: the old ones, garbage and all, are freed.
            Paths packed;
            packed.records.resize(records.size());
            packed.segments.reserve(committed.segments.size() - committed.garbage);
            for (size_t path = 0; path < records.size(); ++path)
                if (records[path].kept) packed.records[path] = packed.append(records[path], committed);
            committed = std::move(packed);
        }
    });
    committedSegments_ = 0;
    for (const Paths& c : committed_) committedSegments_ += c.segments.size() - c.garbage;
    world_ = newWorld_;
    hasCommitted_ = true;
    endMeasurement();
}

void PathCache::discard() {
    if (measuring_ && hasCommitted_) {
        // A path traced for the refused layout, where the committed one has none, holds
        // for the committed layout too if the move missed it (the test is symmetric in
        // the old and the new bounds): kept, so the next measurement need not trace it.
        for (size_t w = 0; w < committed_.size(); ++w) {
            Paths& committed = committed_[w];
            const Pending& p = pending_[w];
            for (size_t i = 0; i < p.tracedPaths.size(); ++i) {
                const size_t path = size_t(p.tracedPaths[i]);
                const Record& t = p.traced.records[i];
                if (!t.kept || (path < committed.records.size() && committed.records[path].kept) ||
                    check(w, t, p.traced, false) == Verdict::Changed)
                    continue;
                if (committedSegments_ + t.segmentCount > maxSegments_) continue;
                if (committed.records.size() <= path) committed.records.resize(path + 1);
                committed.records[path] = committed.append(t, p.traced);
                committedSegments_ += t.segmentCount;
            }
        }
    }
    endMeasurement();
}

void PathCache::endMeasurement() {
    reusedLast_ = reused(), askedAgainLast_ = askedAgain();
    measuring_ = false;
    for (Pending& p : pending_) p.clear();
    pendingSegments_ = 0;
}

}  // namespace luxplan
