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

// What changed from one layout to another: per entity whether its world transform
// changed, the boxes of every moved entity's clusters at its old and its new pose, their
// union, and whether a luminaire moved.
struct Move {
    std::vector<char> entityMoved;
    std::vector<PlacedBoxes> boxes;  // refer to the EntityClusters' boxes
    Bounds3 bounds;
    bool emittersMoved = false;
};

class EntityClusters {
public:
    explicit EntityClusters(const Scene& scene);
    // Entity `entity`'s boxes (its triangles' clusters, then one per luminaire), in its
    // own frame, and per box the triangles it bounds (none for a luminaire's).
    const std::vector<Bounds3>& boxes(size_t entity) const { return boxes_[entity]; }
    const std::vector<BoxedTriangles>& triangles(size_t entity) const { return triangles_[entity]; }

    // The move from `before` to `after` (world transforms per entity; `before` empty:
    // nothing moved). Boxes are widened by 1 mm and 1e-6 of the largest coordinate: Embree
    // traces in float and pane crossings step 0.1 mm off the line.
    Move moveBetween(const Scene& scene, const std::vector<Transform>& before, const std::vector<Transform>& after) const;

private:
    std::vector<std::vector<Bounds3>> boxes_;
    std::vector<std::vector<BoxedTriangles>> triangles_;
};

}  // namespace luxplan
