// Scenes for module tests, built in C++ instead of read from JSON (as Yocto/GL's
// scene presets): chainable calls that record what a scene file would say, and
// build(), which resolves it as io::loadScene does (material indices in name order,
// entity paths, parts and presets as meshes, carried samplers and emitters listed on
// their entities, default tolerances, JSON paths, voxels). Loader-free: it links luxplan_scene only.
//
//   Scene s = SceneBuilder()
//                 .material("m", diffuse(0.5))
//                 .room({0, 0, 0}, {6, 4, 3}, "m", "m", "m").window(Wall::South, 1, 1, 1, 1)
//                 .entity("table", {3, 2, 0}).region({1, 1}, {5, 3}, {0, 90}).part({1, 0.6, 0.75}, "m").end()
//                 .build();
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/scene/scene.h>

namespace luxplan::test {

inline const Vec3 kZ(0, 0, 1);  // up, in every scene

Material diffuse(double reflectance);
Material glossy(double reflectance, double roughness, double base);
Material glossy(double reflectance, double roughness, Vec3 base);
Material glass(double transmittance);
Material mirror(double reflectance);
Material translucent(double reflectance, double transmittance);

class SceneBuilder {
public:
    // The scene's "name" (default "scene", what the loader takes from scene.json).
    SceneBuilder& name(const std::string& name);
    SceneBuilder& material(const std::string& name, const Material& m);

    // Static geometry, in the order of the scene file's "geometry".
    SceneBuilder& room(Vec3 min, Vec3 max, const std::string& floor, const std::string& walls, const std::string& ceiling,
                       const std::string& name = "room");
    // An opening in the last room's wall; `glass` names the pane's material (empty: open).
    SceneBuilder& window(Wall wall, double offset, double width, double sill, double height, const std::string& glass = "");
    SceneBuilder& skylight(Vec2 center, Vec2 size, const std::string& glass = "");
    SceneBuilder& box(const std::string& name, Vec3 min, Vec3 max, const std::string& material);
    SceneBuilder& blocker(const std::string& name, Vec3 min, Vec3 max);  // an invisible box

    SceneBuilder& daylight(const DaylightParams& d);
    SceneBuilder& uniformSky(double luminanceNits, double groundReflectance = 0);  // no sun
    // A uniform sky and the sun where `sun` puts it.
    SceneBuilder& sunAndUniformSky(const SunOverride& sun, double skyNits, double groundReflectance = 0);
    SceneBuilder& overcastSky(double horizontalIlluminanceLx, double groundReflectance = 0.2);

    // An emitter or a sampler: carried by the open entity, if any, else fixed.
    SceneBuilder& emitter(const std::string& name, std::shared_ptr<const EmitterShape> shape, double fluxLm);
    // Target [min, max] (max kInf: open); tolerance unset: the loader's default.
    SceneBuilder& sampler(const std::string& name, std::shared_ptr<const SamplerType> type, double targetMin,
                          double targetMax = kInf, std::optional<double> tolerance = std::nullopt);
    // A statistics goal of the last sampler (its "statistics" object: min, max or u0);
    // tolerance unset: the loader's default.
    SceneBuilder& statistic(Statistic statistic, double targetMin, double targetMax = kInf,
                            std::optional<double> tolerance = std::nullopt);

    // Opens an entity (a child of the open one, if any) until end().
    SceneBuilder& entity(const std::string& name, Vec3 position = {}, double rotationDeg = 0);
    // A placement region of the open entity; no rotations: it keeps its initial one.
    // An entity without regions is fixed.
    SceneBuilder& region(Vec2 lo, Vec2 hi, std::vector<double> rotationsDeg = {});
    // A region whose rotations are the interval [minDeg, maxDeg] (the file's "rotation_range").
    SceneBuilder& rangeRegion(Vec2 lo, Vec2 hi, double minDeg, double maxDeg);
    // A box part of the open entity, `size` centred at `center` (default: on the floor).
    SceneBuilder& part(Vec3 size, const std::string& material, std::optional<Vec3> center = std::nullopt);
    // A furniture preset (scene/presets.h) of the open entity, all of it in `material`;
    // size unset: the preset's default; centre unset: standing on the floor.
    SceneBuilder& preset(const std::string& preset, const std::string& material, std::optional<Vec3> size = std::nullopt,
                         std::optional<Vec3> center = std::nullopt);
    SceneBuilder& fronts(const std::vector<Vec2>& fronts);  // normalized, as the loader does
    SceneBuilder& end();

    // `a` and `b` are entity paths (or bare unique names); `b` may be "room" (for a kind
    // that accepts it: the builder does not check).
    SceneBuilder& constraint(std::shared_ptr<const ConstraintKind> kind, const std::string& a, const std::string& b,
                             double weight = 1);
    SceneBuilder& overlap(double tolerance, double weight = 1);

    // The file's "objective" and "optimizer" objects.
    SceneBuilder& lightingWeight(double w);
    // The file's "maintenance_factor" (the builder does not check its range).
    SceneBuilder& maintenanceFactor(double factor);
    SceneBuilder& optimizer(const OptimizerSettings& settings);

    // Throws std::invalid_argument for an unknown name or an entity left open.
    Scene build() const;

private:
    struct Part {
        std::string preset;          // empty: a box
        std::optional<Vec3> size;    // a box's, or the preset's (unset: its default)
        std::optional<Vec3> center;
        std::string material;
    };
    struct EntityDef {
        Entity entity;
        std::vector<Part> parts;
        int childCount = 0, samplerCount = 0, emitterCount = 0;
    };
    struct StaticDef {
        StaticItem item;
        Bounds3 box;
        std::string material, floor, walls, ceiling;
        std::vector<std::pair<Opening, std::string>> openings;  // and the pane's material
    };
    struct ConstraintDef {
        ConstraintSpec spec;
        std::string a, b;
    };
    Entity* open();
    uint32_t resolve(const std::map<std::string, uint32_t>& index, const std::string& name) const;

    std::string name_ = "scene";
    std::map<std::string, Material> materials_;
    std::optional<DaylightParams> daylight_;
    std::vector<StaticDef> geometry_;
    std::vector<Emitter> emitters_;
    std::vector<LightSamplerSpec> samplers_;
    std::vector<EntityDef> entities_;
    std::vector<int> stack_;  // open entities
    int topLevel_ = 0, fixedEmitters_ = 0, fixedSamplers_ = 0, constraintEntries_ = 0;
    std::vector<ConstraintDef> constraints_;
    OverlapRule overlap_;
    Objective objective_;
    double maintenanceFactor_ = 1;
    OptimizerSettings optimizer_;
};

}  // namespace luxplan::test
