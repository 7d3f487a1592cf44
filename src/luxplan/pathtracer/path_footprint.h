// What one path's rays met: the segments they covered (each ray from its origin to its
// hit, or to its end), and whether the path read the emitter choice, whose
// probabilities depend on every luminaire's position. A path whose footprint misses
// everything a move changes traces the same as before it (lightsamplers/path_cache.h).
#pragma once

#include <array>
#include <cstdint>
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

struct PathFootprint {
    std::vector<Segment> segments;
    std::vector<OcclusionTest> tests;  // in the order of their segments
    bool usedEmitterChoice = false;    // sampled an emitter, or weighed a hit on one by MIS

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

// Whether a segment passes through boxes (widen a box for a margin), tested box after
// box with its divisions done once.
class SegmentProbe {
public:
    explicit SegmentProbe(const Segment& s);
    SegmentProbe(const Vec3& from, const Vec3& to);
    bool meets(const Bounds3& b) const;

private:
    double from_[3], inv_[3];
    bool flat_[3];  // no extent along the axis
};

// Boxes given in an object's own frame and placed in the world by its transform:
// oriented boxes, so that a segment past the corner of a rotated desk does not meet
// it. Each is widened by margin + relativeMargin * (the largest world coordinate of
// the whole) in world units.
class PlacedBoxes {
public:
    PlacedBoxes(const Transform& worldFromLocal, const std::vector<Bounds3>& local, double margin, double relativeMargin);
    // The world box around them all (widened too).
    const Bounds3& worldBounds() const { return world_; }
    // `probe` is SegmentProbe(s), for the quick test against worldBounds() first.
    bool meets(const Segment& s, const SegmentProbe& probe) const;

private:
    Bounds3 world_;
    Transform localFromWorld_;
    std::vector<Bounds3> local_;  // widened
};

}  // namespace luxplan
