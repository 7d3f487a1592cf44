#include <luxplan/scene/scene.h>

namespace luxplan {

const EnumNames<Wall>& wallNames() {
    static const EnumNames<Wall> names{
        {{Wall::North, "north"}, {Wall::South, "south"}, {Wall::East, "east"}, {Wall::West, "west"}, {Wall::Ceiling, "ceiling"}}};
    return names;
}

const EnumNames<MaterialType>& materialTypeNames() {
    static const EnumNames<MaterialType> names{{{MaterialType::Diffuse, "diffuse"},
                                                {MaterialType::Glossy, "glossy"},
                                                {MaterialType::Glass, "glass"},
                                                {MaterialType::Mirror, "mirror"},
                                                {MaterialType::Translucent, "translucent"}}};
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
