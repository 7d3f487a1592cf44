#include <luxplan/scene/region.h>

#include <algorithm>

namespace luxplan {
namespace {

// The lowest and highest rotation a region allows (degrees, as written).
std::pair<double, double> rotationBounds(const Region& r) {
    if (r.continuousRotation) return {r.rotationMinDeg, r.rotationMaxDeg};
    auto [lo, hi] = std::minmax_element(r.rotationsDeg.begin(), r.rotationsDeg.end());
    return {*lo, *hi};
}

// A rotation interval written with its start in [0, 360), at most a full turn.
void setInterval(Region& r, double from, double to) {
    r.continuousRotation = true;
    r.rotationsDeg.clear();
    if (to - from >= 360) {
        r.rotationMinDeg = 0, r.rotationMaxDeg = 360;
        return;
    }
    double shift = from - wrapDegrees(from);
    r.rotationMinDeg = from - shift, r.rotationMaxDeg = to - shift;
}

}  // namespace

bool sameRotation(double aDeg, double bDeg) {
    double diff = wrapDegrees(aDeg - bDeg);
    return diff < kRotationToleranceDeg || diff > 360.0 - kRotationToleranceDeg;
}

bool regionContains(const Region& r, Vec2 xy, double rotationDeg, double eps) {
    if (xy.x < r.lo.x - eps || xy.x > r.hi.x + eps || xy.y < r.lo.y - eps || xy.y > r.hi.y + eps) return false;
    if (r.continuousRotation) {
        if (r.rotationMaxDeg - r.rotationMinDeg >= 360) return true;
        double from = wrapDegrees(r.rotationMinDeg), span = r.rotationMaxDeg - r.rotationMinDeg;
        double offset = wrapDegrees(rotationDeg - from);
        return offset <= span + kRotationToleranceDeg || offset >= 360 - kRotationToleranceDeg;
    }
    for (double a : r.rotationsDeg)
        if (sameRotation(rotationDeg, a)) return true;
    return false;
}

int findRegion(const std::vector<Region>& regions, Vec2 xy, double rotationDeg) {
    for (size_t i = 0; i < regions.size(); ++i)
        if (regionContains(regions[i], xy, rotationDeg, kRegionTolerance)) return int(i);
    return -1;
}

std::vector<double> distinctRotations(const Region& region) {
    std::vector<double> out;
    for (double r : region.rotationsDeg) {
        bool seen = false;
        for (double o : out) seen = seen || sameRotation(o, r);
        if (!seen) out.push_back(r);
    }
    return out;
}

bool fullTurn(const Region& region) {
    return region.continuousRotation && region.rotationMaxDeg - region.rotationMinDeg >= 360.0;
}

double normalizeRotation(const Region& region, double rotationDeg) {
    if (!region.continuousRotation) return rotationDeg;
    double offset = wrapDegrees(rotationDeg - region.rotationMinDeg);
    // regionContains() accepts an offset a hair below 360 as the range's start.
    if (offset > 360.0 - kRotationToleranceDeg) offset = 0;
    return region.rotationMinDeg + offset;
}

double regionMeasure(const Region& region) {
    auto extent = [](double lo, double hi) { return hi > lo ? hi - lo : 1.0; };
    double rotation = 1;
    if (region.continuousRotation) {
        double span = std::min(radians(region.rotationMaxDeg - region.rotationMinDeg), 2 * kPi);
        rotation = span > 0 ? span : 1.0;
    } else {
        rotation = double(std::max<size_t>(1, distinctRotations(region).size()));
    }
    return extent(region.lo.x, region.hi.x) * extent(region.lo.y, region.hi.y) * rotation;
}

std::vector<Region> composeRegions(const Region& parent, const Region& child) {
    std::vector<Region> out;
    const Vec2 corners[4] = {child.lo, {child.hi.x, child.lo.y}, child.hi, {child.lo.x, child.hi.y}};
    auto [childLo, childHi] = rotationBounds(child);
    if (!parent.continuousRotation) {
        for (double theta : distinctRotations(parent)) {
            Transform rot = Transform::rotateZ(radians(theta));
            Region r;
            r.bound = child.bound;
            Vec2 lo(kInf, kInf), hi(-kInf, -kInf);
            for (Vec2 c : corners) {
                Vec3 w = rot.applyVector({c.x, c.y, 0});
                lo = Vec2(std::min(lo.x, w.x), std::min(lo.y, w.y));
                hi = Vec2(std::max(hi.x, w.x), std::max(hi.y, w.y));
            }
            r.lo = parent.lo + lo, r.hi = parent.hi + hi;
            if (child.continuousRotation) setInterval(r, theta + childLo, theta + childHi);
            else
                for (double a : child.rotationsDeg) r.rotationsDeg.push_back(wrapDegrees(theta + a));
            out.push_back(r);
        }
        return out;
    }
    double reach = 0;
    for (Vec2 c : corners) reach = std::max(reach, length(c));
    Region r;
    r.bound = child.bound;
    r.lo = parent.lo - Vec2(reach, reach), r.hi = parent.hi + Vec2(reach, reach);
    setInterval(r, parent.rotationMinDeg + childLo, parent.rotationMaxDeg + childHi);
    out.push_back(r);
    return out;
}

}  // namespace luxplan
