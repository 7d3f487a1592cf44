#include "support/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <luxplan/scene/presets.h>
#include <luxplan/scene/room.h>

namespace luxplan::test {

namespace {
const double kVoxelSize = 0.02;  // io::LoadOptions::voxelSize
}

Material diffuse(double reflectance) {
    Material m;
    m.type = MaterialType::Diffuse;
    m.reflectance = Vec3(reflectance, reflectance, reflectance);
    return m;
}

Material glossy(double reflectance, double roughness, double base) {
    Material m;
    m.type = MaterialType::Glossy;
    m.reflectance = Vec3(reflectance, reflectance, reflectance);
    m.roughness = roughness;
    m.base = Vec3(base, base, base);
    return m;
}

Material glossy(double reflectance, double roughness, Vec3 base) {
    Material m = glossy(reflectance, roughness, 0.0);
    m.base = base;
    return m;
}

Material mirror(double reflectance) {
    Material m;
    m.type = MaterialType::Mirror;
    m.reflectance = Vec3(reflectance, reflectance, reflectance);
    return m;
}

Material glass(double transmittance) {
    Material m;
    m.type = MaterialType::Glass;
    m.transmittance = transmittance;
    return m;
}

Material translucent(double reflectance, double transmittance) {
    Material m;
    m.type = MaterialType::Translucent;
    m.reflectance = Vec3(reflectance, reflectance, reflectance);
    m.diffuseTransmittance = Vec3(transmittance, transmittance, transmittance);
    return m;
}

SceneBuilder& SceneBuilder::name(const std::string& name) {
    name_ = name;
    return *this;
}

SceneBuilder& SceneBuilder::material(const std::string& name, const Material& m) {
    materials_[name] = m;
    materials_[name].name = name;
    return *this;
}

SceneBuilder& SceneBuilder::room(Vec3 min, Vec3 max, const std::string& floor, const std::string& walls,
                                 const std::string& ceiling, const std::string& name) {
    StaticDef d;
    d.item.name = name;
    d.item.kind = StaticKind::Room;
    d.item.jsonPath = "/geometry/" + std::to_string(geometry_.size());
    d.box = Bounds3(min, max);
    d.floor = floor, d.walls = walls, d.ceiling = ceiling;
    geometry_.push_back(d);
    return *this;
}

SceneBuilder& SceneBuilder::window(Wall wall, double offset, double width, double sill, double height, const std::string& glass) {
    if (geometry_.empty() || geometry_.back().item.kind != StaticKind::Room) throw std::invalid_argument("window() needs a room()");
    Opening o;
    o.wall = wall;
    o.offset = offset, o.width = width, o.sill = sill, o.height = height;
    geometry_.back().openings.emplace_back(o, glass);
    return *this;
}

SceneBuilder& SceneBuilder::skylight(Vec2 center, Vec2 size, const std::string& glass) {
    if (geometry_.empty() || geometry_.back().item.kind != StaticKind::Room) throw std::invalid_argument("skylight() needs a room()");
    Opening o;
    o.wall = Wall::Ceiling;
    o.center = center, o.size = size;
    geometry_.back().openings.emplace_back(o, glass);
    return *this;
}

SceneBuilder& SceneBuilder::box(const std::string& name, Vec3 min, Vec3 max, const std::string& material) {
    StaticDef d;
    d.item.name = name;
    d.item.kind = StaticKind::Box;
    d.item.jsonPath = "/geometry/" + std::to_string(geometry_.size());
    d.box = Bounds3(min, max);
    d.material = material;
    geometry_.push_back(d);
    return *this;
}

SceneBuilder& SceneBuilder::blocker(const std::string& name, Vec3 min, Vec3 max) {
    box(name, min, max, "");
    geometry_.back().item.invisible = true;
    return *this;
}

SceneBuilder& SceneBuilder::daylight(const DaylightParams& d) {
    daylight_ = d;
    return *this;
}

SceneBuilder& SceneBuilder::uniformSky(double luminanceNits, double groundReflectance) {
    DaylightParams d;
    d.model = SkyModelType::Uniform;
    d.luminanceNits = luminanceNits;
    d.sun = false;
    d.groundReflectance = groundReflectance;
    return daylight(d);
}

SceneBuilder& SceneBuilder::sunAndUniformSky(const SunOverride& sun, double skyNits, double groundReflectance) {
    uniformSky(skyNits, groundReflectance);
    daylight_->sun.reset();  // the override implies a sun
    daylight_->sunOverride = sun;
    return *this;
}

SceneBuilder& SceneBuilder::overcastSky(double horizontalIlluminanceLx, double groundReflectance) {
    DaylightParams d;
    d.model = SkyModelType::CieOvercast;
    d.horizontalIlluminanceLx = horizontalIlluminanceLx;
    d.groundReflectance = groundReflectance;
    return daylight(d);
}

Entity* SceneBuilder::open() { return stack_.empty() ? nullptr : &entities_[size_t(stack_.back())].entity; }

SceneBuilder& SceneBuilder::emitter(const std::string& name, std::shared_ptr<const EmitterShape> shape, double fluxLm) {
    Emitter e;
    e.name = name;
    e.shape = std::move(shape);
    e.fluxLm = fluxLm;
    if (Entity* owner = open()) {
        e.name = owner->path + "." + name;  // scoped by its entity, as the loader does
        e.entity = stack_.back();
        e.jsonPath = owner->jsonPath + "/emitters/" + std::to_string(entities_[size_t(stack_.back())].emitterCount++);
    } else {
        e.jsonPath = "/luminaires/" + std::to_string(fixedEmitters_++);
    }
    emitters_.push_back(e);
    return *this;
}

SceneBuilder& SceneBuilder::sampler(const std::string& name, std::shared_ptr<const SamplerType> type, double targetMin,
                                    double targetMax, std::optional<double> tolerance) {
    LightSamplerSpec s;
    s.name = name;
    s.type = std::move(type);
    s.targetMin = targetMin, s.targetMax = targetMax;
    if (targetMax < targetMin || targetMin < 0) throw std::invalid_argument("sampler \"" + name + "\": bad target range");
    // The loader's default tolerance (L_rej): the width of the range, or half the
    // finite bound when the range is open or a single value.
    double width = targetMax - targetMin;
    double fallback = std::isfinite(width) && width > 0 ? width : 0.5 * (std::isfinite(targetMax) ? targetMax : targetMin);
    if (!(fallback > 0)) fallback = 1;
    s.tolerance = tolerance.value_or(fallback);
    if (Entity* owner = open()) {
        s.name = owner->path + "." + name;  // scoped by its entity, as the loader does
        s.entity = stack_.back();
        s.jsonPath = owner->jsonPath + "/samplers/" + std::to_string(entities_[size_t(stack_.back())].samplerCount++);
    } else {
        s.jsonPath = "/samplers/" + std::to_string(fixedSamplers_++);
    }
    samplers_.push_back(s);
    return *this;
}

SceneBuilder& SceneBuilder::statistic(Statistic statistic, double targetMin, double targetMax, std::optional<double> tolerance) {
    if (samplers_.empty()) throw std::invalid_argument("statistic(): no sampler yet");
    if (statistic == Statistic::Mean) throw std::invalid_argument("statistic(): the mean's goal is the sampler's target");
    if (targetMax < targetMin || targetMin < 0) throw std::invalid_argument("statistic(): bad target range");
    LightSamplerSpec& s = samplers_.back();
    StatisticGoal g;
    g.statistic = statistic;
    g.targetMin = targetMin, g.targetMax = targetMax;
    // The loader's default: half the bound the goal guards, its min or else its max.
    double fallback = 0.5 * (targetMin > 0 ? targetMin : targetMax);
    if (!(fallback > 0) || !std::isfinite(fallback)) fallback = 1;
    g.tolerance = tolerance.value_or(fallback);
    g.jsonPath = s.jsonPath + "/statistics/" + statisticNames().name(statistic);
    // The loader reads them in the order min, max, u0.
    auto at = std::find_if(s.statistics.begin(), s.statistics.end(),
                           [&](const StatisticGoal& x) { return int(x.statistic) > int(statistic); });
    s.statistics.insert(at, g);
    return *this;
}

SceneBuilder& SceneBuilder::entity(const std::string& name, Vec3 position, double rotationDeg) {
    EntityDef d;
    Entity& e = d.entity;
    e.name = name;
    e.position = position;
    e.rotationDeg = rotationDeg;
    int index = int(entities_.size());
    if (Entity* parent = open()) {
        e.parent = stack_.back();
        e.path = parent->path + "." + name;
        e.jsonPath = parent->jsonPath + "/children/" + std::to_string(entities_[size_t(stack_.back())].childCount++);
        parent->children.push_back(index);
    } else {
        e.path = name;
        e.jsonPath = "/entities/" + std::to_string(topLevel_++);
    }
    entities_.push_back(std::move(d));
    stack_.push_back(index);
    return *this;
}

SceneBuilder& SceneBuilder::region(Vec2 lo, Vec2 hi, std::vector<double> rotationsDeg) {
    Entity* e = open();
    if (!e) throw std::invalid_argument("region() outside an entity");
    Region r;
    r.lo = lo, r.hi = hi;
    r.rotationsDeg = rotationsDeg.empty() ? std::vector<double>{e->rotationDeg} : std::move(rotationsDeg);
    e->regions.push_back(r);
    return *this;
}

SceneBuilder& SceneBuilder::rangeRegion(Vec2 lo, Vec2 hi, double minDeg, double maxDeg) {
    Entity* e = open();
    if (!e) throw std::invalid_argument("rangeRegion() outside an entity");
    if (maxDeg < minDeg) throw std::invalid_argument("rotation range is inverted");
    Region r;
    r.lo = lo, r.hi = hi;
    r.continuousRotation = true;
    r.rotationMinDeg = minDeg, r.rotationMaxDeg = maxDeg;
    e->regions.push_back(r);
    return *this;
}

SceneBuilder& SceneBuilder::part(Vec3 size, const std::string& material, std::optional<Vec3> center) {
    if (!open()) throw std::invalid_argument("part() outside an entity");
    entities_[size_t(stack_.back())].parts.push_back({"", size, center, material});
    return *this;
}

SceneBuilder& SceneBuilder::preset(const std::string& preset, const std::string& material, std::optional<Vec3> size,
                                   std::optional<Vec3> center) {
    if (!open()) throw std::invalid_argument("preset() outside an entity");
    if (!findPreset(preset)) throw std::invalid_argument("unknown preset \"" + preset + "\"");
    entities_[size_t(stack_.back())].parts.push_back({preset, size, center, material});
    return *this;
}

SceneBuilder& SceneBuilder::fronts(const std::vector<Vec2>& fronts) {
    Entity* e = open();
    if (!e) throw std::invalid_argument("fronts() outside an entity");
    e->fronts.clear();
    for (const Vec2& v : fronts) e->fronts.push_back(v * (1.0 / length(v)));
    return *this;
}

SceneBuilder& SceneBuilder::end() {
    if (stack_.empty()) throw std::invalid_argument("end() without an open entity");
    stack_.pop_back();
    return *this;
}

SceneBuilder& SceneBuilder::constraint(std::shared_ptr<const ConstraintKind> kind, const std::string& a, const std::string& b,
                                       double weight) {
    ConstraintDef c;
    c.spec.kind = std::move(kind);
    c.spec.weight = weight;
    c.spec.jsonPath = "/constraints/" + std::to_string(constraintEntries_++);
    c.a = a, c.b = b;
    constraints_.push_back(c);
    return *this;
}

SceneBuilder& SceneBuilder::overlap(double tolerance, double weight) {
    overlap_.tolerance = tolerance;
    overlap_.weight = weight;
    overlap_.jsonPath = "/constraints/" + std::to_string(constraintEntries_++);
    return *this;
}

SceneBuilder& SceneBuilder::lightingWeight(double w) {
    objective_.lightingWeight = w;
    return *this;
}

SceneBuilder& SceneBuilder::maintenanceFactor(double factor) {
    maintenanceFactor_ = factor;
    return *this;
}

SceneBuilder& SceneBuilder::optimizer(const OptimizerSettings& settings) {
    optimizer_ = settings;
    return *this;
}

uint32_t SceneBuilder::resolve(const std::map<std::string, uint32_t>& index, const std::string& name) const {
    auto it = index.find(name);
    if (it == index.end()) throw std::invalid_argument("unknown material \"" + name + "\"");
    return it->second;
}

Scene SceneBuilder::build() const {
    if (!stack_.empty()) throw std::invalid_argument("entity \"" + entities_[size_t(stack_.back())].entity.path + "\" is not closed");
    Scene s;
    s.name = name_;
    s.daylight = daylight_;
    for (const auto& [name, m] : materials_) {  // name order, as the loader's JSON object
        s.materialIndex[name] = uint32_t(s.materials.size());
        s.materials.push_back(m);
    }

    for (const StaticDef& d : geometry_) {
        StaticItem item = d.item;
        if (item.kind == StaticKind::Room) {
            RoomShell room;
            room.box = d.box;
            room.floorMaterial = resolve(s.materialIndex, d.floor);
            room.wallMaterial = resolve(s.materialIndex, d.walls);
            room.ceilingMaterial = resolve(s.materialIndex, d.ceiling);
            for (auto [o, pane] : d.openings) {
                if (!pane.empty()) o.material = resolve(s.materialIndex, pane);
                room.openings.push_back(o);
            }
            item.room = room;
            item.mesh = buildRoomShell(room);
        } else {
            addBox(item.mesh, d.box, item.invisible ? 0 : resolve(s.materialIndex, d.material));
            item.voxels = voxelizeSolid(item.mesh, kVoxelSize);
        }
        s.geometry.push_back(std::move(item));
    }

    for (const EntityDef& d : entities_) {
        Entity e = d.entity;
        for (const Part& p : d.parts) {
            PartInfo info;
            info.material = resolve(s.materialIndex, p.material);
            TriangleMesh mesh;
            if (p.preset.empty()) {
                info.kind = "box";
                Vec3 c = p.center.value_or(Vec3(0, 0, p.size->z / 2));
                addBox(mesh, Bounds3(c - *p.size * 0.5, c + *p.size * 0.5), info.material);
            } else {
                const PresetInfo& preset = *findPreset(p.preset);
                info.kind = preset.name;
                Vec3 size = p.size.value_or(preset.defaultSize);
                Vec3 c = p.center.value_or(Vec3(0, 0, size.z / 2));
                mesh.append(buildPreset(preset, size, {{preset.slots.front(), info.material}}),
                            Transform::translate(c - Vec3(0, 0, size.z / 2)));
            }
            info.bounds = mesh.bounds();
            info.firstTriangle = e.mesh.triangles.size(), info.triangles = mesh.triangles.size();
            e.parts.push_back(info);
            e.mesh.append(mesh);
        }
        if (e.hasGeometry()) e.voxels = voxelizeSolid(e.mesh, kVoxelSize);
        s.entities.push_back(std::move(e));
    }

    // The loader's order: fixed luminaires before carried emitters; carried samplers
    // (read with their entity) before the fixed ones; carried ones in entity order.
    std::vector<Emitter> emitters = emitters_;
    std::stable_sort(emitters.begin(), emitters.end(), [](const Emitter& a, const Emitter& b) { return a.entity < b.entity; });
    for (const Emitter& e : emitters) {
        if (e.entity >= 0) s.entities[size_t(e.entity)].emitters.push_back(int(s.emitters.size()));
        s.emitters.push_back(e);
    }
    std::vector<LightSamplerSpec> samplers = samplers_;
    auto key = [](const LightSamplerSpec& x) { return x.entity < 0 ? std::numeric_limits<int>::max() : x.entity; };
    std::stable_sort(samplers.begin(), samplers.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
    for (const LightSamplerSpec& x : samplers) {
        if (x.entity >= 0) s.entities[size_t(x.entity)].samplers.push_back(int(s.samplers.size()));
        s.samplers.push_back(x);
    }

    auto entityRef = [&](const std::string& name, bool allowRoom) {
        if (name == "room" && allowRoom) return kRoomEntity;
        int e = s.findEntity(name);
        if (e < 0)
            for (size_t i = 0; i < s.entities.size(); ++i)
                if (s.entities[i].name == name) {
                    if (e >= 0) throw std::invalid_argument("entity \"" + name + "\" is ambiguous");
                    e = int(i);
                }
        if (e < 0) throw std::invalid_argument("unknown entity \"" + name + "\"");
        return e;
    };
    for (const ConstraintDef& d : constraints_) {
        ConstraintSpec c = d.spec;
        c.a = entityRef(d.a, false);
        c.b = entityRef(d.b, true);  // the kind says whether it takes the room (the loader checks it)
        if (c.a == c.b) throw std::invalid_argument("a constraint needs two different entities");
        s.constraints.push_back(c);
    }
    s.overlap = overlap_;
    s.objective = objective_;
    s.maintenanceFactor = maintenanceFactor_;
    s.optimizer = optimizer_;
    return s;
}

}  // namespace luxplan::test
