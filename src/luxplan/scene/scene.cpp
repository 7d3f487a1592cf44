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

const char* samplerTypeName(LightSamplerType t) {
    switch (t) {
        case LightSamplerType::Planar: return "planar";
        case LightSamplerType::Directional: return "directional";
        case LightSamplerType::Volume: return "volume";
    }
    return "?";
}

const char* constraintTypeName(ConstraintType t) {
    switch (t) {
        case ConstraintType::Alignment: return "alignment";
        case ConstraintType::Distance: return "distance";
        case ConstraintType::Focus: return "focus";
        case ConstraintType::Conversation: return "conversation";
        case ConstraintType::Overlap: return "overlap";
    }
    return "?";
}

const char* wallName(Wall w) {
    switch (w) {
        case Wall::North: return "north";
        case Wall::South: return "south";
        case Wall::East: return "east";
        case Wall::West: return "west";
        case Wall::Ceiling: return "ceiling";
    }
    return "?";
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
