#include <luxplan/annual/coefficient_cache.h>

#include <bit>
#include <span>

#include <luxplan/core/parallel.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {
CoefficientCache::CoefficientCache(const Scene& scene, const DaylightCoefficients& year, std::vector<size_t> which,
                                   int paths, uint64_t seed)
    : scene_(scene), year_(year), which_(std::move(which)), paths_(std::max(1, paths)), seed_(seed), clusters_(scene) {}

bool CoefficientCache::meetsMove(const Segment& s) const {
    if (!movedFilter_.mayMeet(s)) return false;
    const SegmentProbe probe(s);
    for (const PlacedBoxes& b : moved_)
        if (b.meets(s, probe)) return true;
    return false;
}

bool CoefficientCache::meetsMove(const Segment* segments, uint32_t count) const {
    for (uint32_t first = 0; first < count; first += 32)
        for (uint32_t may = movedFilter_.mayMeet(segments + first, std::min(32u, count - first)); may != 0; may &= may - 1) {
            const Segment& s = segments[first + uint32_t(std::countr_zero(may))];
            const SegmentProbe probe(s);
            for (const PlacedBoxes& b : moved_)
                if (b.meets(s, probe)) return true;
        }
    return false;
}

bool CoefficientCache::update(const PathTracer& tracer, const PlacedSampler& placed, const DaylightCoefficients::Point& point,
                              const PointState& before, bool pointMoved, PointState& after, uint64_t& traced) const {
    const bool whole = !before.valid || pointMoved;
    const std::vector<DaylightInstant>& hours = year_.hours();
    // Which paths and rays the move changes.
    std::vector<char> pathChanged(size_t(paths_), 1), rayChanged(hours.size(), 1);
    bool any = whole;
    if (!whole) {
        for (size_t p = 0; p < size_t(paths_); ++p) {
            const PathRecord& r = before.paths[p];
            pathChanged[p] = (emittersMoved_ && r.usedEmitterChoice) ||
                             meetsMove(before.segments.data() + r.firstSegment, r.segmentCount);
            any = any || pathChanged[p];
        }
        for (size_t h = 0; h < hours.size(); ++h) {
            rayChanged[h] = meetsMove(before.sunRays[h]);
            any = any || rayChanged[h];
        }
    }
    if (!any) return false;

    after = PointState();
    after.valid = true;
    after.paths.resize(size_t(paths_));
    RayStats stats;
    const PathSamples::Sequence sequence = DaylightCoefficients::sequenceOf(point.sampler, point.item, seed_);
    std::vector<BasisEntry> entries;
    PathFootprint footprint;
    PointCoefficients c = year_.emptyCoefficients();
    for (int p = 0; p < paths_; ++p) {
        PathRecord& r = after.paths[size_t(p)];
        r.firstEntry = uint32_t(after.entries.size());
        r.firstSegment = uint32_t(after.segments.size());
        if (pathChanged[size_t(p)]) {
            footprint.clear();
            year_.tracePath(tracer, placed, sequence, point.sampler, point.item, p, seed_, entries, stats, &footprint);
            after.entries.insert(after.entries.end(), entries.begin(), entries.end());
            after.segments.insert(after.segments.end(), footprint.segments.begin(), footprint.segments.end());
            r.usedEmitterChoice = footprint.usedEmitterChoice;
            ++traced;
        } else {
            const PathRecord& old = before.paths[size_t(p)];
            after.entries.insert(after.entries.end(), before.entries.begin() + old.firstEntry,
                                 before.entries.begin() + old.firstEntry + old.entryCount);
            after.segments.insert(after.segments.end(), before.segments.begin() + old.firstSegment,
                                  before.segments.begin() + old.firstSegment + old.segmentCount);
            r.usedEmitterChoice = old.usedEmitterChoice;
        }
        r.entryCount = uint32_t(after.entries.size()) - r.firstEntry;
        r.segmentCount = uint32_t(after.segments.size()) - r.firstSegment;
        // Summed path after path, as DaylightCoefficients::coefficients sums them.
        year_.add(std::span<const BasisEntry>(after.entries).subspan(r.firstEntry), c);
    }
    DaylightCoefficients::scale(c, paths_);

    const std::unique_ptr<Sensor> sensor = placed.sensorOf(point.item);
    after.sunRays.resize(hours.size());
    after.sunFactors.assign(hours.size(), 0.0);
    for (size_t h = 0; h < hours.size(); ++h) {
        if (!rayChanged[h]) {
            after.sunRays[h] = before.sunRays[h];
            after.sunFactors[h] = before.sunFactors[h];
            continue;
        }
        footprint.clear();
        if (hours[h].sunUp()) after.sunFactors[h] = tracer.directSun(*sensor, hours[h].sunDirection, stats, &footprint);
        after.sunRays[h] = footprint.segments.empty() ? Segment{} : footprint.segments.front();
    }
    c.direct = after.sunFactors;
    year_.hourly(c, after.values, after.direct);
    return true;
}

