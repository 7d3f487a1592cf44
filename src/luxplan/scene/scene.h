// The scene model: everything a scene file says, validated and resolved (names
// to indices, relative paths to files, parts to triangle meshes). Built by
// io/scene_loader; read by the ray tracer, the light samplers and the optimizer.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/core/names.h>
#include <luxplan/core/point_statistics.h>
#include <luxplan/daylight/daylight_params.h>
#include <luxplan/materials/material.h>
#include <luxplan/scene/mesh.h>
#include <luxplan/scene/region.h>
#include <luxplan/scene/settings.h>
#include <luxplan/scene/voxels.h>

namespace luxplan {

enum class Wall { North, South, East, West, Ceiling };

struct Opening {
    Wall wall = Wall::South;
    double offset = 0, width = 1, sill = 0, height = 1;  // walls: metres along the wall / above the floor
    Vec2 center, size;                                    // ceiling openings
    std::optional<uint32_t> material;                     // the pane's material, if glazed
    // A blind or curtain ("blind"): a layer of this material over the whole opening,
    // kBlindInset inside the room, when deployed.
    std::optional<uint32_t> blindMaterial;
    bool blindDeployed = true;
};

// How far inside the room a deployed blind hangs in front of its opening (m).
inline constexpr double kBlindInset = 0.005;

struct RoomShell {
    Bounds3 box;
    uint32_t floorMaterial = 0, wallMaterial = 0, ceilingMaterial = 0;
    std::vector<Opening> openings;
};

enum class StaticKind { Room, Box, Mesh };

// An immovable part of the scene (collision target and light transport geometry).
struct StaticItem {
    std::string name;
    std::string jsonPath;
    StaticKind kind = StaticKind::Box;
    bool invisible = false;  // a blocker: collides, takes no part in light transport
    TriangleMesh mesh;       // world frame
    std::optional<RoomShell> room;
    VoxelGrid voxels;        // solid volume (world frame); empty for the room shell
};

class EmitterShape;  // emitters/emitter_shape.h

// A Lambertian area emitter; fixed (entity < 0, world frame) or carried by an
// entity (its frame).
struct Emitter {
    std::string name;
    std::string jsonPath;
    std::shared_ptr<const EmitterShape> shape;  // rect, disk, sphere (emitters/)
    double fluxLm = 1000;
    double cctK = 4000;
    int entity = -1;
};

class SamplerType;  // lightsamplers/sampler_type.h

// A goal on a statistic over a sampler's points (its "statistics" object): one more
// term of Eq. 3, P(statistic, targetMin, targetMax, tolerance, 1) with the sampler's
// weight.
struct StatisticGoal {
    Statistic statistic = Statistic::U0;  // min, max or u0 (the mean's goal is the sampler's target)
    double targetMin = 0, targetMax = kInf;  // the type's unit; u0 is a ratio
    double tolerance = 1;
    std::string jsonPath;  // of the goal's object, for errors found later
};

// A goal on the year (the sampler's "annual" object): the share of the daylight's
// occupied hours with the sun up (annual/daylight_coefficients.h, annualHours) whose
// value lies in the sampler's target, itself within [targetMin, targetMax].
struct AnnualGoal {
    double targetMin = 0, targetMax = 1;  // shares of the hours, within [0, 1]
    double tolerance = 0.1;
    std::string jsonPath;  // of the "in_range" object, for errors found later
};

// A lighting intention (the paper's Section 4): what its type measures where, and
// the accepted range of the value.
struct LightSamplerSpec {
    std::string name;
    std::string jsonPath;
    std::string file;  // the scene file it was read from, for errors found later ("" if built in code)
    std::shared_ptr<const SamplerType> type;  // planar, directional, volume (lightsamplers/)
    double targetMin = 0, targetMax = kInf;   // in the type's unit
    double tolerance = 1;  // the paper's L_rej (same unit as the target)
    double weight = 1;
    int entity = -1;       // -1: world frame; else the entity it moves with
    std::vector<StatisticGoal> statistics;  // planar and volume samplers only
    std::optional<AnnualGoal> annual;       // samplers whose points are single sensors, in daylight
};

// What a part was, kept for outputs (plans, glTF) and summaries.
struct PartInfo {
    std::string kind;    // "box", "mesh" or the preset name
    Bounds3 bounds;      // entity frame
    uint32_t material = 0;
    // Its triangles in the entity's mesh: [firstTriangle, firstTriangle + triangles).
    size_t firstTriangle = 0, triangles = 0;
};

// A movable entity: a group (children), an object (parts), or both.
struct Entity {
    std::string name;
    std::string path;      // dotted path from the top level, e.g. "desk1.monitor"
    std::string jsonPath;
    int parent = -1;
    std::vector<int> children;
    Vec3 position;         // initial placement in the parent's frame
    double rotationDeg = 0;
    std::vector<Region> regions;  // empty: immovable
    // The footprint rule (constraints/footprint.h): the footprint of its parts and of
    // every descendant's stays inside the room. A top-level entity's
    // "placement.in_room" (default true); members take their group's.
    bool inRoom = true;
    TriangleMesh mesh;            // all parts, entity frame
    std::vector<PartInfo> parts;
    std::vector<Vec2> fronts{Vec2(0, -1)};
    std::vector<int> samplers;    // indices into Scene::samplers
    std::vector<int> emitters;    // indices into Scene::emitters
    VoxelGrid voxels;             // solid volume of the parts, entity frame

