// scene.glb: it reads back with tinygltf (nodes, meshes, materials, lights); luxplan's
// own glTF import reads it in tests/roundtrip/glb_import_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <tiny_gltf.h>

#include <luxplan/core/error.h>
#include <luxplan/output/gltf_export.h>
#include <luxplan/output/render.h>
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
    // panel, bulb, desk1.lamp.shade; the default view (the scene has no cameras).
    EXPECT_EQ(m.nodes.size(), 9u);
    EXPECT_EQ(m.meshes.size(), 8u);
    ASSERT_EQ(m.scenes.size(), 1u);
    EXPECT_EQ(m.scenes[0].nodes.size(), 9u);
    for (const char* name : {"room", "pillar", "desk1", "desk1.lamp", "group.chair", "panel", "bulb", "desk1.lamp.shade",
                             kDefaultViewName})
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
    // Its colour within [0, 1] (largest component 1), colour x intensity the sun's.
    ASSERT_EQ(light.color.size(), 3u);
    const Vec3 color(light.color[0], light.color[1], light.color[2]);
    EXPECT_NEAR(std::max({color.x, color.y, color.z}), 1, 1e-12);
    EXPECT_NEAR(luminance(color) * light.intensity, 60000, 60000 * 1e-6);
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

// glTF y-up: luxplan's (x, y, z) is (x, z, -y) there, and back.
Vec3 luxplanPoint(const std::vector<double>& gltf) { return {gltf.at(0), -gltf.at(2), gltf.at(1)}; }

tinygltf::Model readGlb(const std::filesystem::path& file) {
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, file.string())) << err;
    return m;
}

// Every light of every exported file: colour components in [0, 1] (the Khronos
// validator's range), the largest 1, colour x intensity as luxplan's.
TEST(Gltf, LightColoursAreWithinZeroAndOne) {
    const LightColor sun = lightColorAndIntensity(Vec3(1.202, 0.95, 0.61), 50000);
    EXPECT_NEAR(sun.color.x, 1, 1e-12);
    EXPECT_NEAR(sun.color.y, 0.95 / 1.202, 1e-12);
    EXPECT_NEAR(sun.color.z, 0.61 / 1.202, 1e-12);
    EXPECT_NEAR(sun.intensity, 50000 * 1.202, 1e-6);
    const LightColor dim = lightColorAndIntensity(Vec3(0.5, 0.25, 0.1), 100);  // brightened to 1
    EXPECT_NEAR(dim.color.x, 1, 1e-12);
    EXPECT_NEAR(dim.intensity, 50, 1e-9);
    const LightColor negative = lightColorAndIntensity(Vec3(0.8, -0.01, 0.4), 10);
    EXPECT_EQ(negative.color.y, 0);
    EXPECT_NEAR(negative.color.x, 1, 1e-12);
    const LightColor black = lightColorAndIntensity(Vec3(0, 0, 0), 100);
    EXPECT_EQ(black.intensity, 0);
    EXPECT_EQ(black.color, Vec3(1, 1, 1));

    // A low sun through Preetham's atmosphere is reddish: its colour of luminance 1 has a
    // red component above 1.
    DaylightParams d;
    d.model = SkyModelType::Preetham;
    d.sunOverride = SunOverride{10, 180, std::nullopt};
    Scene scene = daylitTable();
    scene.daylight = d;
    test::SceneLab lab(scene);
    ASSERT_GT(summarizeSun(*lab.daylight).color.x, 1);
    test::TempDir dir;
    writeGlb(dir.path() / "scene.glb", lab.scene, initialLayout(lab.scene), &*lab.daylight);
    const tinygltf::Model m = readGlb(dir.path() / "scene.glb");
    ASSERT_EQ(m.lights.size(), 1u);  // the sun: the table has no lamps
    auto e = exportScene();          // and the furnished room's lamps
    std::vector<tinygltf::Light> lights = m.lights;
    lights.insert(lights.end(), e->model.lights.begin(), e->model.lights.end());
    for (const tinygltf::Light& light : lights) {
        ASSERT_EQ(light.color.size(), 3u) << light.name;
        for (double c : light.color) {
            EXPECT_GE(c, 0) << light.name;
            EXPECT_LE(c, 1) << light.name;
        }
        EXPECT_NEAR(*std::max_element(light.color.begin(), light.color.end()), 1, 1e-12) << light.name;
        EXPECT_GT(light.intensity, 0) << light.name;
    }
}

