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

// layout.json's precision: x and y to 0.1 mm (4 decimals in metres), rotations to
// 0.01 degree. A value on that grid is k / kLayoutPositionScale (or k /
// kLayoutRotationScale): the double a JSON reader makes of its 4 (2) decimals.
inline constexpr double kLayoutPositionScale = 1e4;  // steps per metre
inline constexpr double kLayoutRotationScale = 100;  // steps per degree

// Which way a value goes to the grid: the nearest step, or the one below or above.
enum class RoundTowards { Nearest, Down, Up };

// The placement as layout.json writes it: x, y and the rotation on the grid (z, the
// plane the entity moves on, as it is). A value already on the grid stays. A rounding
// that would take the placement out of its region (the box, by any margin; the
// rotations) goes the other way; where neither way stays inside (a region narrower
// than a step, a discrete rotation off the grid) the value stays as it is. So
// rounding a rounded placement changes nothing, whichever way either went.
Placement roundedPlacement(const Entity& entity, const Placement& placement, RoundTowards x = RoundTowards::Nearest,
                           RoundTowards y = RoundTowards::Nearest, RoundTowards rotation = RoundTowards::Nearest);
// Every movable entity's placement rounded to the nearest step (roundedPlacement);
// the others as they are.
Layout roundedLayout(const Scene& scene, const Layout& layout);

}  // namespace luxplan