    bool movable() const { return !regions.empty(); }
    bool isGroup() const { return !children.empty(); }
    bool hasGeometry() const { return !mesh.empty(); }
};

class ConstraintKind;  // constraints/constraint_type.h

inline constexpr int kRoomEntity = -2;  // constraint target "room"

// A relational constraint (Section 5.2) between two entities.
struct ConstraintSpec {
    std::string name;  // optional; scoped by its entity ("ws1.reach") when an entity holds it
    std::string jsonPath;
    std::shared_ptr<const ConstraintKind> kind;  // alignment, distance, focus, conversation (constraints/)
    int a = -1, b = -1;  // entity indices (b may be kRoomEntity where the kind accepts the room)
    double weight = 1;
};

// The overlap rule (Eq. 6), which holds between every two solids of the scene. The
// scene file sets it with a "constraints" entry of type "overlap".
struct OverlapRule {
    double tolerance = 0.05;  // between entities: fraction of the smaller volume (the paper's V_ref)
    // Walls, static geometry and blockers are hard limits: an entity may enter them by
    // this volume (m^3, "wall_tolerance_l" in litres; voxel noise, not a design
    // margin), and a layout that goes further is rejected.
    double wallTolerance = 0.001;
    double weight = 1;        // w_o in G(x)
    std::string jsonPath;     // the entry that set it; empty: the defaults
    // Entity pairs the rule skips besides an ancestor and its descendants: in a
    // flattened scene, the pairs that were so related before (flattenScene()).
    std::vector<std::pair<int, int>> exempt;
};

// Eq. 1: C = w L + (1 - w) G, w the lighting weight.
struct Objective {
    double lightingWeight = 0.5;
    double cost(double lighting, double geometry) const { return lightingWeight * lighting + (1 - lightingWeight) * geometry; }
};

// The scene file's names for these enums ("south", "glossy"): one table each
// parses, prints and lists them (core/names.h).
const EnumNames<Wall>& wallNames();
const EnumNames<MaterialType>& materialTypeNames();

// A named view of the room ("cameras"), for render.png and the glTF.
struct SceneCamera {
    std::string name;
    std::string jsonPath;
    Vec3 eye, target;
    double fovDeg = 60;  // vertical field of view
};

struct Scene {
    std::filesystem::path file;
    std::string name;
    Site site;
    std::optional<DaylightParams> daylight;  // absent: night
    // "maintenance_factor", in (0, 1]: every luminaire's and carried emitter's light is
    // scaled by it (EN 12464-1's maintained illuminance); the daylight is not.
    double maintenanceFactor = 1;
    std::vector<Material> materials;
    std::map<std::string, uint32_t> materialIndex;
    std::vector<StaticItem> geometry;
    std::vector<Emitter> emitters;  // fixed luminaires first, then the ones entities carry
    std::vector<Entity> entities;   // depth first: a parent before its children
    std::vector<LightSamplerSpec> samplers;
    std::vector<ConstraintSpec> constraints;
    std::vector<SceneCamera> cameras;
    OverlapRule overlap;
    Objective objective;
    OptimizerSettings optimizer;
    std::vector<std::string> settingsSet;  // the "optimizer" keys --set gave, over the file's (messages name them)

    // Entity index for a dotted path, or -1.
    int findEntity(const std::string& path) const;
    const RoomShell* room() const;
};

}  // namespace luxplan
