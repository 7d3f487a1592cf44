// What one path's rays met: the segments they covered (each ray from its origin to its
// hit, or to its end), and whether the path read the emitter choice, whose
// probabilities depend on every luminaire's position. A path whose footprint misses
// everything a move changes traces the same as before it (lightsamplers/path_cache.h).
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

// A box for the first, cheap test of many segments against it: no divisions and no
// branch per axis (the separating axis theorem: the box's three axes and their cross
// products with the segment), two segments at a time. Padded for rounding, so that it
// never says "apart" of a segment that SegmentProbe says meets the box; it may say
// "may meet" of one a micrometre outside.
class SegmentBoxFilter {
public:
    SegmentBoxFilter() = default;
    explicit SegmentBoxFilter(const Bounds3& box);
    // Bit i: segments[i] may meet the box (n <= 32).
    uint32_t mayMeet(const Segment* segments, uint32_t n) const;
    bool mayMeet(const Segment& s) const { return mayMeet(&s, 1) != 0; }

private:
    double centre_[3] = {}, half_[3] = {-1, -1, -1};  // an empty box: nothing meets it
};

// The box of segments' parts inside a clip box (a kept path's box, clipped to where
// moves happen). It holds every part inside the clip box, and at most the parts inside
// the clip box widened by a micrometre.
class PartsInside {
public:
    PartsInside() = default;
    explicit PartsInside(const Bounds3& clip);
    Bounds3 of(std::span<const Segment> segments) const;  // empty if no part is inside

private:
    static constexpr double kWiden = 1e-6;  // m: over the clipping's rounding
    double lo_[3] = {}, hi_[3] = {-1, -1, -1};  // the clip box, widened
};

// A triangle prepared for "does a segment come within a margin of it?": its plane and
// its edges' inward normals in that plane, so that the test is a few dot products.
class TriangleProximity {
public:
    TriangleProximity(const Vec3& a, const Vec3& b, const Vec3& c);
    // False only if every point of [p, q] lies farther than `margin` from the triangle
    // (a degenerate triangle always says true). The points within the margin lie in the
    // slab |plane distance| <= margin and inside every edge's line moved out by the
    // margin; the part of the segment in the slab is tested against each edge line.
    bool near(const Vec3& p, const Vec3& q, double margin) const;

private:
    Vec3 normal_;  // unit; the plane is dot(normal_, x) = offset_
    double offset_ = 0;
    std::array<Vec3, 3> edgeNormal_{};  // unit, in the plane, pointing inside
    std::array<double, 3> edgeOffset_{};
    bool degenerate_ = false;
};

// The triangles that one of PlacedBoxes' boxes bounds. `coversBox`: they cover most of
// the box's faces (a box part), so that a segment entering the box itself is taken to
// meet them without testing each (saying "meets" is always safe: the path is traced
// again).
struct BoxedTriangles {
    std::vector<TriangleProximity> triangles;  // none: the box alone decides
    bool coversBox = false;
};

// Boxes given in an object's own frame and placed in the world by its transform:
// oriented boxes, so that a segment past the corner of a rotated desk does not meet
// it. Each is widened by margin + relativeMargin * (the largest world coordinate of
// the whole) in world units. A box may come with the triangles it bounds: a segment
// that crosses the box then meets it only if it comes within the margin of one of
// them (a ray between a chair's legs misses the chair, not only its box).
class PlacedBoxes {
public:
    // `triangles`, where given, has an entry per box of `local`. Both must outlive this
    // (it keeps `local` for the boxes as given).
    PlacedBoxes(const Transform& worldFromLocal, const std::vector<Bounds3>& local, double margin, double relativeMargin,
                const std::vector<BoxedTriangles>* triangles = nullptr);
    // The world box around them all (widened too).
    const Bounds3& worldBounds() const { return world_; }
    // `probe` is SegmentProbe(s), for the quick test against worldBounds() first.
    bool meets(const Segment& s, const SegmentProbe& probe) const;

private:
    Bounds3 world_;
    Transform localFromWorld_;
    const std::vector<Bounds3>* tight_;  // as given
    std::vector<Bounds3> local_;         // widened
    double localMargin_ = 0;             // the margin in the local frame (at least the world's)
    const std::vector<BoxedTriangles>* triangles_ = nullptr;
};

}  // namespace luxplan
