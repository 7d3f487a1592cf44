#include <luxplan/rt/embree_scene.h>

#include <cstring>
#include <mutex>

#include <tbb/task_arena.h>

#include <luxplan/core/error.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/rt/coincident_faces.h>

namespace luxplan {

// ---- device ----

static const char* errorName(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_UNKNOWN: return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "unrecognized error";
}

EmbreeDevice::EmbreeDevice() {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw EmbreeError("cannot create the Embree device: " + std::string(errorName(rtcGetDeviceError(nullptr))));
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::onError, this);
    // The tracer needs ray masks (shadow rays see opaque surfaces, panes and
    // luminaires apart) and two-sided triangles; an Embree built otherwise would give
    // wrong light silently. Filter functions break ties at coincident faces (intersect):
    // without them the path cache could differ from a fresh trace, silently too.
    const char* missing = nullptr;
    if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED) == 0) missing = "ray masks (EMBREE_RAY_MASK=ON)";
    else if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED) != 0)
        missing = "two-sided triangles (EMBREE_BACKFACE_CULLING=OFF)";
    else if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) == 0)
        missing = "filter functions (EMBREE_FILTER_FUNCTION=ON)";
    if (missing) {
        rtcReleaseDevice(device_);
        throw EmbreeError(std::string("this Embree library was built without ") + missing + ", which luxplan needs");
    }
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

std::shared_ptr<EmbreeDevice> EmbreeDevice::shared() {
    static std::mutex mutex;
    static std::weak_ptr<EmbreeDevice> instance;
    std::lock_guard lock(mutex);
    auto device = instance.lock();
    if (!device) {
        device = std::make_shared<EmbreeDevice>();
        instance = device;
    }
    return device;
}

void EmbreeDevice::onError(void* self, RTCError code, const char* message) {
    auto* device = static_cast<EmbreeDevice*>(self);
    if (!device->pendingError_.empty()) device->pendingError_ += "; ";
    device->pendingError_ += std::string(errorName(code)) + (message ? std::string(": ") + message : "");
}

void EmbreeDevice::check(const char* during) {
    if (pendingError_.empty()) return;
    std::string message = "Embree error during " + std::string(during) + ": " + pendingError_;
    pendingError_.clear();
    throw EmbreeError(message);
}

// ---- scene ----

namespace {

void setRowMajor(RTCGeometry g, const Transform& t) {
    float m[12] = {float(t.m[0]), float(t.m[1]), float(t.m[2]), float(t.t.x),
                   float(t.m[3]), float(t.m[4]), float(t.m[5]), float(t.t.y),
                   float(t.m[6]), float(t.m[7]), float(t.m[8]), float(t.t.z)};
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
}

RTCRay toRtcRay(const Ray& r) {
    RTCRay ray;
    ray.org_x = float(r.origin.x), ray.org_y = float(r.origin.y), ray.org_z = float(r.origin.z);
    ray.dir_x = float(r.direction.x), ray.dir_y = float(r.direction.y), ray.dir_z = float(r.direction.z);
    ray.tnear = float(r.tMin);
    ray.tfar = std::isinf(r.tMax) ? std::numeric_limits<float>::infinity() : float(r.tMax);
    ray.time = 0;
    ray.mask = r.mask;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

}  // namespace

void EmbreeScene::attachMesh(SubScene& sub, const TriangleMesh& mesh, HitKind kind, int index) {
    auto transmissive = [&](uint32_t material) { return scene_.materials[material].type == MaterialType::Glass; };
    size_t glass = 0;
    for (uint32_t m : mesh.materials) glass += transmissive(m);
    const std::vector<char> prone = coincidentFacesOfOtherMaterials(mesh);
    if (glass == 0) {
        attachTriangles(sub, mesh, kind, index, kOpaqueMask, prone);
        return;
    }
    // The room shell's glass is its openings' panes.
    const bool panes = kind == HitKind::Static && scene_.geometry[size_t(index)].kind == StaticKind::Room;
    if (!panes) hasGlass_ = true;
    // Split, keeping vertices (and normals) whole: unused vertices cost nothing.
    TriangleMesh parts[2];
    std::vector<char> partProne[2];
    for (auto& part : parts) part.positions = mesh.positions, part.normals = mesh.normals;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int k = transmissive(mesh.materials[t]) ? 1 : 0;
        parts[k].triangles.push_back(mesh.triangles[t]);
        parts[k].materials.push_back(mesh.materials[t]);
        partProne[k].push_back(prone[t]);
    }
    for (int k = 0; k < 2; ++k) {
        if (parts[k].empty()) continue;
        splitMeshes_.push_back(std::move(parts[k]));
        attachTriangles(sub, splitMeshes_.back(), kind, index, k == 0 ? kOpaqueMask : (panes ? kPaneMask : kGlassMask),
                        partProne[k]);
    }
}