AnnualSeries CoefficientCache::measure(const PathTracer& tracer) {
    const EmbreeScene& rt = tracer.rayTracer();
    const size_t entities = scene_.entities.size();
    pendingWorld_.resize(entities);
    for (size_t i = 0; i < entities; ++i) pendingWorld_[i] = rt.worldFromEntity(int(i));

    // What moved since the committed layout.
    Move move = clusters_.moveBetween(scene_, hasCommitted_ ? world_ : std::vector<Transform>{}, pendingWorld_);
    moved_ = std::move(move.boxes);
    movedUnion_ = move.bounds;
    emittersMoved_ = move.emittersMoved;
    const std::vector<char>& entityMoved = move.entityMoved;
    movedFilter_ = SegmentBoxFilter(movedUnion_);

    std::vector<std::unique_ptr<PlacedSampler>> placed;
    const std::vector<DaylightCoefficients::Point> points = DaylightCoefficients::points(scene_, tracer, which_, placed);
    if (committed_.size() != which_.size()) committed_.assign(which_.size(), {});
    for (size_t s = 0; s < which_.size(); ++s)
        if (committed_[s].size() != size_t(placed[s]->items())) committed_[s].assign(size_t(placed[s]->items()), {});

    const PointState invalid;
    std::vector<PointState> changed(points.size());
    std::vector<char> isChanged(points.size(), 0);
    std::vector<uint64_t> tracedBy(points.size(), 0);
    parallelFor(points.size(), [&](size_t w) {
        const DaylightCoefficients::Point& pt = points[w];
        const int carrier = scene_.samplers[pt.sampler].entity;
        const bool pointMoved = carrier >= 0 && entityMoved[size_t(carrier)];
        const PointState& before = hasCommitted_ ? committed_[pt.placed][size_t(pt.item)] : invalid;
        isChanged[w] = update(tracer, *placed[pt.placed], pt, before, pointMoved, changed[w], tracedBy[w]);
    });

    std::vector<std::vector<double>> values(points.size()), direct(points.size());
    pending_.clear();
    measured_.assign(which_.size(), {});
    for (size_t s = 0; s < which_.size(); ++s) measured_[s].assign(size_t(placed[s]->items()), 0);
    for (const DaylightCoefficients::Point& pt : points) measured_[pt.placed][size_t(pt.item)] = 1;
    traced_ = 0;
    for (size_t w = 0; w < points.size(); ++w) {
        const DaylightCoefficients::Point& pt = points[w];
        traced_ += tracedBy[w];
        const PointState& state = isChanged[w] ? changed[w] : committed_[pt.placed][size_t(pt.item)];
        values[w] = state.values, direct[w] = state.direct;
        if (isChanged[w]) pending_.push_back({pt.placed, pt.item, std::move(changed[w])});
    }
    reused_ = uint64_t(points.size()) * uint64_t(paths_) - traced_;
    measuring_ = true;
    return year_.series(scene_, which_, placed, points, values, direct);
}

void CoefficientCache::commit() {
    if (!measuring_) return;
    for (Change& c : pending_) committed_[c.sampler][size_t(c.item)] = std::move(c.state);
    pending_.clear();
    // A point the layout covers was not measured: what it kept may no longer hold.
    for (size_t s = 0; s < committed_.size(); ++s)
        for (size_t i = 0; i < committed_[s].size(); ++i)
            if (!measured_[s][i]) committed_[s][i] = PointState();
    world_ = pendingWorld_;
    hasCommitted_ = true;
    measuring_ = false;
}

void CoefficientCache::discard() {
    pending_.clear();
    measuring_ = false;
}

}  // namespace luxplan
