#include <luxplan/incremental/footprint_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace luxplan {
namespace {

// Two doubles in one SSE2 register (GCC's vector extensions; every x86-64 has SSE2), for
// tests of two segments at a time, and the lanes' comparisons (all bits set where true).
using Pair = double __attribute__((vector_size(16)));
using PairMask = long long __attribute__((vector_size(16)));
Pair pair(double x) { return Pair{x, x}; }
Pair absolute(Pair x) { return Pair(PairMask(x) & ~PairMask(pair(-0.0))); }
// a where `take` is set, else b; bitwise, since `take ? a : b` becomes a branch per lane.
Pair select(PairMask take, Pair a, Pair b) { return Pair((take & PairMask(a)) | (~take & PairMask(b))); }

}  // namespace

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

SegmentBoxFilter::SegmentBoxFilter(const Bounds3& box) {
    if (box.empty()) return;
    // Double rounds a segment's midpoint and the cross products by about 1e-16 of the
    // coordinates involved (up to 1e6 m, PathFootprint::add); a micrometre of pad
    // adds at least 1e-6 times the segment's half-length to each side of the cross
    // terms, far above that.
    constexpr double kPad = 1e-6;
    for (int k = 0; k < 3; ++k) {
        centre_[k] = 0.5 * (box.lo[k] + box.hi[k]);
        half_[k] = 0.5 * (box.hi[k] - box.lo[k]) + kPad;
    }
}

uint32_t SegmentBoxFilter::mayMeet(const Segment* segments, uint32_t n) const {
    // Two segments in the two lanes of a Pair; an odd last one shares the pair with
    // itself. The same arithmetic as one segment at a time, so the same answers, in half
    // the time.
    const Pair half = pair(0.5);
    uint32_t mask = 0;
    for (uint32_t i = 0; i < n; i += 2) {
        const Segment& s0 = segments[i];
        const Segment& s1 = segments[std::min(i + 1, n - 1)];
        Pair m[3], d[3], a[3];
        for (int k = 0; k < 3; ++k) {
            const Pair from = {double(s0.from[k]), double(s1.from[k])}, to = {double(s0.to[k]), double(s1.to[k])};
            d[k] = half * (to - from);
            m[k] = half * (to + from) - centre_[k];
            a[k] = absolute(d[k]);
        }
        const PairMask apart = (absolute(m[0]) > half_[0] + a[0]) | (absolute(m[1]) > half_[1] + a[1]) |
                               (absolute(m[2]) > half_[2] + a[2]) |
                               (absolute(m[1] * d[2] - m[2] * d[1]) > half_[1] * a[2] + half_[2] * a[1]) |
                               (absolute(m[2] * d[0] - m[0] * d[2]) > half_[0] * a[2] + half_[2] * a[0]) |
                               (absolute(m[0] * d[1] - m[1] * d[0]) > half_[0] * a[1] + half_[1] * a[0]);
        mask |= uint32_t(apart[0] == 0) << i | uint32_t(apart[1] == 0 && i + 1 < n) << (i + 1);
    }
    return mask;
}

TriangleProximity::TriangleProximity(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = cross(b - a, c - a);
    const double area2 = length(n);
    if (!(area2 > 0)) {  // a zero edge or three points in a line
        degenerate_ = true;
        return;
    }
    const std::array<Vec3, 3> v{a, b, c};
    normal_ = n / area2;
    offset_ = dot(normal_, a);
    for (int k = 0; k < 3; ++k) {
        const Vec3& from = v[size_t(k)];
        const Vec3 edge = v[size_t((k + 1) % 3)] - from;
        edgeNormal_[size_t(k)] = normalize(cross(normal_, edge));  // inward for a counter-clockwise (a, b, c) about n
        edgeOffset_[size_t(k)] = dot(edgeNormal_[size_t(k)], from);
    }
}

