// The scene on Embree 3: one device with an error callback and one top-level scene.
// The static geometry and every entity with geometry (parts or emitters) lie in it
// as world-space triangles and points, so that a ray descends one BVH, not one per
// instance it enters (1.3x the rays per second in the office); moving an entity
// rewrites its vertices and rebuilds that BVH. Items lie flat while their triangles
// add up to at most kFlatTriangles (static geometry first); the others (large mesh files, a
// hall of many pieces) keep a sub-scene each, instanced in the top level, so that no
// move rebuilds them.
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

#include <luxplan/scene/layout.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// The process's Embree device. Errors reported by Embree's callback are kept and
// turned into EmbreeError by check().
class EmbreeDevice {
public:
    EmbreeDevice();
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    static std::shared_ptr<EmbreeDevice> shared();
    RTCDevice handle() const { return device_; }
    // Throws EmbreeError if Embree reported an error since the last check.
    void check(const char* during);

private:
    static void onError(void* self, RTCError code, const char* message);
    RTCDevice device_ = nullptr;
    std::string pendingError_;
};

// Ray masks: shadow rays can ask for opaque surfaces only, then cross glass
// (transmissive materials) one surface at a time. The panes of the room's openings
// have a mask of their own: shadow rays cross them analytically (pathtracer/panes.h).
inline constexpr unsigned kOpaqueMask = 1u, kGlassMask = 2u, kEmitterMask = 4u, kPaneMask = 8u, kAllMask = 0xffffffffu;

struct Ray {
    Vec3 origin;
    Vec3 direction;  // need not be unit length; t is in units of its length
    double tMin = 0;
    double tMax = kInf;
    unsigned mask = kAllMask;
    // Closest hit only: of faces met at exactly the same t, the first in a fixed order
    // (instance, geometry, triangle) instead of the one the BVH of the moment visits
    // first (a second query, about 40% of a ray's cost). For rays that may run inside a
    // see-through part, where its faces can coincide with another material's: a glass
    // top resting on a wooden leg (incremental/path_cache.h needs the same hit after
    // any move).
    bool breakTies = false;
};

// Every ray a scene traces, for replaying them through Embree alone (bench/): what
// the path tracer costs beyond its rays.
struct RayLog {
    std::vector<Ray> closest, shadow;
};

enum class HitKind { Static, Entity, Emitter };

struct Hit {
    double t = 0;
    Vec3 point;
    Vec3 geometricNormal;  // unit, world frame, from the triangle's winding (outwards)
    Vec3 shadingNormal;    // interpolated vertex normal if the mesh has them, else geometric
    uint32_t material = 0; // Scene::materials index (static and entity surfaces)
    HitKind kind = HitKind::Static;
    int index = -1;        // static item, entity or emitter index, by kind
    uint32_t primitive = 0;
};

class EmbreeScene {
public:
    EmbreeScene(const Scene& scene, const Layout& layout, std::shared_ptr<EmbreeDevice> device = EmbreeDevice::shared());
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Places every entity for `layout` and commits the top level.
    void setLayout(const Layout& layout);
    // Lower level: set instance transforms one by one, then commit() once.
    void setEntityTransform(int entity, const Transform& worldFromEntity);
    void commit();

    std::optional<Hit> intersect(const Ray& ray) const;
    bool occluded(const Ray& ray) const;
    // Appends every ray traced from now on to `log` (null: stop). Not thread-safe:
    // record with one thread.
    void record(RayLog* log) { log_ = log; }

    const Scene& scene() const { return scene_; }
    const Transform& worldFromEntity(int entity) const { return worldFromEntity_[entity]; }
    // Number of entities in the scene (flat or instanced) that rays can meet.
    size_t entityCount() const;
    // The most triangles that lie flat in the top level, all items together.
    static constexpr size_t kFlatTriangles = 20000;
    // How many do.
    size_t flatTriangleCount() const { return flatTriangles_; }
    // Whether any visible surface other than the room's window panes has a
    // transmissive (glass) material.
    bool hasGlass() const { return hasGlass_; }

private:
    struct TriangleFace {
        Vec3 normal;  // unit, from the winding, in double (TriangleMesh::geometricNormal)
        uint32_t material = 0;
        // In one plane with an overlapping face of another material of its item
        // (rt/coincident_faces.h): a hit here breaks ties as Ray::breakTies does.
        bool tieProne = false;
    };
    struct GeometryInfo {
        HitKind kind = HitKind::Static;
        int index = -1;
        int entity = -1;                     // whose transform places it; -1: the world frame
        const TriangleMesh* mesh = nullptr;  // for triangle geometry (its own frame)
        // Per triangle, what every hit reads, side by side: one cache line, not the
        // three vertices and the material of a mesh spread over memory.
        const std::vector<TriangleFace>* faces = nullptr;
        // A sphere or disc emitter, in its own frame (flat geometry moves it); a
        // sphere's normal is zero.
        Vec3 center, normal;
        float radius = 0;
    };
    struct SubScene {
        RTCScene scene = nullptr;
        std::vector<GeometryInfo> geometries;  // by geomID
        bool flat = false;                     // the top level itself
        int entity = -1;                       // -1 for static geometry
        unsigned instanceId = RTC_INVALID_GEOMETRY_ID;
    };

    // Attaches a mesh as up to two geometries: opaque triangles and glass triangles.
    void attachMesh(SubScene& sub, const TriangleMesh& mesh, HitKind kind, int index);
    // `tieProne`: per triangle, TriangleFace::tieProne (empty: none).
    unsigned attachTriangles(SubScene& sub, const TriangleMesh& mesh, HitKind kind, int index, unsigned mask,
                             const std::vector<char>& tieProne);
    void attachEmitter(SubScene& sub, const Emitter& emitter, int index);
    void finishSubScene(SubScene& sub);
    // What a hit met: its sub-scene and geometry.
    struct Met {
        const SubScene* sub;
        const GeometryInfo* info;
    };
    Met metBy(const RTCHit& hit) const;
    // Of the faces `found`'s ray meets at exactly its distance, the first in a fixed
    // order (instance, geometry, triangle): a second query over a sliver of t around it.
    RTCHit firstOfTheTied(const RTCRayHit& found, float tMin) const;
    // Writes a flat geometry's vertices where worldFromEntity_ puts them.
    void place(RTCGeometry g, const GeometryInfo& info);

    const Scene& scene_;
    std::shared_ptr<EmbreeDevice> device_;
    RTCScene top_ = nullptr;
    SubScene flat_;                          // the top level's own geometry (scene: top_)
    std::vector<SubScene> subScenes_;        // instanced: large static items and entities
    std::vector<int> subSceneOfInstance_;    // top-level geomID -> subScenes_ index
    std::vector<int> subSceneOfEntity_;      // entity -> subScenes_ index, or -1
    std::vector<std::vector<unsigned>> flatOfEntity_;  // entity -> its flat geomIDs in top_
    size_t entitiesMet_ = 0;
    size_t flatTriangles_ = 0;
    std::vector<Transform> worldFromEntity_;
    std::vector<TriangleMesh> emitterMeshes_;  // emitters Embree sees as triangles (rects)
    std::deque<TriangleMesh> splitMeshes_;     // meshes split into opaque and glass parts
    std::deque<std::vector<TriangleFace>> faces_;  // GeometryInfo::faces of every triangle geometry
    bool hasGlass_ = false;
    RayLog* log_ = nullptr;
};

}  // namespace luxplan
