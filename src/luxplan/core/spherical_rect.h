// Uniform sampling of the solid angle a rectangle subtends from a point (Ureña,
// Fajardo, King 2013, "An Area-Preserving Parametrization for Spherical Rectangles",
// EGSR; the paper's [UnFK13]). Used for window portals and rect emitters: every
// sample has pdf 1 / solidAngle, so no distance or cosine terms add variance.
#pragma once

#include <luxplan/core/math.h>

namespace luxplan {

// A rectangle: corner + two orthogonal edges.
struct Rect3 {
    Vec3 corner, edgeU, edgeV;
    Vec3 center() const { return corner + (edgeU + edgeV) * 0.5; }
    double area() const { return length(cross(edgeU, edgeV)); }
    Vec3 normal() const { return normalize(cross(edgeU, edgeV)); }
    // Ray parameter t > 0 where p + t w crosses the rectangle, or a negative value.
    double intersect(const Vec3& p, const Vec3& w) const;
};

// A rectangle that many rays are tested against (window panes, portals): its normal and
// squared edge lengths computed once, the crossing then the same arithmetic as
// Rect3::intersect's.
class RectTarget {
public:
    RectTarget() = default;
    explicit RectTarget(const Rect3& r)
        : rect_(r), n_(cross(r.edgeU, r.edgeV)), uu_(dot(r.edgeU, r.edgeU)), vv_(dot(r.edgeV, r.edgeV)) {}
    const Rect3& rect() const { return rect_; }
    double intersect(const Vec3& p, const Vec3& w) const {
        const double denom = dot(n_, w);
        if (denom == 0) return -1;
        const double t = dot(n_, rect_.corner - p) / denom;
        if (t <= 0) return -1;
        const Vec3 q = p + w * t - rect_.corner;
        const double a = dot(q, rect_.edgeU) / uu_, b = dot(q, rect_.edgeV) / vv_;
        return (a >= 0 && a <= 1 && b >= 0 && b <= 1) ? t : -1;
    }

private:
    Rect3 rect_;
    Vec3 n_;
    double uu_ = 1, vv_ = 1;
};

// The spherical rectangle of `rect` seen from `origin`.
class SphericalRect {
public:
    SphericalRect() = default;
    SphericalRect(const Rect3& rect, const Vec3& origin);
    // Solid angle (sr); 0 when the origin lies in the rectangle's plane.
    double solidAngle() const { return solidAngle_; }
    // A point on the rectangle whose direction from the origin is uniform in the solid angle.
    Vec3 sample(Vec2 u) const;

private:
    Vec3 origin_, x_, y_, z_;
    double x0_ = 0, y0_ = 0, z0_ = 0, x1_ = 0, y1_ = 0;
    double b0_ = 0, b1_ = 0, k_ = 0, solidAngle_ = 0;
};

}  // namespace luxplan
