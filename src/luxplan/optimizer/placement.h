// Placement sampling (paper 5.1): uniform draws from an entity's valid parameter
// partitions X_m (scene/region.h: a box for the origin plus a rotation set or
// interval), in the base measure regionMeasure() defines.
#pragma once

#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

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
