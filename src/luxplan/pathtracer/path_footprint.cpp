#include <luxplan/pathtracer/path_footprint.h>

#include <algorithm>

namespace luxplan {
namespace {

// Rays with no end stop here: far outside any room (coordinates are limited to about
// 1e5 m), and near enough that float keeps the direction to a few 1e-8.
constexpr double kFar = 1e6;

std::array<float, 3> toFloat(const Vec3& p) { return {float(p.x), float(p.y), float(p.z)}; }

}  // namespace

void PathFootprint::add(const Vec3& p, const Vec3& d, double tMin, double tEnd) {
    const double len = length(d);
    if (!(len > 0)) return;
    const double end = std::min(tEnd, kFar / len);
    segments.push_back({toFloat(p + d * tMin), toFloat(p + d * end)});
}

SegmentProbe::SegmentProbe(const Segment& s) {
    for (size_t axis = 0; axis < 3; ++axis) {
        from_[axis] = s.from[axis];
        const double d = double(s.to[axis]) - double(s.from[axis]);
        flat_[axis] = d == 0;
        inv_[axis] = flat_[axis] ? 0 : 1 / d;
    }
}

bool SegmentProbe::meets(const Bounds3& b) const {
    // Slabs: the parameter interval [t0, t1] of the segment inside each.
    double t0 = 0, t1 = 1;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = b.lo[axis], hi = b.hi[axis], from = from_[axis];
        if (flat_[axis]) {
            if (from < lo || from > hi) return false;
            continue;
        }
        double a = (lo - from) * inv_[axis], c = (hi - from) * inv_[axis];
        if (a > c) std::swap(a, c);
        t0 = std::max(t0, a), t1 = std::min(t1, c);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace luxplan