unsigned EmbreeScene::attachTriangles(SubScene& sub, const TriangleMesh& mesh, HitKind kind, int index, unsigned mask,
                                      const std::vector<char>& tieProne) {
    RTCGeometry g = rtcNewGeometry(device_->handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryMask(g, mask);
    rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size());
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangles.size()));
    std::memcpy(idx, mesh.triangles.data(), mesh.triangles.size() * 3 * sizeof(unsigned));
    std::vector<TriangleFace>& faces = faces_.emplace_back(mesh.triangles.size());
    for (size_t t = 0; t < faces.size(); ++t)
        faces[t] = {mesh.geometricNormal(t), mesh.materials[t], t < tieProne.size() && tieProne[t] != 0};
    GeometryInfo info;
    info.kind = kind, info.index = index, info.mesh = &mesh, info.faces = &faces;
    info.entity = sub.flat ? (kind == HitKind::Emitter ? scene_.emitters[size_t(index)].entity
                              : kind == HitKind::Entity ? index : -1)
                           : -1;
    place(g, info);  // in its own frame where it is instanced (entity -1 there)
    info.entity = sub.entity >= 0 ? sub.entity : info.entity;
    rtcCommitGeometry(g);
    unsigned id = rtcAttachGeometry(sub.scene, g);
    rtcReleaseGeometry(g);
    if (sub.geometries.size() <= id) sub.geometries.resize(id + 1);
    sub.geometries[id] = info;
    return id;
}

void EmbreeScene::attachEmitter(SubScene& sub, const Emitter& e, int index) {
    EmitterPrimitive prim = e.shape->primitive();
    if (prim.kind == EmitterPrimitive::Kind::Triangles) {
        TriangleMesh& m = emitterMeshes_[index];
        m = std::move(prim.triangles);
        attachTriangles(sub, m, HitKind::Emitter, index, kEmitterMask, {});
        return;
    }
    bool sphere = prim.kind == EmitterPrimitive::Kind::Sphere;
    RTCGeometry g = rtcNewGeometry(device_->handle(), sphere ? RTC_GEOMETRY_TYPE_SPHERE_POINT : RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT);
    rtcSetGeometryMask(g, kEmitterMask);
    rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1);
    if (!sphere) rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 1);
    GeometryInfo info;
    info.kind = HitKind::Emitter, info.index = index;
    info.center = prim.center, info.radius = float(prim.radius);
    if (!sphere) info.normal = prim.normal;  // a disc's; a sphere has none (and no normal buffer)
    info.entity = sub.flat ? e.entity : -1;
    place(g, info);
    info.entity = e.entity;
    rtcCommitGeometry(g);
    unsigned id = rtcAttachGeometry(sub.scene, g);
    rtcReleaseGeometry(g);
    if (sub.geometries.size() <= id) sub.geometries.resize(id + 1);
    sub.geometries[id] = info;
}

