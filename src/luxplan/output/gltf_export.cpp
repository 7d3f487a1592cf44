// glTF 2.0 export of a scene under a layout: meshes split into one primitive per
// material, PBR materials, emitters as emissive shapes and KHR_lights_punctual lights.
#include <luxplan/output/gltf_export.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include <luxplan/core/error.h>

namespace luxplan {
namespace {

constexpr int kDiskSegments = 48;
constexpr int kSphereSubdivisions = 2;  // 320 triangles
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

// Turns every triangle of `mesh` so that its winding normal points along outward(centroid).
template <class Outward>
void orientTriangles(TriangleMesh& mesh, Outward outward) {
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        auto& t = mesh.triangles[i];
        Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        if (dot(cross(b - a, c - a), outward((a + b + c) / 3.0)) < 0) std::swap(t[1], t[2]);
    }
}

// An emitter's shape in its local frame, where it emits towards -z (glTF spot lights
// shine along their node's -z) or, for a sphere, all round its centre.
TriangleMesh emitterShape(const Emitter& e) {
    TriangleMesh mesh;
    if (e.shape == EmitterShape::Rect) {
        double a = e.size.x / 2, b = e.size.y / 2;
        mesh.positions = {{-a, -b, 0}, {a, -b, 0}, {a, b, 0}, {-a, b, 0}};
        mesh.addTriangle(0, 3, 2, 0);
        mesh.addTriangle(0, 2, 1, 0);
        mesh.normals.assign(4, Vec3(0, 0, -1));
    } else if (e.shape == EmitterShape::Disk) {
        mesh.positions.push_back({0, 0, 0});
        for (int k = 0; k < kDiskSegments; ++k) {
            double phi = 2 * kPi * k / kDiskSegments;
            mesh.positions.push_back({e.radius * std::cos(phi), e.radius * std::sin(phi), 0});
        }
        for (uint32_t k = 0; k < uint32_t(kDiskSegments); ++k)
            mesh.addTriangle(0, 1 + (k + 1) % kDiskSegments, 1 + k, 0);
        mesh.normals.assign(mesh.positions.size(), Vec3(0, 0, -1));
        orientTriangles(mesh, [](const Vec3&) { return Vec3(0, 0, -1); });
    } else {
        // Icosphere: the icosahedron with every triangle split in four, kSphereSubdivisions times.
        const double g = (1 + std::sqrt(5.0)) / 2;
        std::vector<Vec3> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                               {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
        for (Vec3& v : p) v = normalize(v);
        std::vector<std::array<uint32_t, 3>> faces = {
            {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
            {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
        for (int level = 0; level < kSphereSubdivisions; ++level) {
            std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
            auto midpoint = [&](uint32_t a, uint32_t b) {
                auto key = std::minmax(a, b);
                auto [it, added] = midpoints.try_emplace({key.first, key.second}, uint32_t(p.size()));
                if (added) p.push_back(normalize(p[a] + p[b]));
                return it->second;
            };
            std::vector<std::array<uint32_t, 3>> next;
            for (const auto& f : faces) {
                uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
                next.push_back({f[0], ab, ca});
                next.push_back({f[1], bc, ab});
                next.push_back({f[2], ca, bc});
                next.push_back({ab, bc, ca});
            }
            faces = std::move(next);
        }
        for (const Vec3& v : p) {
            mesh.positions.push_back(v * e.radius);
            mesh.normals.push_back(v);
        }
        for (const auto& f : faces) mesh.addTriangle(f[0], f[1], f[2], 0);
        orientTriangles(mesh, [](const Vec3& c) { return c; });
    }
    return mesh;
}

// emitterFromLocal: the emitter's frame in its owner's frame (world or entity), with
// local -z along the normal for rects and disks.
Transform emitterFrame(const Emitter& e) {
    Transform t;
    t.t = e.center;
    if (e.shape == EmitterShape::Sphere) return t;
    Vec3 n = normalize(e.normal);
    Vec3 x, y;
    Vec3 up = e.up - n * dot(e.up, n);
    if (e.shape == EmitterShape::Rect && length(up) > 1e-9) {
        // The rect's first side runs along cross(up, n), its second along up.
        y = normalize(up);
        x = -cross(y, n);
    } else {
        Frame f = Frame::fromNormal(-n);
        x = f.s, y = f.t;
    }
    Vec3 z = -n;
    t.m = {x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z};
    return t;
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

    // Adds a glTF mesh with one primitive per material; positions and normals are
    // taken through `vertexTransform` (a rotation and translation). -1 for an empty mesh.
    int addMesh(const std::string& name, const TriangleMesh& mesh, const Transform& vertexTransform,
                int materialOverride = -1) {
        std::map<int, std::vector<size_t>> byMaterial;
        for (size_t t = 0; t < mesh.triangles.size(); ++t)
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

    // A root node; `transform` is in glTF's frame.
    tinygltf::Node& addNode(const std::string& name, int mesh, const Transform& transform, const std::string& jsonPath) {
        tinygltf::Node node;
        node.name = name;
        node.mesh = mesh;
        setNodeTransform(node, transform);
        if (!jsonPath.empty())
            node.extras = tinygltf::Value(tinygltf::Value::Object{{"json_path", tinygltf::Value(jsonPath)}});
        model_.nodes.push_back(std::move(node));
        model_.scenes[0].nodes.push_back(int(model_.nodes.size()) - 1);
        return model_.nodes.back();
    }

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

    // A KHR_lights_punctual light of `intensityCd` candela; spot lights get the widest
    // cone glTF allows (a hemisphere), the closest it has to a Lambertian emitter.
    int addLight(const std::string& name, bool spot, double intensityCd, const Vec3& rgb) {
        tinygltf::Light light;
        light.name = name;
        light.type = spot ? "spot" : "point";
        light.intensity = intensityCd;
        light.color = {rgb.x, rgb.y, rgb.z};
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

}  // namespace

Vec3 blackBodyRgb(double kelvin) {
    // CIE 1931 chromaticity of the Planckian locus (Kim et al. 2002 cubic fits), then
    // XYZ (Y = 1) to linear sRGB primaries.
    double t = std::clamp(kelvin, 1667.0, 25000.0);
    double t2 = t * t, t3 = t2 * t;
    double x = t <= 4000 ? -0.2661239e9 / t3 - 0.2343589e6 / t2 + 0.8776956e3 / t + 0.179910
                         : -3.0258469e9 / t3 + 2.1070379e6 / t2 + 0.2226347e3 / t + 0.240390;
    double x2 = x * x, x3 = x2 * x;
    double y = t <= 2222   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
               : t <= 4000 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                           : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    double X = x / y, Y = 1, Z = (1 - x - y) / y;
    Vec3 rgb(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z, -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
             0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
    rgb = max(rgb, Vec3(0, 0, 0));
    return rgb / maxComponent(rgb);
}

void writeGlb(const std::filesystem::path& file, const Scene& scene, const Layout& layout) {
    GlbBuilder glb(scene);
    const Transform toGltf = gltfFromLuxplan(), fromGltf = luxplanFromGltf();
    std::vector<Transform> world = worldTransforms(scene, layout);

    for (const StaticItem& item : scene.geometry) {
        if (item.invisible || item.mesh.empty()) continue;
        int mesh = glb.addMesh(item.name, item.mesh, toGltf);
        if (mesh >= 0) glb.addNode(item.name, mesh, Transform(), item.jsonPath);
    }
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& e = scene.entities[i];
        if (!e.hasGeometry()) continue;
        int mesh = glb.addMesh(e.path, e.mesh, toGltf);
        if (mesh >= 0) glb.addNode(e.path, mesh, toGltf * world[i] * fromGltf, e.jsonPath);
    }
    for (const Emitter& e : scene.emitters) {
        std::string name = e.entity >= 0 ? scene.entities[size_t(e.entity)].path + "." + e.name : e.name;
        Vec3 rgb = blackBodyRgb(e.cctK);
        Transform owner = e.entity >= 0 ? world[size_t(e.entity)] : Transform();
        int mesh = glb.addMesh(name, emitterShape(e), Transform(), glb.addEmitterMaterial(e, rgb));
        tinygltf::Node& node = glb.addNode(name, mesh, toGltf * owner * emitterFrame(e), e.jsonPath);
        // Intensity of a Lambertian emitter: flux / (4 pi) all round for a sphere; peak
        // (along the normal) flux / pi for a one-sided rect or disk.
        bool spot = e.shape != EmitterShape::Sphere;
        int light = glb.addLight(name, spot, spot ? e.fluxLm / kPi : e.fluxLm / (4 * kPi), rgb);
        node.extensions[kLights] = tinygltf::Value(tinygltf::Value::Object{{"light", tinygltf::Value(light)}});
    }

    // WriteGltfSceneToStream(binary) writes what WriteGltfSceneToFile(embedImages,
    // embedBuffers, binary) would; the stream is ours so that a file that cannot be
    // opened or written is reported (tinygltf 2.7's file writer does not check).
    std::ofstream out(file, std::ios::binary);
    if (!out) throw IoError("cannot write " + file.string());
    tinygltf::TinyGLTF writer;
    bool ok = writer.WriteGltfSceneToStream(&glb.model(), out, false, true);
    out.close();
    if (!ok || !out) throw IoError("cannot write " + file.string());
}

}  // namespace luxplan
