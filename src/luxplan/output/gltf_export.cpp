// glTF 2.0 export of a scene under a layout: meshes split into one primitive per
// material, PBR materials, emitters as emissive shapes and KHR_lights_punctual lights.
#include <luxplan/output/gltf_export.h>
#include <luxplan/output/black_body.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/output/render.h>

namespace luxplan {
namespace {

constexpr const char* kTransmission = "KHR_materials_transmission";
constexpr const char* kLights = "KHR_lights_punctual";

// luxplan's z-up frame to glTF's y-up frame: (x, y, z) -> (x, z, -y); the inverse of
// io/mesh_io's import.
Transform gltfFromLuxplan() {
    Transform t;
    t.m = {1, 0, 0, 0, 0, 1, 0, -1, 0};
    return t;
}

Transform luxplanFromGltf() {
    Transform t;
    t.m = {1, 0, 0, 0, 0, -1, 0, 1, 0};
    return t;
}

// A rotation matrix (row-major) as a unit quaternion [x, y, z, w].
std::vector<double> quaternion(const std::array<double, 9>& r) {
    double x, y, z, w;
    double trace = r[0] + r[4] + r[8];
    if (trace > 0) {
        double s = 0.5 / std::sqrt(trace + 1);
        w = 0.25 / s, x = (r[7] - r[5]) * s, y = (r[2] - r[6]) * s, z = (r[3] - r[1]) * s;
    } else if (r[0] > r[4] && r[0] > r[8]) {
        double s = 2 * std::sqrt(1 + r[0] - r[4] - r[8]);
        w = (r[7] - r[5]) / s, x = 0.25 * s, y = (r[1] + r[3]) / s, z = (r[2] + r[6]) / s;
    } else if (r[4] > r[8]) {
        double s = 2 * std::sqrt(1 + r[4] - r[0] - r[8]);
        w = (r[2] - r[6]) / s, x = (r[1] + r[3]) / s, y = 0.25 * s, z = (r[5] + r[7]) / s;
    } else {
        double s = 2 * std::sqrt(1 + r[8] - r[0] - r[4]);
        w = (r[3] - r[1]) / s, x = (r[2] + r[6]) / s, y = (r[5] + r[7]) / s, z = 0.25 * s;
    }
    double n = std::sqrt(x * x + y * y + z * z + w * w);
    return {x / n, y / n, z / n, w / n};
}

bool isRigid(const Transform& t) {
    Vec3 c0(t.m[0], t.m[3], t.m[6]), c1(t.m[1], t.m[4], t.m[7]), c2(t.m[2], t.m[5], t.m[8]);
    const double eps = 1e-6;
    return std::abs(dot(c0, c0) - 1) < eps && std::abs(dot(c1, c1) - 1) < eps && std::abs(dot(c2, c2) - 1) < eps &&
           std::abs(dot(c0, c1)) < eps && std::abs(dot(c0, c2)) < eps && std::abs(dot(c1, c2)) < eps &&
           t.determinant() > 0;
}

// The node's local transform: translation and rotation for rigid motions, else a matrix.
void setNodeTransform(tinygltf::Node& node, const Transform& t) {
    if (!isRigid(t)) {
        const auto& m = t.m;  // row-major; glTF wants column-major
        node.matrix = {m[0], m[3], m[6], 0, m[1], m[4], m[7], 0, m[2], m[5], m[8], 0, t.t.x, t.t.y, t.t.z, 1};
        return;
    }
    if (t.t != Vec3()) node.translation = {t.t.x, t.t.y, t.t.z};
    const std::array<double, 9> identity{1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (t.m != identity) node.rotation = quaternion(t.m);
}


class GlbBuilder {
public:
    explicit GlbBuilder(const Scene& scene) {
        model_.asset.version = "2.0";
        model_.asset.generator = "luxplan";
        model_.scenes.emplace_back();
        model_.scenes[0].name = scene.name;
        model_.defaultScene = 0;
        for (const Material& m : scene.materials) addMaterial(m);
    }

    // Adds a glTF mesh with one primitive per material of the triangles [first, first +
    // count) of `mesh`; positions and normals are taken through `vertexTransform` (a
    // rotation and translation). -1 for an empty mesh.
    int addMesh(const std::string& name, const TriangleMesh& mesh, const Transform& vertexTransform,
                int materialOverride = -1, size_t first = 0, size_t count = std::numeric_limits<size_t>::max()) {
        std::map<int, std::vector<size_t>> byMaterial;
        const size_t end = std::min(mesh.triangles.size(), first + std::min(count, mesh.triangles.size()));
        for (size_t t = first; t < end; ++t)
            byMaterial[materialOverride >= 0 ? materialOverride : int(mesh.materials[t])].push_back(t);
        tinygltf::Mesh out;
        out.name = name;
        bool normals = mesh.normals.size() == mesh.positions.size();
        for (const auto& [material, tris] : byMaterial) {
            std::vector<uint32_t> remap(mesh.positions.size(), std::numeric_limits<uint32_t>::max());
            std::vector<float> positions, normalData;
            std::vector<uint32_t> indices;
            Vec3 lo(kInf, kInf, kInf), hi(-kInf, -kInf, -kInf);
            for (size_t t : tris) {
                for (uint32_t v : mesh.triangles[t]) {
                    if (remap[v] == std::numeric_limits<uint32_t>::max()) {
                        remap[v] = uint32_t(positions.size() / 3);
                        Vec3 p = vertexTransform.applyPoint(mesh.positions[v]);
                        lo = min(lo, p), hi = max(hi, p);
                        positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
                        if (normals) {
                            Vec3 n = normalize(vertexTransform.applyVector(mesh.normals[v]));
                            normalData.insert(normalData.end(), {float(n.x), float(n.y), float(n.z)});
                        }
                    }
                    indices.push_back(remap[v]);
                }
            }
            tinygltf::Primitive prim;
            prim.mode = TINYGLTF_MODE_TRIANGLES;
            prim.material = material;
            prim.attributes["POSITION"] = addAccessor(positions.data(), positions.size() * 4, positions.size() / 3,
                                                      TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                      TINYGLTF_TARGET_ARRAY_BUFFER, {lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z});
            if (normals)
                prim.attributes["NORMAL"] = addAccessor(normalData.data(), normalData.size() * 4, normalData.size() / 3,
                                                        TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                        TINYGLTF_TARGET_ARRAY_BUFFER, {}, {});
            prim.indices = addAccessor(indices.data(), indices.size() * 4, indices.size(), TINYGLTF_TYPE_SCALAR,
                                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, {}, {});
            out.primitives.push_back(std::move(prim));
        }
        if (out.primitives.empty()) return -1;
        model_.meshes.push_back(std::move(out));
        return int(model_.meshes.size()) - 1;
    }

    // A node, at the root or a child of node `parent`; `transform` is in glTF's frame,
    // relative to the parent. Returns its index.
    int addNode(const std::string& name, int mesh, const Transform& transform, const std::string& jsonPath,
                int parent = -1) {
        tinygltf::Node node;
        node.name = name;
        node.mesh = mesh;
        setNodeTransform(node, transform);
        if (!jsonPath.empty())
            node.extras = tinygltf::Value(tinygltf::Value::Object{{"json_path", tinygltf::Value(jsonPath)}});
        model_.nodes.push_back(std::move(node));
        const int index = int(model_.nodes.size()) - 1;
        if (parent >= 0) model_.nodes[size_t(parent)].children.push_back(index);
        else model_.scenes[0].nodes.push_back(index);
        return index;
    }
    tinygltf::Node& node(int index) { return model_.nodes.at(size_t(index)); }

    // The emissive material of one emitter (after the scene's materials).
    int addEmitterMaterial(const Emitter& e, const Vec3& rgb) {
        tinygltf::Material m;
        m.name = "emitter " + e.name;
        m.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
        m.pbrMetallicRoughness.metallicFactor = 0;
        m.pbrMetallicRoughness.roughnessFactor = 1;
        m.emissiveFactor = {rgb.x, rgb.y, rgb.z};
        model_.materials.push_back(std::move(m));
        return int(model_.materials.size()) - 1;
    }

    // A KHR_lights_punctual light of `intensity` (candela; lux for a directional one)
    // times `rgb`; spot lights get the widest cone glTF allows (a hemisphere), the
    // closest it has to a Lambertian emitter. glTF's colour is within [0, 1]: it is
    // written scaled to a largest component of 1, the scale moved into the intensity
    // (lightColorAndIntensity), so that colour x intensity is unchanged.
    int addLight(const std::string& name, const char* type, double intensity, const Vec3& rgb) {
        tinygltf::Light light;
        light.name = name;
        light.type = type;
        const bool spot = light.type == "spot";
        const auto [color, scaled] = lightColorAndIntensity(rgb, intensity);
        light.intensity = scaled;
        light.color = {color.x, color.y, color.z};
        if (spot) {
            light.spot.innerConeAngle = 0;
            light.spot.outerConeAngle = kPi / 2;
        }
        model_.lights.push_back(std::move(light));
        return int(model_.lights.size()) - 1;
    }

    tinygltf::Model& model() { return model_; }

private:
    void addMaterial(const Material& s) {
        tinygltf::Material m;
        m.name = s.name;
        auto& pbr = m.pbrMetallicRoughness;
        Vec3 color = s.reflectance;
        pbr.metallicFactor = 0;
        pbr.roughnessFactor = 1;
        switch (s.type) {
            case MaterialType::Diffuse: break;
            case MaterialType::Translucent:
                // glTF has no diffuse transmission in its core: a double-sided diffuse
                // surface of the colour seen from either side, reflected plus transmitted.
                color = s.reflectance + s.diffuseTransmittance;
                m.doubleSided = true;
                break;
            case MaterialType::Glossy:
                // glTF's roughness r has GGX alpha = r^2; the coat's F0 has no core glTF slot.
                color = s.base;
                pbr.roughnessFactor = std::sqrt(std::clamp(s.roughness, 0.0, 1.0));
                break;
            case MaterialType::Mirror:
                pbr.metallicFactor = 1;
                pbr.roughnessFactor = 0;
                break;
            case MaterialType::Glass: {
                color = Vec3(1, 1, 1);
                pbr.roughnessFactor = 0;
                m.alphaMode = "BLEND";
                m.doubleSided = true;
                tinygltf::Value::Object transmission{{"transmissionFactor", tinygltf::Value(s.transmittance)}};
                m.extensions[kTransmission] = tinygltf::Value(transmission);
                if (std::find(model_.extensionsUsed.begin(), model_.extensionsUsed.end(), kTransmission) ==
                    model_.extensionsUsed.end())
                    model_.extensionsUsed.push_back(kTransmission);
                break;
            }
        }
        double alpha = s.type == MaterialType::Glass ? std::clamp(1 - s.transmittance, 0.0, 1.0) : 1.0;
        pbr.baseColorFactor = {color.x, color.y, color.z, alpha};
        model_.materials.push_back(std::move(m));
    }

    int addAccessor(const void* data, size_t bytes, size_t count, int type, int componentType, int target,
                    std::vector<double> lo, std::vector<double> hi) {
        auto& buffer = buffer0();
        size_t offset = buffer.data.size();
        buffer.data.resize(offset + bytes);
        if (bytes) std::memcpy(buffer.data.data() + offset, data, bytes);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = offset;
        view.byteLength = bytes;
        view.target = target;
        model_.bufferViews.push_back(view);
        tinygltf::Accessor acc;
        acc.bufferView = int(model_.bufferViews.size()) - 1;
        acc.byteOffset = 0;
        acc.componentType = componentType;
        acc.count = count;
        acc.type = type;
        acc.minValues = std::move(lo);
        acc.maxValues = std::move(hi);
        model_.accessors.push_back(std::move(acc));
        return int(model_.accessors.size()) - 1;
    }

    tinygltf::Buffer& buffer0() {
        if (model_.buffers.empty()) model_.buffers.emplace_back();
        return model_.buffers[0];
    }

    tinygltf::Model model_;
};

// Where each camera's far plane goes: beyond every point of `scene` under the layout
// (`world`), luxplan's frame; empty for a scene without geometry.
Bounds3 gltfSceneBounds(const Scene& scene, const std::vector<Transform>& world) {
    Bounds3 b;
    for (const StaticItem& item : scene.geometry)
        if (!item.invisible && !item.mesh.empty()) b.extend(item.mesh.bounds());
    for (size_t i = 0; i < scene.entities.size(); ++i)
        if (scene.entities[i].hasGeometry()) b.extend(world[i].apply(scene.entities[i].mesh.bounds()));
    for (const Emitter& e : scene.emitters) {
        const Transform owner = e.entity >= 0 ? world[size_t(e.entity)] : Transform();
        const EmitterMesh shape = e.shape->mesh();
        if (!shape.mesh.empty()) b.extend((owner * shape.frame).apply(shape.mesh.bounds()));
    }
    return b;
}

// A rotation taking glTF's -z (where cameras look and directional lights shine) to
// unit `forward`, keeping `up` (not parallel to it) up.
Transform lookingAlong(Vec3 forward, Vec3 up) {
    const Vec3 f = normalize(forward);
    if (length(cross(f, up)) < 1e-6) up = std::abs(f.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 r = normalize(cross(f, up)), u = cross(r, f);
    Transform t;
    t.m = {r.x, u.x, -f.x, r.y, u.y, -f.y, r.z, u.z, -f.z};
    return t;
}

}  // namespace

LightColor lightColorAndIntensity(const Vec3& rgb, double intensity) {
    const Vec3 c = max(rgb, Vec3(0, 0, 0));  // a black body's colour has no negative parts; glTF's none either
    const double peak = std::max({c.x, c.y, c.z});
    if (!(peak > 0) || !std::isfinite(peak)) return {Vec3(1, 1, 1), 0};
    return {c / peak, intensity * peak};
}

double cameraFar(const Bounds3& scene, const Vec3& eye) {
    double farthest = 0;
    if (!scene.empty())
        for (int k = 0; k < 8; ++k) {
            const Vec3 corner(k & 1 ? scene.hi.x : scene.lo.x, k & 2 ? scene.hi.y : scene.lo.y, k & 4 ? scene.hi.z : scene.lo.z);
            farthest = std::max(farthest, length(corner - eye));
        }
    return std::max(std::ceil(2 * farthest), 10.0);
}

SunSummary summarizeSun(const DaylightEnvironment& daylight) {
    SunSummary sun;
    Vec3 direction, color;
    for (const SunDisk& d : daylight.sunDisks()) {
        const double e = d.weight * d.normalIlluminanceLx;
        sun.normalIlluminanceLx += e;
        direction = direction + d.direction * e;
        color = color + d.color * e;
    }
    if (!(sun.normalIlluminanceLx > 0)) return {};
    sun.direction = normalize(direction);
    sun.color = color / sun.normalIlluminanceLx;
    return sun;
}

SkySummary summarizeSky(const DaylightEnvironment& daylight) {
    // The sky's mean radiance over the upper hemisphere, weighted by cos(theta) (E_h = pi L
    // for a uniform sky), from a fixed grid of directions: enough for a world colour.
    SkySummary sky;
    Vec3 sum;
    double weight = 0;
    const int rings = 16, segments = 32;
    for (int i = 0; i < rings; ++i) {
        const double cosTheta = (i + 0.5) / rings, sinTheta = std::sqrt(1 - cosTheta * cosTheta);
        for (int k = 0; k < segments; ++k) {
            const double phi = 2 * kPi * (k + 0.5) / segments;
            Vec3 w(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
            sum = sum + daylight.Le(w) * cosTheta;
            weight += cosTheta;
        }
    }
    const Vec3 mean = sum / weight;
    sky.luminance = luminance(mean);
    sky.color = sky.luminance > 0 ? mean / sky.luminance : Vec3(1, 1, 1);
    sky.horizontalIlluminanceLx = daylight.skyHorizontalIlluminance();
    return sky;
}

void writeGlb(const std::filesystem::path& file, const Scene& scene, const Layout& layout,
              const DaylightEnvironment* daylight) {
    GlbBuilder glb(scene);
    const Transform toGltf = gltfFromLuxplan(), fromGltf = luxplanFromGltf();
    std::vector<Transform> world = worldTransforms(scene, layout);

    for (const StaticItem& item : scene.geometry) {
        if (item.invisible || item.mesh.empty()) continue;
        int mesh = glb.addMesh(item.name, item.mesh, toGltf);
        if (mesh >= 0) glb.addNode(item.name, mesh, Transform(), item.jsonPath);
    }
    // An entity is a node placed by the layout; with several parts, each part is a
    // child node of its own ("desk1.table part 2: box"), so a 3D tool can pick it.
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& e = scene.entities[i];
        if (!e.hasGeometry()) continue;
        const Transform placed = toGltf * world[i] * fromGltf;
        size_t covered = 0;
        for (const PartInfo& p : e.parts) covered += p.firstTriangle == covered ? p.triangles : e.mesh.triangles.size() + 1;
        if (e.parts.size() < 2 || covered != e.mesh.triangles.size()) {
            int mesh = glb.addMesh(e.path, e.mesh, toGltf);
            if (mesh >= 0) glb.addNode(e.path, mesh, placed, e.jsonPath);
            continue;
        }
        const int node = glb.addNode(e.path, -1, placed, e.jsonPath);
        for (size_t k = 0; k < e.parts.size(); ++k) {
            const PartInfo& p = e.parts[k];
            std::string name = e.path;
            name += " part ";
            name += std::to_string(k + 1);
            name += ": ";
            name += p.kind.empty() ? "box" : p.kind;
            int mesh = glb.addMesh(name, e.mesh, toGltf, -1, p.firstTriangle, p.triangles);
            std::string path = e.jsonPath;
            path += "/parts/";
            path += std::to_string(k);
            if (mesh >= 0) glb.addNode(name, mesh, Transform(), path, node);
        }
    }
    for (const Emitter& e : scene.emitters) {
        const std::string& name = e.name;  // scoped by its entity already ("desk1.lamp.shade")
        Vec3 rgb = blackBodyRgb(e.cctK);
        Transform owner = e.entity >= 0 ? world[size_t(e.entity)] : Transform();
        EmitterMesh shape = e.shape->mesh();
        int mesh = glb.addMesh(name, shape.mesh, Transform(), glb.addEmitterMaterial(e, rgb));
        const int node = glb.addNode(name, mesh, toGltf * owner * shape.frame, e.jsonPath);
        // Intensity of a Lambertian emitter: flux / (4 pi) all round for one that emits
        // all round; peak (along the normal) flux / pi for a one-sided one. The flux is
        // the maintained one, as the renders show it.
        bool spot = e.shape->normal().has_value();
        const double flux = scene.maintenanceFactor * e.fluxLm;
        int light = glb.addLight(name, spot ? "spot" : "point", spot ? flux / kPi : flux / (4 * kPi), rgb);
        glb.node(node).extensions[kLights] = tinygltf::Value(tinygltf::Value::Object{{"light", tinygltf::Value(light)}});
    }

    // Daylight: the sun as a directional light (lux at normal incidence), shining from
    // the illuminance-weighted mean of its disks; the sky's colour and luminance in the
    // scene's extras ("sky"), which glTF has no core place for (docs/outputs.md gives
    // the lines that make it Blender's world colour).
    if (daylight) {
        if (SunSummary sun = summarizeSun(*daylight); sun.normalIlluminanceLx > 0) {
            int light = glb.addLight("sun", "directional", sun.normalIlluminanceLx, sun.color);
            const Vec3 travel = toGltf.applyVector(-sun.direction), up = toGltf.applyVector(Vec3(0, 0, 1));
            Transform orient = lookingAlong(travel, up);
            orient.t = toGltf.applyPoint(Vec3(0, 0, 10));
            const int node = glb.addNode("sun", -1, orient, "/daylight");
            glb.node(node).extensions[kLights] = tinygltf::Value(tinygltf::Value::Object{{"light", tinygltf::Value(light)}});
        }
    }
    auto triple = [](const Vec3& v) {
        return tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(v.x), tinygltf::Value(v.y), tinygltf::Value(v.z)});
    };
    tinygltf::Value::Object extras;
    if (daylight && daylight->hasSky()) {
        const SkySummary sky = summarizeSky(*daylight);
        extras["sky"] = tinygltf::Value(tinygltf::Value::Object{
            {"color", triple(sky.color)},
            {"luminance_cd_m2", tinygltf::Value(sky.luminance)},
            {"horizontal_illuminance_lx", tinygltf::Value(sky.horizontalIlluminanceLx)}});
    }
    // The room's inside as an axis-aligned box in glTF's frame, for a viewer to frame
    // the room rather than everything around it (report.html's 3D view).
    if (const RoomShell* room = scene.room()) {
        const Bounds3& b = room->box;
        extras["room"] = tinygltf::Value(tinygltf::Value::Object{{"min", triple(Vec3(b.lo.x, b.lo.z, -b.hi.y))},
                                                                 {"max", triple(Vec3(b.hi.x, b.hi.z, -b.lo.y))}});
    }
    if (!extras.empty()) glb.model().scenes[0].extras = tinygltf::Value(std::move(extras));