void EmbreeScene::place(RTCGeometry g, const GeometryInfo& info) {
    const Transform* t = info.entity >= 0 ? &worldFromEntity_[size_t(info.entity)] : nullptr;
    auto* v = static_cast<float*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_VERTEX, 0));
    if (info.mesh) {
        const std::vector<Vec3>& positions = info.mesh->positions;
        for (size_t i = 0; i < positions.size(); ++i) {
            const Vec3 p = t ? t->applyPoint(positions[i]) : positions[i];
            v[3 * i] = float(p.x), v[3 * i + 1] = float(p.y), v[3 * i + 2] = float(p.z);
        }
        return;
    }
    const Vec3 c = t ? t->applyPoint(info.center) : info.center;
    v[0] = float(c.x), v[1] = float(c.y), v[2] = float(c.z), v[3] = info.radius;
    if (!(info.normal == Vec3())) {
        const Vec3 n = t ? t->applyVector(info.normal) : info.normal;
        auto* nb = static_cast<float*>(rtcGetGeometryBufferData(g, RTC_BUFFER_TYPE_NORMAL, 0));
        nb[0] = float(n.x), nb[1] = float(n.y), nb[2] = float(n.z);
    }
}

namespace {

// Embree's parallel builders may lay a BVH out differently from run to run, and the
// event hall's values then differed in their last digits between runs at 2 threads
// (tests/cli/thread_count_test.cpp). Built on the calling thread alone, the same scene,
// seed and thread count trace the same numbers (a build in the search is small).
void commitOnOneThread(RTCScene scene) {
    tbb::task_arena one(1);
    one.execute([&] { rtcCommitScene(scene); });
}

// Robust traversal: a box test that rounds the wrong way can skip the triangle a few
// ulps nearer than the one found, and whether it does depends on the BVH of the
// moment; the path cache needs a ray that missed every move to meet what it met
// before (incremental/path_cache.h). About 2% of the search's time.
// The context filter function: the second query that breaks ties (below).
const RTCSceneFlags kTraversal = RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION;

RTCScene newSubScene(RTCDevice device) {
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, kTraversal);
    return scene;
}

}  // namespace

void EmbreeScene::finishSubScene(SubScene& sub) {
    commitOnOneThread(sub.scene);
    RTCGeometry inst = rtcNewGeometry(device_->handle(), RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(inst, sub.scene);
    setRowMajor(inst, sub.entity >= 0 ? worldFromEntity_[sub.entity] : Transform());
    rtcCommitGeometry(inst);
    sub.instanceId = rtcAttachGeometry(top_, inst);
    rtcReleaseGeometry(inst);
    if (subSceneOfInstance_.size() <= sub.instanceId) subSceneOfInstance_.resize(sub.instanceId + 1, -1);
}

EmbreeScene::EmbreeScene(const Scene& scene, const Layout& layout, std::shared_ptr<EmbreeDevice> device)
    : scene_(scene), device_(std::move(device)) {
    RTCDevice dev = device_->handle();
    worldFromEntity_ = worldTransforms(scene, layout);
    emitterMeshes_.resize(scene.emitters.size());
    top_ = rtcNewScene(dev);
    rtcSetSceneFlags(top_, RTC_SCENE_FLAG_DYNAMIC | kTraversal);
    rtcSetSceneBuildQuality(top_, RTC_BUILD_QUALITY_LOW);
    flat_.scene = top_;
    flat_.flat = true;

    // Items lie flat while their triangles add up to at most kFlatTriangles, the room
    // first (nearly every ray meets it), so that a move rebuilds a small BVH; the
    // others get a sub-scene each, built once and instanced.
    auto fitsFlat = [&](const TriangleMesh& mesh) {
        if (flatTriangles_ + mesh.triangleCount() > kFlatTriangles) return false;
        flatTriangles_ += mesh.triangleCount();
        return true;
    };
    // Static geometry: visible static items and fixed luminaires. Invisible blockers
    // only collide (overlap constraint) and take no part in light transport.
    for (size_t i = 0; i < scene.geometry.size(); ++i) {
        const StaticItem& item = scene.geometry[i];
        if (item.invisible || item.mesh.empty()) continue;
        if (fitsFlat(item.mesh)) {
            attachMesh(flat_, item.mesh, HitKind::Static, int(i));
            continue;
        }
        SubScene sub;
        sub.scene = newSubScene(dev);
        attachMesh(sub, item.mesh, HitKind::Static, int(i));
        subScenes_.push_back(std::move(sub));
    }
    for (size_t i = 0; i < scene.emitters.size(); ++i)
        if (scene.emitters[i].entity < 0) attachEmitter(flat_, scene.emitters[i], int(i));

    subSceneOfEntity_.assign(scene.entities.size(), -1);
    flatOfEntity_.assign(scene.entities.size(), {});
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& e = scene.entities[i];
        if (!e.hasGeometry() && e.emitters.empty()) continue;
        ++entitiesMet_;
        if (fitsFlat(e.mesh)) {
            const size_t before = flat_.geometries.size();
            if (e.hasGeometry()) attachMesh(flat_, e.mesh, HitKind::Entity, int(i));
            for (int em : e.emitters) attachEmitter(flat_, scene.emitters[em], em);
            for (size_t id = before; id < flat_.geometries.size(); ++id) flatOfEntity_[i].push_back(unsigned(id));
            continue;
        }
        SubScene sub;
        sub.scene = newSubScene(dev);
        sub.entity = int(i);
        attachMesh(sub, e.mesh, HitKind::Entity, int(i));
        for (int em : e.emitters) attachEmitter(sub, scene.emitters[em], em);
        subSceneOfEntity_[i] = int(subScenes_.size());
        subScenes_.push_back(std::move(sub));
    }
    for (size_t s = 0; s < subScenes_.size(); ++s) {
        finishSubScene(subScenes_[s]);
        subSceneOfInstance_[subScenes_[s].instanceId] = int(s);
    }
    commit();
}

