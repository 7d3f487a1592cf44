// Layout state: the degrees of freedom of every entity (region, x, y, rotation)
// and the world transforms they produce through the group hierarchy.
#pragma once

#include <vector>

#include <luxplan/scene/scene.h>

namespace luxplan {

// One entity's placement in its parent's frame. z stays at its initial value.
struct Placement {
    int region = -1;  // index into Entity::regions; -1 for immovable entities
    Vec3 position;
    double rotationDeg = 0;
};

struct Layout {
    std::vector<Placement> placements;  // one per Scene::entities entry
};

// The placement the scene file gives (region: the first that holds it, else -1).
Layout initialLayout(const Scene& scene);

// parentFromEntity for one entity: rotate about z by its rotation, then translate.
Transform localTransform(const Placement& placement);

// worldFromEntity for every entity (parents are composed before children).
std::vector<Transform> worldTransforms(const Scene& scene, const Layout& layout);

}  // namespace luxplan