    // The cameras: the scene's, else render.png's default view (defaultCamera: for a
    // room, from inside it), so that every file opens on the room. A glTF camera looks
    // down its -z with +y up; its far plane lies beyond the whole scene (cameraFar).
    const Bounds3 bounds = gltfSceneBounds(scene, world);
    auto addCamera = [&](const std::string& name, const Camera& look, const std::string& jsonPath) {
        Transform view = lookingAlong(look.lookAt - look.position, look.up);
        view.t = look.position;
        tinygltf::Camera camera;
        camera.name = name;
        camera.type = "perspective";
        camera.perspective.yfov = look.fovDeg * kPi / 180;
        camera.perspective.znear = kGltfCameraNear;
        camera.perspective.zfar = cameraFar(bounds, look.position);
        glb.model().cameras.push_back(camera);
        const int node = glb.addNode(name, -1, toGltf * view, jsonPath);
        glb.node(node).camera = int(glb.model().cameras.size()) - 1;
    };
    for (const SceneCamera& c : scene.cameras)
        addCamera(c.name, lookingAt(c.eye, c.target, c.fovDeg), c.jsonPath);  // render.png's up, too
    if (scene.cameras.empty()) addCamera(kDefaultViewName, defaultCamera(scene), "");

    // WriteGltfSceneToStream(binary) writes what WriteGltfSceneToFile(embedImages,
    // embedBuffers, binary) would; the stream is ours so that a file that cannot be
    // opened or written is reported (tinygltf 2.7's file writer does not check).
    std::ostringstream out(std::ios::binary);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&glb.model(), out, false, true)) throw IoError("cannot write " + file.string());
    writeFileAtomically(file, out.str());
}

}  // namespace luxplan