// Every camera is a perspective camera with 0 < znear < zfar, its far plane beyond
// everything in the file, surroundings far outside the room included (Blender clips at
// zfar: zfar 0 drew an empty frame).
TEST(Gltf, NoCameraHasItsFarPlaneAtOrBeforeItsNearPlane) {
    Scene scene = test::furnishedRoom();
    scene.cameras.push_back({"door", "/cameras/0", {0.5, 3.5, 1.6}, {4, 1, 1}, 70});
    scene.cameras.push_back({"above", "/cameras/1", {2.5, 2, 2.9}, {2.5, 2, 0}, 90});  // straight down
    Scene far = test::SceneBuilder()
                    .material("wall", test::diffuse(0.5))
                    .room({0, 0, 0}, {4, 4, 3}, "wall", "wall", "wall")
                    .box("building_opposite", {60, -20, 0}, {70, 30, 12}, "wall")
                    .build();
    test::TempDir dir;
    for (const Scene* s : {&scene, &far}) {
        const auto file = dir.path() / (s->cameras.empty() ? "far.glb" : "cameras.glb");
        writeGlb(file, *s, initialLayout(*s));
        const tinygltf::Model m = readGlb(file);
        ASSERT_EQ(m.cameras.size(), std::max<size_t>(s->cameras.size(), 1));
        for (const tinygltf::Camera& c : m.cameras) {
            EXPECT_EQ(c.type, "perspective") << c.name;
            EXPECT_GT(c.perspective.znear, 0) << c.name;
            EXPECT_GT(c.perspective.zfar, c.perspective.znear) << c.name;
            EXPECT_GT(c.perspective.yfov, 0) << c.name;
        }
        for (const tinygltf::Node& n : m.nodes) {
            if (n.camera < 0) continue;
            ASSERT_EQ(n.translation.size(), 3u) << n.name;
            const Vec3 eye = luxplanPoint(n.translation);
            const double zfar = m.cameras.at(size_t(n.camera)).perspective.zfar;
            // Every vertex of the file is nearer than the far plane.
            for (const tinygltf::Node& other : m.nodes) {
                if (other.mesh < 0 || !other.translation.empty() || !other.rotation.empty()) continue;  // world-frame meshes
                for (const tinygltf::Primitive& p : m.meshes.at(size_t(other.mesh)).primitives) {
                    const tinygltf::Accessor& pos = m.accessors.at(size_t(p.attributes.at("POSITION")));
                    for (int k = 0; k < 8; ++k) {
                        const std::vector<double> corner{(k & 1 ? pos.maxValues : pos.minValues)[0],
                                                         (k & 2 ? pos.maxValues : pos.minValues)[1],
                                                         (k & 4 ? pos.maxValues : pos.minValues)[2]};
                        EXPECT_LT(length(luxplanPoint(corner) - eye), zfar) << n.name << " / " << other.name;
                    }
                }
            }
        }
    }
    EXPECT_NEAR(cameraFar(Bounds3({0, 0, 0}, {3, 4, 0}), {0, 0, 0}), 10, 1e-12);   // at least 10 m
    EXPECT_NEAR(cameraFar(Bounds3({0, 0, 0}, {30, 40, 0}), {0, 0, 0}), 100, 1e-12);  // twice the farthest corner
    EXPECT_NEAR(cameraFar(Bounds3(), {0, 0, 0}), 10, 1e-12);                         // no geometry
}

// A scene without cameras gets one: render.png's default view, from inside the room;
// one with cameras gets those alone. The scene's extras give the room's inside.
TEST(Gltf, ASceneWithoutCamerasGetsTheDefaultViewFromInsideTheRoom) {
    auto e = exportScene();  // furnishedRoom: no cameras
    const tinygltf::Model& m = e->model;
    ASSERT_EQ(m.cameras.size(), 1u);
    EXPECT_EQ(m.cameras[0].name, kDefaultViewName);
    const tinygltf::Node* node = findNode(m, kDefaultViewName);
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(node->camera, 0);
    const Camera expected = defaultCamera(e->scene);
    const Vec3 eye = luxplanPoint(node->translation);
    EXPECT_NEAR(length(eye - expected.position), 0, 1e-9);
    EXPECT_TRUE(e->scene.room()->box.contains(eye));
    const Vec3 look = rotate(*node, Vec3(0, 0, -1));  // glTF frame
    const Vec3 want = normalize(expected.lookAt - expected.position);
    EXPECT_NEAR(length(luxplanPoint({look.x, look.y, look.z}) - want), 0, 1e-9);
    EXPECT_NEAR(m.cameras[0].perspective.yfov, radians(expected.fovDeg), 1e-12);
    // The first camera is the default one: the first node with a camera.
    for (const tinygltf::Node& n : m.nodes)
        if (n.camera >= 0) {
            EXPECT_EQ(n.name, kDefaultViewName);
            break;
        }

    // extras.room: the room's box (0..5, 0..4, 0..3) in glTF's frame.
    const tinygltf::Value& room = m.scenes.at(0).extras.Get("room");
    ASSERT_TRUE(room.IsObject());
    const tinygltf::Value &lo = room.Get("min"), &hi = room.Get("max");
    ASSERT_EQ(lo.ArrayLen(), 3u);
    ASSERT_EQ(hi.ArrayLen(), 3u);
    const double wantLo[3] = {0, 0, -4}, wantHi[3] = {5, 3, 0};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(lo.Get(i).GetNumberAsDouble(), wantLo[i], 1e-12) << i;
        EXPECT_NEAR(hi.Get(i).GetNumberAsDouble(), wantHi[i], 1e-12) << i;
    }

    // With cameras: those, no default view.
    Scene scene = test::furnishedRoom();
    scene.cameras.push_back({"door", "/cameras/0", {0.5, 3.5, 1.6}, {4, 1, 1}, 70});
    test::TempDir dir;
    writeGlb(dir.path() / "scene.glb", scene, initialLayout(scene));
    const tinygltf::Model withCamera = readGlb(dir.path() / "scene.glb");
    ASSERT_EQ(withCamera.cameras.size(), 1u);
    EXPECT_EQ(withCamera.cameras[0].name, "door");
    EXPECT_EQ(findNode(withCamera, kDefaultViewName), nullptr);
}

}  // namespace
}  // namespace luxplan
