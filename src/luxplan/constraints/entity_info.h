// Per-entity facts the constraints need that do not change while optimizing:
// own bounds, the geometry below each group, ancestry, and whether it can move.
#pragma once

#include <vector>

#include <luxplan/scene/scene.h>

namespace luxplan {

class EntityInfo {
public:
    explicit EntityInfo(const Scene& scene);

    // Bounds of the entity's own parts in its frame (empty without geometry).
    const Bounds3& localBounds(int e) const { return bounds_[e]; }
    // The entity and all its descendants that have geometry.
    const std::vector<int>& geometrySubtree(int e) const { return subtree_[e]; }
    // Whether one of the two is an ancestor of the other (or they are the same), or
    // the pair is in Scene::overlap.exempt.
    bool related(int a, int b) const;
    // Whether the entity or one of its ancestors is movable (so its world transform can change).
    bool canMove(int e) const { return canMove_[e]; }

private:
    const Scene* scene_;
    std::vector<Bounds3> bounds_;
    std::vector<std::vector<int>> subtree_;
    std::vector<bool> canMove_;
};

// The entity's centre in world space (Eqs. 5, 7): the centre of the bounding box of
// its geometry (for a group: of its own parts and all its descendants', boxed in the
// group's frame), or its origin when there is no geometry below it.
Vec3 entityCenter(const EntityInfo& info, const std::vector<Transform>& world, int e);

}  // namespace luxplan
