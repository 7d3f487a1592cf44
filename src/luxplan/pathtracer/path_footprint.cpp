#include <luxplan/pathtracer/path_footprint.h>

#include <algorithm>
#include <cmath>
#include <limits>

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

void PathFootprint::addOcclusion(const Vec3& p, const Vec3& d, double tMin, double tEnd, unsigned mask, bool blocked) {
    const size_t before = segments.size();
    add(p, d, tMin, tEnd);
    if (segments.size() == before) return;
    OcclusionTest t;
    t.origin = toFloat(p), t.direction = toFloat(d);
    t.tNear = float(tMin);
    t.tFar = std::isinf(tEnd) ? std::numeric_limits<float>::infinity() : float(tEnd);
    t.mask = mask, t.segment = uint32_t(before), t.blocked = blocked;
    tests.push_back(t);
}

}  // namespace luxplan
