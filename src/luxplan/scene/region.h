// A valid parameter partition X_m (the paper's Section 5.1): a box for an entity's
// origin in its parent's frame and a set or interval of rotations. Everything that
// asks whether a placement lies in a region, finds, measures or composes regions is
// here, with its tolerances named once.
#pragma once

#include <utility>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

// What a region's box bounds: the entity's origin (the paper's X_m), or its whole
// footprint (the floor projection of its parts' bounding boxes, its descendants'
// included; constraints/footprint.h). Proposals draw the origin in the box either
// way; a footprint that leaves it is rejected as a geometric rule.
enum class RegionBound { Origin, Footprint };

struct Region {
    Vec2 lo, hi;
    RegionBound bound = RegionBound::Origin;
    std::vector<double> rotationsDeg;  // discrete set, or
    bool continuousRotation = false;   // an interval [rotationMinDeg, rotationMaxDeg]
    double rotationMinDeg = 0, rotationMaxDeg = 0;
};

// Two rotations closer than this (degrees, modulo 360) are the same orientation.
inline constexpr double kRotationToleranceDeg = 1e-6;
// How far (metres) a placement read from a file, or derived through transforms, may
// lie outside a region and still be found in it: float error, not a design margin.
inline constexpr double kRegionTolerance = 1e-6;

// Whether two angles (degrees) are the same orientation.
bool sameRotation(double aDeg, double bDeg);

// Whether (x, y, rotation) lies in the region, the position within `eps` of its box
// (0: exactly, as a proposal must), the rotation modulo 360.
bool regionContains(const Region& region, Vec2 xy, double rotationDeg, double eps = 0);
// The first of `regions` holding the placement within kRegionTolerance, or -1.
int findRegion(const std::vector<Region>& regions, Vec2 xy, double rotationDeg);

// The region's discrete rotations, each orientation once (the first spelling kept).
std::vector<double> distinctRotations(const Region& region);
// Whether a rotation interval covers the full turn (then it wraps around).
bool fullTurn(const Region& region);
// The rotation written inside the region's own range: an interval [a, b] gets a
// value in [a, a + 360) (so inside [a, b] when the region holds it); discrete
// regions keep the value as given.
double normalizeRotation(const Region& region, double rotationDeg);

// The region's size in the optimizer's base measure: the product over x and y of
// the extent (m; a zero extent counts 1) and of the rotation measure (the number of
// distinct discrete rotations, or the interval's span in radians, at most 2 pi; an
// empty span counts 1). Uniform sampling on the union of regions and the Hastings
// factor of interval jumps both use it.
double regionMeasure(const Region& region);

// Where a child can be in its grandparent's frame when its parent is anywhere in
// `parent` and the child anywhere in `child` (the parent's frame). A discrete parent
// rotation gives one region per rotation (exact for quarter turns, the bounding box
// otherwise); an interval gives one region bounded by the child's largest offset.
// The regions keep the child's bound.
std::vector<Region> composeRegions(const Region& parent, const Region& child);

}  // namespace luxplan
