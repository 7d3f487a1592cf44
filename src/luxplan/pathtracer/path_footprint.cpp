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

SegmentProbe::SegmentProbe(const Segment& s) : SegmentProbe(Vec3(s.from[0], s.from[1], s.from[2]), Vec3(s.to[0], s.to[1], s.to[2])) {}

SegmentProbe::SegmentProbe(const Vec3& from, const Vec3& to) {
    for (int axis = 0; axis < 3; ++axis) {
        from_[axis] = from[axis];
        const double d = to[axis] - from[axis];
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

PlacedBoxes::PlacedBoxes(const Transform& worldFromLocal, const std::vector<Bounds3>& local, double margin,
                         double relativeMargin)
    : localFromWorld_(worldFromLocal.inverse()) {
    for (const Bounds3& b : local)
        for (int corner = 0; corner < 8; ++corner)
            world_.extend(worldFromLocal.applyPoint(
                {corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y, corner & 4 ? b.hi.z : b.lo.z}));
    if (world_.empty()) return;
    const double scale = std::max({std::abs(world_.lo.x), std::abs(world_.lo.y), std::abs(world_.lo.z),
                                   std::abs(world_.hi.x), std::abs(world_.hi.y), std::abs(world_.hi.z)});
    const double by = margin + relativeMargin * scale;
    world_ = {world_.lo - Vec3(by, by, by), world_.hi + Vec3(by, by, by)};
    // A world distance stretches in the local frame by at most the largest singular
    // value of the inverse's linear part, which its Frobenius norm bounds.
    double frobenius = 0;
    for (double v : localFromWorld_.m) frobenius += v * v;
    const double localBy = by * std::sqrt(frobenius);
    for (const Bounds3& b : local) local_.push_back({b.lo - Vec3(localBy, localBy, localBy), b.hi + Vec3(localBy, localBy, localBy)});
}

bool PlacedBoxes::meets(const Segment& s, const SegmentProbe& probe) const {
    if (!probe.meets(world_)) return false;
    auto local = [&](const std::array<float, 3>& p) { return localFromWorld_.applyPoint({p[0], p[1], p[2]}); };
    const SegmentProbe inFrame(local(s.from), local(s.to));
    for (const Bounds3& b : local_)
        if (inFrame.meets(b)) return true;
    return false;
}

}  // namespace luxplan
