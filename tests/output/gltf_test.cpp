// scene.glb: it reads back with tinygltf (nodes, meshes, materials, lights); luxplan's
// own glTF import reads it in tests/roundtrip/glb_import_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include <tiny_gltf.h>

#include <luxplan/core/error.h>
#include <luxplan/output/gltf_export.h>
#include <luxplan/daylight/daylight.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"
#include "support/shared_scenes.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

struct Exported {
    test::TempDir dir;
    Scene scene;
    Layout layout;
    std::filesystem::path file;
    tinygltf::Model model;
};

std::unique_ptr<Exported> exportScene() {
    auto e = std::make_unique<Exported>();
    e->scene = test::furnishedRoom();  // support/shared_scenes.h
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

TEST(Gltf, UnwritableFileThrows) {
    test::TempDir dir;
    Scene scene = test::furnishedRoom();
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

// A table of two box parts (top and one leg) under a uniform 2000 cd/m2 sky and a sun
// at 30 deg altitude due south (azimuth 180) with 60 klx at normal incidence.
Scene daylitTable() {
    DaylightParams d;
    d.model = SkyModelType::Uniform;
    d.luminanceNits = 2000;
    d.sunOverride = SunOverride{30, 180, 60000};
    d.groundReflectance = 0;
    return test::SceneBuilder()
        .material("wall", test::diffuse(0.5))
        .material("wood", test::diffuse(0.4))
        .daylight(d)
        .room({0, 0, 0}, {4, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 1, 2, 0.9, 1.2)
        .entity("table", {2, 2, 0}).part({1.2, 0.8, 0.04}, "wood", Vec3(0, 0, 0.73)).part({0.05, 0.05, 0.71}, "wood").end()
        .build();
}

TEST(Gltf, PartsAreNodesAndTheSunAndSkyAreThere) {
    test::SceneLab lab(daylitTable());
    test::TempDir dir;
    const auto file = dir.path() / "scene.glb";
    writeGlb(file, lab.scene, initialLayout(lab.scene), &*lab.daylight);
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, file.string())) << err;

    // The table is a node placed by the layout, its two parts child nodes with meshes.
    const tinygltf::Node* table = findNode(m, "table");
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->mesh, -1);
    ASSERT_EQ(table->children.size(), 2u);
    const tinygltf::Node& top = m.nodes[size_t(table->children[0])];
    EXPECT_EQ(top.name, "table part 1: box");
    EXPECT_EQ(m.nodes[size_t(table->children[1])].name, "table part 2: box");
    ASSERT_GE(top.mesh, 0);
    // Part 1's mesh is the top alone: 12 triangles, its bounds the top's (glTF y-up).
    const tinygltf::Primitive& prim = m.meshes[size_t(top.mesh)].primitives.at(0);
    EXPECT_EQ(m.accessors[size_t(prim.indices)].count, 36u);
    const tinygltf::Accessor& pos = m.accessors[size_t(prim.attributes.at("POSITION"))];
    EXPECT_NEAR(pos.minValues[1], 0.71, 1e-6);
    EXPECT_NEAR(pos.maxValues[1], 0.75, 1e-6);
    // The scene's root nodes are room and table and the sun, not the parts.
    for (int root : m.scenes[0].nodes) EXPECT_EQ(m.nodes[size_t(root)].name.find(" part "), std::string::npos);

    // The sun: a directional light of 60 klx shining along -z of its node, i.e. from
    // the south (luxplan -y, glTF +z) downwards at 30 deg.
    const tinygltf::Node* sun = findNode(m, "sun");
    ASSERT_NE(sun, nullptr);
    ASSERT_TRUE(sun->extensions.count("KHR_lights_punctual"));
    const tinygltf::Light& light = m.lights.at(size_t(sun->extensions.at("KHR_lights_punctual").Get("light").GetNumberAsInt()));
    EXPECT_EQ(light.type, "directional");
    EXPECT_NEAR(light.intensity, 60000, 60000 * 1e-6);
    Vec3 shines = rotate(*sun, Vec3(0, 0, -1));  // glTF frame
    Vec3 expected(0, -std::sin(radians(30)), -std::cos(radians(30)));  // luxplan (0, +cos, -sin) in glTF
    EXPECT_NEAR(shines.x, expected.x, 1e-6);
    EXPECT_NEAR(shines.y, expected.y, 1e-6);
    EXPECT_NEAR(shines.z, expected.z, 1e-6);

    // The sky: a uniform 2000 cd/m2 sky is its own mean, E_h = pi L.
    const tinygltf::Value& sky = m.scenes[0].extras.Get("sky");
    ASSERT_TRUE(sky.IsObject());
    EXPECT_NEAR(sky.Get("luminance_cd_m2").GetNumberAsDouble(), 2000, 2000 * 1e-3);
    EXPECT_NEAR(sky.Get("horizontal_illuminance_lx").GetNumberAsDouble(), kPi * 2000, kPi * 2000 * 1e-2);
    EXPECT_EQ(sky.Get("color").ArrayLen(), 3u);

    // Without daylight: no sun, no sky.
    writeGlb(file, lab.scene, initialLayout(lab.scene));
    tinygltf::Model night;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&night, &err, &warn, file.string())) << err;
    EXPECT_EQ(findNode(night, "sun"), nullptr);
    EXPECT_FALSE(night.scenes[0].extras.Has("sky"));
}

}  // namespace
}  // namespace luxplan
