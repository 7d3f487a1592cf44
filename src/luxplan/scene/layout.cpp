#include <luxplan/scene/layout.h>

#include <cmath>

namespace luxplan {
namespace {

// `value` on the grid of `scale` steps per unit, `towards` first, then the other
// way, each kept only if `allowed`; else `value` itself. A value on the grid stays.
template <class Allowed>
double roundToGrid(double value, double scale, RoundTowards towards, Allowed&& allowed) {
    if (!std::isfinite(value)) return value;
    const double steps = value * scale;
    const double nearest = std::round(steps) / scale;
    if (nearest == value) return value;
    const double down = std::floor(steps) / scale, up = std::ceil(steps) / scale;
    double first = nearest, second = nearest == down ? up : down;
    if (towards == RoundTowards::Down) first = down, second = up;
    if (towards == RoundTowards::Up) first = up, second = down;
    if (allowed(first)) return first;
    if (allowed(second)) return second;
    return value;
}

}  // namespace

Layout initialLayout(const Scene& scene) {
    Layout layout;
    for (const Entity& e : scene.entities) {
        Placement p;
        p.position = e.position;
        p.rotationDeg = e.rotationDeg;
        p.region = findRegion(e.regions, {e.position.x, e.position.y}, e.rotationDeg);
        layout.placements.push_back(p);
    }
    return layout;
}

Placement roundedPlacement(const Entity& entity, const Placement& placement, RoundTowards x, RoundTowards y,
                           RoundTowards rotation) {
    const Region* region = placement.region >= 0 && size_t(placement.region) < entity.regions.size()
                               ? &entity.regions[size_t(placement.region)]
                               : nullptr;
    Placement p = placement;
    p.position.x = roundToGrid(placement.position.x, kLayoutPositionScale, x, [&](double v) {
        return !region || (v >= region->lo.x && v <= region->hi.x);
    });
    p.position.y = roundToGrid(placement.position.y, kLayoutPositionScale, y, [&](double v) {
        return !region || (v >= region->lo.y && v <= region->hi.y);
    });
    p.rotationDeg = roundToGrid(placement.rotationDeg, kLayoutRotationScale, rotation, [&](double v) {
        // The rotation alone: the box's corner is in the box.
        return !region || regionContains(*region, region->lo, v);
    });
    return p;
}

Layout roundedLayout(const Scene& scene, const Layout& layout) {
    Layout rounded = layout;
    for (size_t i = 0; i < scene.entities.size() && i < layout.placements.size(); ++i)
        if (scene.entities[i].movable()) rounded.placements[i] = roundedPlacement(scene.entities[i], layout.placements[i]);
    return rounded;
}

Transform localTransform(const Placement& p) { return Transform::placement(p.position, p.rotationDeg); }

std::vector<Transform> worldTransforms(const Scene& scene, const Layout& layout) {
    std::vector<Transform> world(scene.entities.size());
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        Transform local = localTransform(layout.placements[i]);
        int parent = scene.entities[i].parent;
        world[i] = parent >= 0 ? world[parent] * local : local;
    }
    return world;
}

}  // namespace luxplan
