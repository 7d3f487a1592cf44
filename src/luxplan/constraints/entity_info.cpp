// Static per-entity data and entity centres for the relational constraints.
#include <luxplan/constraints/entity_info.h>

namespace luxplan {

EntityInfo::EntityInfo(const Scene& scene)
    : scene_(&scene), bounds_(scene.entities.size()), subtree_(scene.entities.size()), canMove_(scene.entities.size()) {
    const auto& entities = scene.entities;
    for (size_t i = 0; i < entities.size(); ++i) {
        if (entities[i].hasGeometry()) bounds_[i] = entities[i].mesh.bounds();
        // Entities are stored depth first (a parent before its children).
        int parent = entities[i].parent;
        canMove_[i] = entities[i].movable() || (parent >= 0 && canMove_[parent]);
    }
    for (size_t i = 0; i < entities.size(); ++i) {
        if (!entities[i].hasGeometry()) continue;
        for (int e = int(i); e >= 0; e = entities[e].parent) subtree_[e].push_back(int(i));
    }
}

bool EntityInfo::related(int a, int b) const {
    for (int e = a; e >= 0; e = scene_->entities[e].parent)
        if (e == b) return true;
    for (int e = b; e >= 0; e = scene_->entities[e].parent)
        if (e == a) return true;
    for (auto [x, y] : scene_->overlap.exempt)
        if ((x == a && y == b) || (x == b && y == a)) return true;
    return false;
}

Vec3 entityCenter(const EntityInfo& info, const std::vector<Transform>& world, int e) {
    const auto& subtree = info.geometrySubtree(e);
    if (subtree.empty()) return world[e].t;
    Transform groupFromWorld = world[e].inverse();
    Bounds3 box;
    for (int d : subtree) box.extend((groupFromWorld * world[d]).apply(info.localBounds(d)));
    return world[e].applyPoint(box.center());
}

}  // namespace luxplan
