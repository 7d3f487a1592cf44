// scene.glb: it reads back with tinygltf (nodes, meshes, materials, lights) and with
// luxplan's own glTF import, whose y-up to z-up turn must give the scene's bounds.
#include <gtest/gtest.h>

#include <cmath>

#include <tiny_gltf.h>

#include <luxplan/core/error.h>
#include <luxplan/io/mesh_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/output/gltf_export.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

const char* kScene = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.6},
                "wood": {"type": "glossy", "reflectance": 0.04, "base": [0.5, 0.3, 0.1], "roughness": 0.25},
                "glass": {"type": "glass", "transmittance": 0.8},
                "chrome": {"type": "mirror", "reflectance": 0.9}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [5,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"},
                "openings": [{"wall": "south", "offset": 1, "width": 1.5, "sill": 0.9, "height": 1.2, "material": "glass"}]},
               {"name": "pillar", "box": {"min": [4,3,0], "max": [4.5,3.5,3]}, "material": "chrome"},
               {"name": "blocker", "box": {"min": [0,0,0], "max": [0.5,0.5,1]}, "invisible": true}],
  "luminaires": [{"name": "panel", "shape": "rect", "center": [2.5,2,2.99], "normal": [0,0,-1], "size": [0.6,1.2],
                  "up": [0,1,0], "flux_lm": 3000, "cct_k": 4000},
                 {"name": "bulb", "shape": "sphere", "center": [1,1,2.5], "radius": 0.1, "flux_lm": 800}],
  "entities": [{"name": "desk1", "position": [2,1.5], "rotation": 90,
                "placement": {"regions": [{"min": [1,1], "max": [4,3], "rotations": [0, 90]}]},
                "parts": [{"preset": "desk", "material": "wood"}],
                "children": [{"name": "lamp", "position": [0.5,0.2,0.75],
                              "parts": [{"box": {"size": [0.1,0.1,0.4]}, "material": "chrome"}],
                              "emitters": [{"name": "shade", "shape": "disk", "center": [0,0,0.45], "normal": [0,0,-1],
                                            "radius": 0.08, "flux_lm": 400}]}]},
               {"name": "group", "children": [{"name": "chair", "position": [3,2],
                                               "parts": [{"preset": "chair", "material": "wood"}]}]}]})";

constexpr size_t kEmitterTriangles = 2 + 48 + 320;  // rect, disk, icosphere

struct Exported {
    test::TempDir dir;
    Scene scene;
    Layout layout;
    std::filesystem::path file;
    tinygltf::Model model;
};

std::unique_ptr<Exported> exportScene() {
    auto e = std::make_unique<Exported>();
    e->scene = io::loadScene(e->dir.write("scene.json", kScene));
    e->layout = initialLayout(e->scene);
    e->file = e->dir.path() / "scene.glb";
    writeGlb(e->file, e->scene, e->layout);
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&e->model, &err, &warn, e->file.string())) << err;
    return e;
}

const tinygltf::Node* findNode(const tinygltf::Model& model, const std::string& name) {
    for (const auto& n : model.nodes)
        if (n.name == name) return &n;
    return nullptr;
}

// The node's rotation applied to v (glTF's [x, y, z, w] quaternion).
Vec3 rotate(const tinygltf::Node& node, const Vec3& v) {
    if (node.rotation.size() != 4) return v;
    Vec3 q(node.rotation[0], node.rotation[1], node.rotation[2]);
    double w = node.rotation[3];
    Vec3 t = cross(q, v) * 2.0;
    return v + t * w + cross(q, t);
}

