#include <luxplan/scene/layout.h>

namespace luxplan {

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
