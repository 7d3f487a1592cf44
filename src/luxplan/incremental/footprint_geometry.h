// The geometric tests of the path cache (path_cache.h): whether a path's footprint
// (pathtracer/path_footprint.h: its rays as float segments) meets what a move changed.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/pathtracer/path_footprint.h>

namespace luxplan {

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