TEST(Gltf, NodesMeshesMaterialsAndLights) {
    auto e = exportScene();
    const tinygltf::Model& m = e->model;
    // room, pillar (not the blocker); desk1, desk1.lamp, group.chair (not the empty group);
    // panel, bulb, desk1.lamp.shade.
    EXPECT_EQ(m.nodes.size(), 8u);
    EXPECT_EQ(m.meshes.size(), 8u);
    ASSERT_EQ(m.scenes.size(), 1u);
    EXPECT_EQ(m.scenes[0].nodes.size(), 8u);
    for (const char* name : {"room", "pillar", "desk1", "desk1.lamp", "group.chair", "panel", "bulb", "desk1.lamp.shade"})
        EXPECT_NE(findNode(m, name), nullptr) << name;
    EXPECT_EQ(findNode(m, "blocker"), nullptr);
    EXPECT_EQ(findNode(m, "group"), nullptr);

    // One material per scene material, then one emissive material per emitter.
    ASSERT_EQ(m.materials.size(), 4u + 3u);
    auto material = [&](const std::string& name) -> const tinygltf::Material& {
        for (const auto& mat : m.materials)
            if (mat.name == name) return mat;
        ADD_FAILURE() << name;
        return m.materials[0];
    };
    EXPECT_NEAR(material("wood").pbrMetallicRoughness.roughnessFactor, 0.5, 1e-9);  // sqrt(alpha)
    EXPECT_NEAR(material("wood").pbrMetallicRoughness.baseColorFactor[0], 0.5, 1e-9);
    EXPECT_EQ(material("chrome").pbrMetallicRoughness.metallicFactor, 1.0);
    EXPECT_EQ(material("glass").alphaMode, "BLEND");
    EXPECT_NEAR(material("glass").pbrMetallicRoughness.baseColorFactor[3], 0.2, 1e-9);
    EXPECT_TRUE(material("glass").extensions.count("KHR_materials_transmission"));
    EXPECT_GT(material("emitter panel").emissiveFactor[0], 0.9);

    // Lights: candela from flux (flux / pi for one-sided emitters, / 4 pi for spheres).
    ASSERT_EQ(m.lights.size(), 3u);
    for (const auto& light : m.lights) {
        if (light.name == "panel") {
            EXPECT_EQ(light.type, "spot");
            EXPECT_NEAR(light.intensity, 3000 / kPi, 1e-6);
            EXPECT_NEAR(light.spot.outerConeAngle, kPi / 2, 1e-9);
        } else if (light.name == "bulb") {
            EXPECT_EQ(light.type, "point");
            EXPECT_NEAR(light.intensity, 800 / (4 * kPi), 1e-6);
        } else {
            EXPECT_EQ(light.name, "desk1.lamp.shade");
            EXPECT_EQ(light.type, "spot");
        }
    }
    // Spot lights shine along their node's -z, which must be the emitter's normal turned
    // y-up: straight down is glTF's -y.
    for (const char* name : {"panel", "desk1.lamp.shade"}) {
        const tinygltf::Node* node = findNode(m, name);
        ASSERT_NE(node, nullptr);
        EXPECT_TRUE(node->extensions.count("KHR_lights_punctual")) << name;
        Vec3 d = rotate(*node, Vec3(0, 0, -1));
        EXPECT_NEAR(d.x, 0, 1e-9) << name;
        EXPECT_NEAR(d.y, -1, 1e-9) << name;
        EXPECT_NEAR(d.z, 0, 1e-9) << name;
    }
    // desk1 turns 90 degrees about luxplan's z: about glTF's y; (2, 1.5) becomes (2, 0, -1.5).
    const tinygltf::Node* desk = findNode(m, "desk1");
    ASSERT_NE(desk, nullptr);
    ASSERT_EQ(desk->rotation.size(), 4u);
    EXPECT_NEAR(desk->rotation[1], std::sin(kPi / 4), 1e-9);
    EXPECT_NEAR(desk->rotation[3], std::cos(kPi / 4), 1e-9);
    ASSERT_EQ(desk->translation.size(), 3u);
    EXPECT_NEAR(desk->translation[0], 2, 1e-9);
    EXPECT_NEAR(desk->translation[1], 0, 1e-9);
    EXPECT_NEAR(desk->translation[2], -1.5, 1e-9);
}

// The bounds of everything visible under a layout, and its triangle count (emitters included).
std::pair<Bounds3, size_t> visibleGeometry(const Scene& scene, const Layout& layout) {
    std::vector<Transform> world = worldTransforms(scene, layout);
    Bounds3 bounds;
    size_t triangles = kEmitterTriangles;
    for (const StaticItem& item : scene.geometry) {
        if (item.invisible) continue;
        bounds.extend(item.mesh.bounds());
        triangles += item.mesh.triangleCount();
    }
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& ent = scene.entities[i];
        if (!ent.hasGeometry()) continue;
        TriangleMesh placed;
        placed.append(ent.mesh, world[i]);
        bounds.extend(placed.bounds());
        triangles += ent.mesh.triangleCount();
    }
    return {bounds, triangles};
}

void expectBounds(const Bounds3& b, const Bounds3& expected) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.lo[k], expected.lo[k], 1e-5) << k;
        EXPECT_NEAR(b.hi[k], expected.hi[k], 1e-5) << k;
    }
}

TEST(Gltf, LuxplanImportGivesTheSceneBack) {
    auto e = exportScene();
    const Scene& scene = e->scene;
    auto [bounds, triangles] = visibleGeometry(scene, e->layout);
    TriangleMesh back = io::loadMeshFile(e->file, 0);
    EXPECT_EQ(back.triangleCount(), triangles);
    expectBounds(back.bounds(), bounds);

    // Another layout moves the desk (and its lamp) to the room's north-east, past the
    // pillar's bounds: the file's bounds follow.
    Layout moved = e->layout;
    int desk = scene.findEntity("desk1");
    ASSERT_GE(desk, 0);
    moved.placements[size_t(desk)].position = Vec3(4.6, 3.3, 0);
    moved.placements[size_t(desk)].rotationDeg = 0;
    auto other = e->dir.path() / "moved.glb";
    writeGlb(other, scene, moved);
    auto [movedBounds, movedTriangles] = visibleGeometry(scene, moved);
    TriangleMesh backMoved = io::loadMeshFile(other, 0);
    EXPECT_EQ(backMoved.triangleCount(), movedTriangles);
    expectBounds(backMoved.bounds(), movedBounds);
    EXPECT_GT(movedBounds.hi.x, bounds.hi.x);  // the desk now sticks out of the room
}

TEST(Gltf, UnwritableFileThrows) {
    test::TempDir dir;
    Scene scene = io::loadScene(dir.write("scene.json", kScene));
    EXPECT_THROW(writeGlb(dir.path() / "missing" / "scene.glb", scene, initialLayout(scene)), IoError);
}

TEST(Gltf, BlackBodyColours) {
    Vec3 d65 = blackBodyRgb(6500);
    EXPECT_GT(d65.z, 0.9);
    EXPECT_GT(d65.y, 0.9);
    Vec3 warm = blackBodyRgb(2700);
    EXPECT_EQ(warm.x, 1.0);
    EXPECT_GT(warm.x, warm.y);
    EXPECT_GT(warm.y, warm.z);
    Vec3 cold = blackBodyRgb(12000);
    EXPECT_EQ(cold.z, 1.0);
}

}  // namespace
}  // namespace luxplan
