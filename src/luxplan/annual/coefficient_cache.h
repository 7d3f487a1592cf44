// Daylight coefficients kept between layouts: the search measures the annual goals of
// each layout it tries, and most of a move leaves most paths as they were. Each point
// keeps its paths' light by basis (DaylightCoefficients::tracePath) with the paths'
// footprints, and its direct-sun rays, one per hour; measuring a moved layout traces
// again only
//   - every path and ray of a point whose sampler is carried by an entity that moved,
//   - a path or a direct-sun ray one of whose segments meets the old or the new boxes
//     of a moved entity (incremental/entity_clusters.h), and
//   - a path that read the emitter choice when a luminaire moved,
// and recomputes the hours of the points whose coefficients changed. The numbers are
// those of DaylightCoefficients::measure for the same layout, bit for bit
// (tests/annual/coefficient_cache_test.cpp). As the path cache (incremental/
// path_cache.h), a measurement is pending until commit() (the search accepted the
// layout) or discard().
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <luxplan/annual/daylight_coefficients.h>
#include <luxplan/incremental/entity_clusters.h>

namespace luxplan {

class CoefficientCache {
public:
    // Measures the samplers `which` (indices into Scene::samplers) of `year`, `paths` paths
    // per point from `seed`. `year` must outlive this.
    CoefficientCache(const Scene& scene, const DaylightCoefficients& year, std::vector<size_t> which, int paths,
                     uint64_t seed);

    // DaylightCoefficients::measure(tracer, which, paths, seed) at the tracer's layout
    // (the tracer under year.basis(), updated to its EmbreeScene's layout).
    AnnualSeries measure(const PathTracer& tracer);
    void commit();   // the measured layout's coefficients become the kept ones
    void discard();  // back to the kept ones

    // Of the last measurement: paths traced, and read back.
    uint64_t tracedPaths() const { return traced_; }
    uint64_t reusedPaths() const { return reused_; }
    const std::vector<size_t>& samplers() const { return which_; }

private:
    struct PathRecord {
        uint32_t firstEntry = 0, entryCount = 0, firstSegment = 0, segmentCount = 0;
        bool usedEmitterChoice = false;
    };
    // One point's paths and rays, its coefficients and hours.
    struct PointState {
        bool valid = false;
        std::vector<PathRecord> paths;
        std::vector<BasisEntry> entries;
        std::vector<Segment> segments;
        std::vector<Segment> sunRays;    // per hour (a zero-length one for an hour with the sun down)
        std::vector<double> sunFactors;  // per hour: directSun's
        std::vector<double> values, direct;  // per hour (DaylightCoefficients::hourly)
    };
    // Whether a segment meets what moved.
    bool meetsMove(const Segment& s) const;
    bool meetsMove(const Segment* segments, uint32_t count) const;
    // The point's state at the tracer's layout from `before` (invalid: traced whole);
    // false when every path and ray held (then `after` is untouched).
    bool update(const PathTracer& tracer, const PlacedSampler& placed, const DaylightCoefficients::Point& point,
                const PointState& before, bool pointMoved, PointState& after, uint64_t& traced) const;

    const Scene& scene_;
    const DaylightCoefficients& year_;
    std::vector<size_t> which_;
    int paths_;
    uint64_t seed_;
    EntityClusters clusters_;

    // Kept (committed) state: per sampler of which_, per item.
    bool hasCommitted_ = false;
    std::vector<Transform> world_;
    std::vector<std::vector<PointState>> committed_;
    // The measurement pending: the points it changed, (sampler, item) -> state.
    struct Change {
        size_t sampler;
        int item;
        PointState state;
    };
    std::vector<Change> pending_;
    std::vector<std::vector<char>> measured_;  // per sampler, per item: the pending measurement measured it
    std::vector<Transform> pendingWorld_;
    bool measuring_ = false;
    // What moved since the committed layout.
    std::vector<PlacedBoxes> moved_;
    Bounds3 movedUnion_;
    SegmentBoxFilter movedFilter_;
    bool emittersMoved_ = false;
    uint64_t traced_ = 0, reused_ = 0;
};

}  // namespace luxplan
