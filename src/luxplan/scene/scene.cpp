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

const EnumNames<ConstraintType>& constraintTypeNames() {
    static const EnumNames<ConstraintType> names{{{ConstraintType::Alignment, "alignment"},
                                                  {ConstraintType::Distance, "distance"},
                                                  {ConstraintType::Focus, "focus"},
                                                  {ConstraintType::Conversation, "conversation"},
                                                  {ConstraintType::Overlap, "overlap"}}};
    return names;
}

const EnumNames<Wall>& wallNames() {
    static const EnumNames<Wall> names{
        {{Wall::North, "north"}, {Wall::South, "south"}, {Wall::East, "east"}, {Wall::West, "west"}, {Wall::Ceiling, "ceiling"}}};
    return names;
}

const EnumNames<EmitterShape>& emitterShapeNames() {
    static const EnumNames<EmitterShape> names{
        {{EmitterShape::Rect, "rect"}, {EmitterShape::Disk, "disk"}, {EmitterShape::Sphere, "sphere"}}};
    return names;
}

const EnumNames<MaterialType>& materialTypeNames() {
    static const EnumNames<MaterialType> names{{{MaterialType::Diffuse, "diffuse"},
                                                {MaterialType::Glossy, "glossy"},
                                                {MaterialType::Glass, "glass"},
                                                {MaterialType::Mirror, "mirror"}}};
    return names;
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
