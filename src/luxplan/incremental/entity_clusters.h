// Each entity's geometry as boxes in its own frame, for the tests of footprints against
// a move (footprint_geometry.h's PlacedBoxes): its mesh's parts, split into clusters of
// about a dozen triangles each with the triangles themselves, and a box per luminaire.
// The path cache's (path_cache.h) and the daylight coefficients' (annual/
// coefficient_cache.h) moves are tested against them.
#pragma once

#include <vector>

#include <luxplan/incremental/footprint_geometry.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class EntityClusters {
public:
    explicit EntityClusters(const Scene& scene);
    // Entity `entity`'s boxes (its triangles' clusters, then one per luminaire), in its
    // own frame, and per box the triangles it bounds (none for a luminaire's).
    const std::vector<Bounds3>& boxes(size_t entity) const { return boxes_[entity]; }
    const std::vector<BoxedTriangles>& triangles(size_t entity) const { return triangles_[entity]; }

private:
    std::vector<std::vector<Bounds3>> boxes_;
    std::vector<std::vector<BoxedTriangles>> triangles_;
};

}  // namespace luxplan
