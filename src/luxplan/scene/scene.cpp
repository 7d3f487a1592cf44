#include <luxplan/scene/scene.h>

namespace luxplan {

double Emitter::area() const {
    switch (shape) {
        case EmitterShape::Rect: return size.x * size.y;
        case EmitterShape::Disk: return kPi * radius * radius;
        case EmitterShape::Sphere: return 4 * kPi * radius * radius;
    }
    return 0;
}

int Scene::findEntity(const std::string& path) const {
    for (size_t i = 0; i < entities.size(); ++i)
        if (entities[i].path == path) return int(i);
    return -1;
}

const RoomShell* Scene::room() const {
    for (const auto& g : geometry)
        if (g.room) return &*g.room;
    return nullptr;
}

}  // namespace luxplan