EmbreeScene::~EmbreeScene() {
    for (auto& sub : subScenes_) rtcReleaseScene(sub.scene);
    rtcReleaseScene(top_);
}

size_t EmbreeScene::entityCount() const { return entitiesMet_; }

void EmbreeScene::setEntityTransform(int entity, const Transform& worldFromEntity) {
    const Transform& was = worldFromEntity_[size_t(entity)];
    if (was.m == worldFromEntity.m && was.t == worldFromEntity.t) return;  // nothing to rebuild
    worldFromEntity_[size_t(entity)] = worldFromEntity;
    for (unsigned id : flatOfEntity_[size_t(entity)]) {
        RTCGeometry g = rtcGetGeometry(top_, id);
        place(g, flat_.geometries[id]);
        rtcUpdateGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0);
        if (flat_.geometries[id].mesh == nullptr && !(flat_.geometries[id].normal == Vec3()))  // a disc
            rtcUpdateGeometryBuffer(g, RTC_BUFFER_TYPE_NORMAL, 0);
        rtcCommitGeometry(g);
    }
    int s = subSceneOfEntity_[size_t(entity)];
    if (s < 0) return;
    RTCGeometry inst = rtcGetGeometry(top_, subScenes_[s].instanceId);
    setRowMajor(inst, worldFromEntity);
    rtcCommitGeometry(inst);
}

void EmbreeScene::setLayout(const Layout& layout) {
    auto world = worldTransforms(scene_, layout);
    for (size_t i = 0; i < world.size(); ++i) setEntityTransform(int(i), world[i]);
    commit();
}

void EmbreeScene::commit() {
    commitOnOneThread(top_);
    device_->check("scene commit");
}

namespace {

// Which of the faces a ray meets at exactly the same distance it hits: the one first
// in a fixed order (instance, geometry, triangle), not the one the BVH of the moment
// visits first, which changes with moves elsewhere. Asked where the first hit is on a
// face that coincides with another material's in its item (TriangleFace::tieProne: a
// partition's glass flush with its wooden base, a glass top on a leg) and for rays
// that ask (Ray::breakTies: from a path inside see-through parts, which may rest on
// other entities, a glass box on the floor). A second query over a sliver of t around
// the hit sees every candidate there, keeps the least and refuses them all.
struct TieQuery {
    RTCIntersectContext context;  // first: Embree hands the filter its address
    float t = 0;
    bool found = false;
    RTCHit best;
};

bool before(const RTCHit& a, const RTCHit& b) {
    if (a.instID[0] != b.instID[0]) return a.instID[0] + 1u < b.instID[0] + 1u;  // flat (invalid id) first
    if (a.geomID != b.geomID) return a.geomID < b.geomID;
    return a.primID < b.primID;
}

void keepTheFirstOfTheTied(const RTCFilterFunctionNArguments* args) {
    auto* q = reinterpret_cast<TieQuery*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        args->valid[i] = 0;  // refused: the traversal goes on to the others
        if (RTCRayN_tfar(args->ray, args->N, i) != q->t) continue;
        RTCHit h;
        h.Ng_x = RTCHitN_Ng_x(args->hit, args->N, i), h.Ng_y = RTCHitN_Ng_y(args->hit, args->N, i);
        h.Ng_z = RTCHitN_Ng_z(args->hit, args->N, i);
        h.u = RTCHitN_u(args->hit, args->N, i), h.v = RTCHitN_v(args->hit, args->N, i);
        h.primID = RTCHitN_primID(args->hit, args->N, i), h.geomID = RTCHitN_geomID(args->hit, args->N, i);
        h.instID[0] = RTCHitN_instID(args->hit, args->N, i, 0);
        if (!q->found || before(h, q->best)) q->best = h, q->found = true;
    }
}

}  // namespace

