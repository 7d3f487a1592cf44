// What one path's rays met: the segments they covered (each ray from its origin to its
// hit, or to its end), and whether the path read the emitter choice, whose
// probabilities depend on every luminaire's position. The tracer records it where
// PathParams::footprint asks; a path whose footprint misses everything a move changes
// traces the same as before it (incremental/path_cache.h, which tests footprints
// against what moved with incremental/footprint_geometry.h).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

struct Segment {
    std::array<float, 3> from, to;
};

// An any-hit (shadow) query as Embree received it (in float), and its answer. A move
// that changes the scene along the query's segment changes nothing downstream unless
// it changes the answer, so the path cache asks the query again instead of tracing the
// whole path.
struct OcclusionTest {
    std::array<float, 3> origin, direction;
    float tNear = 0, tFar = 0;
    unsigned mask = 0;
    uint32_t segment = 0;  // its segment's index in PathFootprint::segments
    bool blocked = false;
};

// A path's footprint, wherever it is stored.
struct FootprintView {
    std::span<const Segment> segments;
    std::span<const OcclusionTest> tests;  // OcclusionTest::segment counts in `segments`
    bool usedEmitterChoice = false;
};

struct PathFootprint {
    std::vector<Segment> segments;
    std::vector<OcclusionTest> tests;  // in the order of their segments
    bool usedEmitterChoice = false;    // sampled an emitter, or weighed a hit on one by MIS

    FootprintView view() const { return {segments, tests, usedEmitterChoice}; }
    void clear() {
        segments.clear();
        tests.clear();
        usedEmitterChoice = false;
    }
    // Appends p + t d for t in [tMin, tEnd] (tEnd may be infinite: the segment then runs
    // far past any room).
    void add(const Vec3& p, const Vec3& d, double tMin, double tEnd);
    // The segment of an any-hit query for p + t d, t in [tMin, tEnd], mask `mask`, that
    // answered `blocked`: its rays are what the query's floats are.
    void addOcclusion(const Vec3& p, const Vec3& d, double tMin, double tEnd, unsigned mask, bool blocked);
};

}  // namespace luxplan
