// Cameras: the scene's "cameras" and render's --camera, --eye, --target and --fov.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "run_cli.h"
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

namespace fs = std::filesystem;
const std::string kOpenPlan = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/open-plan.json";
const std::string kFast = " --width 48 --height 32 --spp 1 --paths 1 --cell 2 --cell-paths 1 --threads 2";

std::string bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::string render(const std::string& view, test::TempDir& dir, const std::string& name) {
    const fs::path out = dir.path() / name;
    test::CliResult r = test::runCli("render " + kOpenPlan + " -o " + out.string() + kFast + " " + view);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return bytes(out / "render.png");
}

TEST(Cameras, RenderFromASceneCameraOrTheSameViewGivenOnTheCommandLine) {
    test::TempDir dir;
    const std::string fromDefault = render("", dir, "default");
    const std::string fromDoor = render("--camera door", dir, "door");
    const std::string fromArgs = render("--eye 0.6,6.1,1.6 --target 6,2,0.9 --fov 70", dir, "args");
    ASSERT_FALSE(fromDoor.empty());
    EXPECT_NE(fromDoor, fromDefault);
    EXPECT_EQ(fromDoor, fromArgs);
    EXPECT_NE(render("--camera door --fov 30", dir, "narrow"), fromDoor);
    EXPECT_FALSE(render("--camera above", dir, "above").empty());  // looking straight down
}

// glTF is y-up: luxplan's (x, y, z) is (x, z, -y) there; a camera looks down its -z.
TEST(Cameras, TheGlbHoldsTheScenesCameras) {
    test::TempDir dir;
    render("", dir, "glb");
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, (dir.path() / "glb" / "scene.glb").string())) << err;
    ASSERT_EQ(model.cameras.size(), 2u);
    const tinygltf::Node* door = nullptr;
    for (const auto& n : model.nodes)
        if (n.name == "door") door = &n;
    ASSERT_NE(door, nullptr);
    ASSERT_GE(door->camera, 0);
    const tinygltf::Camera& camera = model.cameras[size_t(door->camera)];
    EXPECT_EQ(camera.type, "perspective");
    EXPECT_NEAR(camera.perspective.yfov, 70 * M_PI / 180, 1e-9);
    ASSERT_EQ(door->translation.size(), 3u);
    EXPECT_NEAR(door->translation[0], 0.6, 1e-9);
    EXPECT_NEAR(door->translation[1], 1.6, 1e-9);
    EXPECT_NEAR(door->translation[2], -6.1, 1e-9);
    // The camera's -z, rotated by the node's quaternion, points at the target.
    ASSERT_EQ(door->rotation.size(), 4u);
    const double x = door->rotation[0], y = door->rotation[1], z = door->rotation[2], w = door->rotation[3];
    const double look[3] = {-(2 * (x * z + w * y)), -(2 * (y * z - w * x)), -(1 - 2 * (x * x + y * y))};
    const double want[3] = {6 - 0.6, 0.9 - 1.6, -(2 - 6.1)};
    const double norm = std::sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(look[i], want[i] / norm, 1e-6) << i;
}

TEST(Cameras, CommandLineMistakesAreRefused) {
    test::TempDir dir;
    const std::string out = " -o " + (dir.path() / "x").string() + kFast;
    test::CliResult r = test::runCli("render " + kOpenPlan + out + " --camera dor");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(kOpenPlan + ": /: --camera: unknown camera \"dor\" (did you mean \"door\"?) (door or above)"),
              std::string::npos)
        << r.output;
    r = test::runCli("render " + kOpenPlan + out + " --eye 1,1,1 --target 1,1,1");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--target is the same point as --eye"), std::string::npos) << r.output;
    r = test::runCli("render " + kOpenPlan + out + " --eye 1,1");
    EXPECT_NE(r.exitCode, 0);
    r = test::runCli("render " + kOpenPlan + out + " --eye 1,1,1");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--target"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir.path() / "x" / "render.png"));
}

TEST(Cameras, SceneCamerasAreCheckedWithTheirPath) {
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(kOpenPlan));
    auto problems = [&] {
        test::TempDir dir;
        return test::loadProblems(scene.dump(), dir);
    };
    scene["cameras"][1]["target"] = scene["cameras"][1]["eye"];
    EXPECT_EQ(problems(), std::vector<std::string>{"/cameras/1/target: the camera's target is its eye: it looks nowhere"});
    scene["cameras"][1] = scene["cameras"][0];
    EXPECT_EQ(problems(), std::vector<std::string>{"/cameras/1/name: duplicate camera name \"door\" (also at /cameras/0)"});
    scene["cameras"][1] = {{"name", "c"}, {"eye", {1, 1, 1}}, {"target", {2, 2, 1}}, {"fov_deg", 180}};
    EXPECT_EQ(problems(), std::vector<std::string>{"/cameras/1/fov_deg: value 180 outside (0, 180) deg"});
    scene["cameras"][1] = {{"name", "c"}, {"target", {2, 2, 1}}, {"lens", 50}};
    auto p = problems();
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0], "/cameras/1: missing required key \"eye\"");
    EXPECT_EQ(p[1].rfind("/cameras/1/lens: unknown key \"lens\"", 0), 0u) << p[1];
}

}  // namespace
}  // namespace luxplan
