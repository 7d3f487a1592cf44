// Placement sampling (paper 5.1): uniform draws from an entity's valid parameter
// partitions X_m (regions: a box for the origin plus a rotation set or interval).
#pragma once

#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// Whether two angles (degrees) are the same orientation (modulo 360, within 1e-6).
bool sameRotation(double aDeg, double bDeg);

// The region's discrete rotations, each orientation once (modulo 360; the first
// spelling kept).
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

// Uniform in region `region`: position uniform in its box, rotation uniform among its
// rotations or in its interval; z is kept.
Placement sampleInRegion(const Entity& entity, int region, double z, Rng& rng);

// Uniform on the union of the entity's regions: a region with probability
// proportional to regionMeasure(), then uniform inside it. The entity must be movable.
Placement samplePlacement(const Entity& entity, double z, Rng& rng);

// Every movable entity drawn with samplePlacement (at its z in `base`); immovable
// entities keep their placement in `base`. The paper's initial state (Section 6).
Layout sampleLayout(const Scene& scene, const Layout& base, Rng& rng);

}  // namespace luxplan