EmbreeScene::Met EmbreeScene::metBy(const RTCHit& h) const {
    const SubScene& sub = h.instID[0] == RTC_INVALID_GEOMETRY_ID ? flat_ : subScenes_[size_t(subSceneOfInstance_[h.instID[0]])];
    return {&sub, &sub.geometries[h.geomID]};
}

RTCHit EmbreeScene::firstOfTheTied(const RTCRayHit& found, float tMin) const {
    TieQuery q;
    rtcInitIntersectContext(&q.context);
    q.context.filter = keepTheFirstOfTheTied;
    q.t = found.ray.tfar;
    RTCRayHit again;
    again.ray = found.ray;
    again.ray.tnear = std::max(tMin, q.t * (1 - 1e-5f));
    again.ray.tfar = q.t * (1 + 1e-5f);
    again.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    again.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_, &q.context, &again);
    return q.found ? q.best : found.hit;
}

std::optional<Hit> EmbreeScene::intersect(const Ray& r) const {
    if (log_) log_->closest.push_back(r);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = toRtcRay(r);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    Met met = metBy(rh.hit);
    if (r.breakTies || (met.info->faces && (*met.info->faces)[rh.hit.primID].tieProne)) {
        rh.hit = firstOfTheTied(rh, float(r.tMin));
        met = metBy(rh.hit);
    }

    const SubScene& sub = *met.sub;
    const GeometryInfo& info = *met.info;
    Hit hit;
    hit.t = rh.ray.tfar;
    hit.point = r.origin + r.direction * hit.t;
    hit.kind = info.kind;
    hit.index = info.index;
    hit.primitive = rh.hit.primID;
    // Normals are taken in the geometry's own frame, in double, and placed in the
    // world: entity transforms are rigid, so normals transform like vectors.
    const Transform* world = info.entity >= 0 ? &worldFromEntity_[size_t(info.entity)] : nullptr;
    // Embree's own Ng (a sphere's, a disc's) is in the frame of what the ray met: the
    // world for flat geometry.
    Vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    if (!info.mesh && &sub == &flat_) world = nullptr;
    if (info.mesh) {
        const TriangleFace& face = (*info.faces)[rh.hit.primID];
        ng = face.normal;  // exact, in double
        hit.material = face.material;
        Vec3 ns = ng;
        if (info.mesh->normals.size() == info.mesh->positions.size()) {
            const auto& tri = info.mesh->triangles[rh.hit.primID];
            double u = rh.hit.u, v = rh.hit.v;
            ns = normalize(info.mesh->normals[tri[0]] * (1 - u - v) + info.mesh->normals[tri[1]] * u +
                           info.mesh->normals[tri[2]] * v);
        }
        hit.shadingNormal = world ? normalize(world->applyVector(ns)) : ns;
    }
    hit.geometricNormal = normalize(world ? world->applyVector(ng) : ng);
    if (!info.mesh) hit.shadingNormal = hit.geometricNormal;
    return hit;
}

bool EmbreeScene::occluded(const Ray& r) const {
    if (log_) log_->shadow.push_back(r);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = toRtcRay(r);
    rtcOccluded1(top_, &context, &ray);
    return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
}

}  // namespace luxplan