bool TriangleProximity::near(const Vec3& p, const Vec3& q, double margin) const {
    if (degenerate_) return true;
    const double dp = dot(normal_, p) - offset_, dq = dot(normal_, q) - offset_;
    if ((dp > margin && dq > margin) || (dp < -margin && dq < -margin)) return false;
    // The part of the segment inside the slab |distance| <= margin.
    double t0 = 0, t1 = 1;
    if (dp != dq) {
        double a = (dp - margin) / (dp - dq), b = (dp + margin) / (dp - dq);
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    const Vec3 x0 = p + (q - p) * t0, x1 = p + (q - p) * t1;
    for (int k = 0; k < 3; ++k) {
        const Vec3& m = edgeNormal_[size_t(k)];
        const double o = edgeOffset_[size_t(k)] - margin;
        if (dot(m, x0) < o && dot(m, x1) < o) return false;
    }
    return true;
}

PlacedBoxes::PlacedBoxes(const Transform& worldFromLocal, const std::vector<Bounds3>& local, double margin,
                         double relativeMargin, const std::vector<BoxedTriangles>* triangles)
    : localFromWorld_(worldFromLocal.inverse()), tight_(&local), triangles_(triangles) {
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
    localMargin_ = localBy;
    for (const Bounds3& b : local) local_.push_back({b.lo - Vec3(localBy, localBy, localBy), b.hi + Vec3(localBy, localBy, localBy)});
}

bool PlacedBoxes::meets(const Segment& s, const SegmentProbe& probe) const {
    if (!probe.meets(world_)) return false;
    auto local = [&](const std::array<float, 3>& p) { return localFromWorld_.applyPoint({p[0], p[1], p[2]}); };
    const Vec3 from = local(s.from), to = local(s.to);
    const SegmentProbe inFrame(from, to);
    for (size_t k = 0; k < local_.size(); ++k) {
        if (!inFrame.meets(local_[k])) continue;
        if (!triangles_ || (*triangles_)[k].triangles.empty()) return true;
        const BoxedTriangles& boxed = (*triangles_)[k];
        if (boxed.coversBox && inFrame.meets((*tight_)[k])) return true;
        for (const TriangleProximity& t : boxed.triangles)
            if (t.near(from, to, localMargin_)) return true;
    }
    return false;
}

PartsInside::PartsInside(const Bounds3& clip) {
    for (int k = 0; k < 3; ++k) lo_[k] = clip.lo[k] - kWiden, hi_[k] = clip.hi[k] + kWiden;
}

Bounds3 PartsInside::of(std::span<const Segment> segments) const {
    // Two segments in the two lanes of a Pair (as SegmentBoxFilter); an odd last one
    // shares the pair with itself. Every segment is clipped, without branches:
    // half of a path's segments leave the room (to the sky, through a window), and a
    // branch on it would be a coin's toss. Along an axis where a segment does not move,
    // the slab distances are infinite (no limit inside the slab, an empty part outside
    // it; where it lies in a widened slab's plane, outside the clip box itself, a NaN
    // that leaves it empty or passes over). Multiplying by a reciprocal can round an ulp
    // away from dividing: the widening is far more, so no part inside is lost.
    Pair lo[3] = {pair(kInf), pair(kInf), pair(kInf)}, hi[3] = {pair(-kInf), pair(-kInf), pair(-kInf)};
    const size_t n = segments.size();
    for (size_t i = 0; i < n; i += 2) {
        const Segment& s0 = segments[i];
        const Segment& s1 = segments[std::min(i + 1, n - 1)];
        Pair from[3], d[3], t0 = pair(0), t1 = pair(1);
        for (int k = 0; k < 3; ++k) {
            from[k] = Pair{double(s0.from[k]), double(s1.from[k])};
            d[k] = Pair{double(s0.to[k]), double(s1.to[k])} - from[k];
            const Pair inverse = 1.0 / d[k];
            const Pair a = (lo_[k] - from[k]) * inverse, b = (hi_[k] - from[k]) * inverse;
            const PairMask ordered = a < b;
            const Pair enter = select(ordered, a, b), leave = select(ordered, b, a);
            t0 = select(t0 < enter, enter, t0);  // a NaN's comparisons are false: t0 stays
            t1 = select(leave < t1, leave, t1);
        }
        const PairMask inside = t0 <= t1;
        for (int k = 0; k < 3; ++k) {
            const Pair p = from[k] + d[k] * t0, q = from[k] + d[k] * t1;
            const PairMask ordered = p < q;
            const Pair least = select(ordered, p, q), most = select(ordered, q, p);
            lo[k] = select(inside & (least < lo[k]), least, lo[k]);
            hi[k] = select(inside & (most > hi[k]), most, hi[k]);
        }
    }
    Bounds3 box;
    for (int lane = 0; lane < 2; ++lane)
        if (lo[0][lane] <= hi[0][lane])
            box.extend(Bounds3(Vec3(lo[0][lane], lo[1][lane], lo[2][lane]), Vec3(hi[0][lane], hi[1][lane], hi[2][lane])));
    return box;
}

}  // namespace luxplan
