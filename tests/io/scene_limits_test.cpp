// Scenes and layouts that once crashed, hung, exhausted memory or were wrongly
// accepted (issue 15): each limit of core/limits.h refused as FILE: /json/path: message.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <set>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include <luxplan/core/error.h>
#include <luxplan/core/limits.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/scene/layout.h>
#include "support/small_room.h"
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

json smallScene() {
    return json::parse(test::smallRoomScene("", 0));
}

using test::onlyProblem;

TEST(SceneLimits, DeepChildrenAreRefusedQuickly) {
    // 10^4 levels of children (a 330 kB file) once took 2.8 GB and overflowed the stack.
    std::string text = R"({"luxplan": 1, "entities": [)";
    const int depth = 10000;
    for (int i = 0; i < depth; ++i) text += R"({"name": "e", "children": [)";
    for (int i = 0; i < depth; ++i) text += "]}";
    text += "]}";
    test::TempDir dir;
    auto start = std::chrono::steady_clock::now();
    auto p = test::loadProblems(text, dir);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NE(p[0].find("exceeds the limit of " + std::to_string(limits::kMaxJsonDepth)), std::string::npos) << p[0];
    EXPECT_EQ(p[0].rfind("/entities/0/children/0/children/0/", 0), 0u) << p[0].substr(0, 200);
}

TEST(SceneLimits, EntityNestingDepth) {
    json s = smallScene();
    json leaf = {{"name", "e"}};
    for (int i = 0; i < limits::kMaxEntityDepth; ++i) leaf = {{"name", "e"}, {"children", {leaf}}};
    s["entities"].push_back(leaf);  // 33 levels
    std::string path = "/entities/1";
    for (int i = 1; i < limits::kMaxEntityDepth; ++i) path += "/children/0";
    EXPECT_EQ(onlyProblem(s), path + "/children: entities nested 33 deep exceed the limit of 32");
    // 32 levels load.
    s = smallScene();
    s["entities"].push_back(leaf["children"][0]);
    test::TempDir dir;
    EXPECT_TRUE(test::loadProblems(s.dump(), dir).empty());
}

TEST(SceneLimits, CoordinatesAndSizesAreBounded) {
    json s = smallScene();
    s["geometry"][0]["room"]["max"][0] = 1e308;
    EXPECT_EQ(onlyProblem(s), "/geometry/0/room/max/0: value 1e+308 exceeds the limit of 100000 m");
    s = smallScene();
    s["entities"][0]["position"][0] = 1e9;
    EXPECT_EQ(onlyProblem(s), "/entities/0/position/0: value 1000000000 exceeds the limit of 100000 m");
    s = smallScene();
    s["entities"][0]["parts"][0]["box"]["size"][2] = 1e308;
    EXPECT_EQ(onlyProblem(s), "/entities/0/parts/0/box/size/2: value 1e+308 exceeds the limit of 100000 m");
    s = smallScene();
    s["entities"][0]["placement"]["regions"][0]["max"][1] = -1e9;
    EXPECT_EQ(onlyProblem(s), "/entities/0/placement/regions/0/max/1: value -1000000000 exceeds the limit of -100000 m");
    s = smallScene();
    s["luminaires"][0]["center"][2] = 1e300;
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/center/2: value 1e+300 exceeds the limit of 100000 m");
    s = smallScene();
    s["luminaires"][0]["size"][0] = 1e300;
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/size/0: value 1e+300 exceeds the limit of 100000 m");
    s = smallScene();
    s["luminaires"][0]["flux_lm"] = 1e300;
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/flux_lm: value 1e+300 exceeds the limit of 1000000000");
    s = smallScene();
    s["samplers"][0]["center"][0] = 1e9;
    EXPECT_EQ(onlyProblem(s), "/samplers/0/center/0: value 1000000000 exceeds the limit of 100000 m");
    s = smallScene();
    s["samplers"][0]["size"][0] = 1e9;
    EXPECT_EQ(onlyProblem(s), "/samplers/0/size/0: value 1000000000 exceeds the limit of 100000 m");
}

// Issue 58: a rule weight of 1e308 made the cost C infinite. Every factor that
// multiplies or divides a penalty is bounded (limits.h), each refused at its key.
TEST(SceneLimits, CostFactorsAreBounded) {
    json s = smallScene();
    s["samplers"][0]["weight"] = 1e308;
    EXPECT_EQ(onlyProblem(s), "/samplers/0/weight: value 1e+308 exceeds the limit of 1000000");
    s = smallScene();
    s["samplers"][0]["target"] = {300, 1e308};
    EXPECT_EQ(onlyProblem(s), "/samplers/0/target/1: value 1e+308 exceeds the limit of 1e+10 lx");
    s = smallScene();
    s["samplers"][0]["tolerance"] = 1e-300;
    EXPECT_EQ(onlyProblem(s), "/samplers/0/tolerance: value 1e-300 outside >= 1e-06 lx");
    s["samplers"][0]["tolerance"] = 1e300;
    EXPECT_EQ(onlyProblem(s), "/samplers/0/tolerance: value 1e+300 exceeds the limit of 1e+10 lx");
    s = smallScene();
    s["samplers"][0]["statistics"] = {{"min", {{"target", {1e11, nullptr}}}}};
    EXPECT_EQ(onlyProblem(s), "/samplers/0/statistics/min/target/0: value 1e+11 exceeds the limit of 1e+10 lx");
    s["samplers"][0]["statistics"] = {{"u0", {{"target", {0.6, 1}}, {"tolerance", 1e-9}}}};
    EXPECT_EQ(onlyProblem(s), "/samplers/0/statistics/u0/tolerance: value 1e-09 outside >= 1e-06");
    s = smallScene();
    s["constraints"] = {{{"type", "overlap"}, {"weight", 1e308}}};
    EXPECT_EQ(onlyProblem(s), "/constraints/0/weight: value 1e+308 exceeds the limit of 1000000");
    s["constraints"] = {{{"type", "overlap"}, {"tolerance", 1e-300}}};
    EXPECT_EQ(onlyProblem(s), "/constraints/0/tolerance: value 1e-300 outside [1e-06, 1]");
    s["constraints"] = {{{"type", "alignment"}, {"a", "desk"}, {"b", "room"}, {"weight", 2e6}}};
    EXPECT_EQ(onlyProblem(s), "/constraints/0/weight: value 2000000 exceeds the limit of 1000000");
    s["constraints"] = {{{"type", "alignment"}, {"a", "desk"}, {"b", "room"}, {"tolerance_deg", 1e-300}}};
    EXPECT_EQ(onlyProblem(s), "/constraints/0/tolerance_deg: value 1e-300 outside [0.001, 180] deg");
    json desk2 = s["entities"][0];
    desk2["name"] = "desk2";
    s["entities"].push_back(desk2);
    s["constraints"] = {{{"type", "distance"}, {"a", "desk"}, {"b", "desk2"}, {"min", 1e308}, {"max", nullptr}}};
    EXPECT_EQ(onlyProblem(s), "/constraints/0/min: value 1e+308 exceeds the limit of 100000");
    s["constraints"] = {{{"type", "distance"}, {"a", "desk"}, {"b", "desk2"}, {"min", 1}, {"max", 2}, {"tolerance", 1e-300}}};
    EXPECT_EQ(onlyProblem(s), "/constraints/0/tolerance: value 1e-300 outside >= 1e-06 m");
}

// At the bounds, the worst a finite input can do stays far below overflow.
TEST(SceneLimits, TheCostAtTheBoundsIsFinite) {
    json s = smallScene();
    s["samplers"][0]["weight"] = limits::kMaxWeight;
    s["samplers"][0]["target"] = {limits::kMaxTargetValue, limits::kMaxTargetValue};
    s["samplers"][0]["tolerance"] = limits::kMinTolerance;
    json desk2 = s["entities"][0];
    desk2["name"] = "desk2";
    desk2["position"] = {4, 2};
    s["entities"].push_back(desk2);
    s["constraints"] = {{{"type", "distance"}, {"a", "desk"}, {"b", "desk2"}, {"min", limits::kMaxLength}, {"max", nullptr},
                         {"tolerance", limits::kMinTolerance}, {"weight", limits::kMaxWeight}},
                        {{"type", "alignment"}, {"a", "desk"}, {"b", "room"}, {"tolerance_deg", limits::kMinToleranceDeg},
                         {"weight", limits::kMaxWeight}},
                        {{"type", "overlap"}, {"tolerance", limits::kMinOverlapTolerance}, {"weight", limits::kMaxWeight}}};
    test::TempDir dir;
    const Scene scene = io::loadScene(dir.write("s.json", s.dump()));
    for (double value : {0.0, 1e17}) {
        const double lighting = lightingCost(scene, {value});
        EXPECT_TRUE(std::isfinite(lighting)) << value;
        EXPECT_GT(lighting, 1e15) << value;
    }
    GeometryEvaluator geometry(scene);
    Layout layout = initialLayout(scene);
    for (double x : {2.0, 4.0}) {  // apart, then one inside the other
        layout.placements[1].position.x = x;
        const GeometryResult g = geometry.evaluate(worldTransforms(scene, layout));
        EXPECT_TRUE(std::isfinite(g.cost)) << x;
        EXPECT_TRUE(std::isfinite(scene.objective.cost(lightingCost(scene, {0.0}), g.cost))) << x;
    }
}

TEST(SceneLimits, HugeDirectionsStayDirections) {
    json s = smallScene();
    s["luminaires"][0]["normal"] = {0, 0, -1e308};  // its length overflows
    test::TempDir dir;
    EXPECT_TRUE(test::loadProblems(s.dump(), dir).empty());
    Scene scene = io::loadScene(dir.write("n.json", s.dump()));
    ASSERT_TRUE(scene.emitters[0].shape->normal());
    EXPECT_NEAR(scene.emitters[0].shape->normal()->z, -1, 1e-12);
}

TEST(SceneLimits, MeshVerticesAfterTheirTransform) {
    test::TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1000 0 0\nv 0 1 0\nf 1 2 3\n");
    json s = smallScene();
    s["geometry"].push_back({{"name", "m"}, {"mesh", "tri.obj"}, {"material", "wall"}, {"transform", {{"scale", 1000}}}});
    auto p = test::loadProblems(s.dump(), dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0], "/geometry/1/mesh: mesh vertex (1000000, 0, 0) after its transform lies outside [-100000, 100000] m");
    s["geometry"][1]["transform"]["scale"] = 1e300;
    p = test::loadProblems(s.dump(), dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0], "/geometry/1/transform/scale: value 1e+300 exceeds the limit of 10000");
}

TEST(SceneLimits, MeshErrorsNameTheSceneAndTheMeshLine) {
    test::TempDir dir;
    auto obj = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
    json s = smallScene();
    s["geometry"].push_back({{"name", "m"}, {"mesh", "bad.obj"}, {"material", "wall"}});
    auto p = test::loadProblems(s.dump(), dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/geometry/1/mesh: cannot read mesh: " + obj.string() + ":4: face vertex index 99 is out of range", 0), 0u)
        << p[0];
}

TEST(SceneLimits, NumbersBeyondADouble) {
    test::TempDir dir;
    std::string text = smallScene().dump();
    text.replace(text.find("3200"), 4, "1e400");
    auto p = test::loadProblems(text, dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0], "/luminaires/0/flux_lm: number overflow parsing '1e400' (the largest number is about 1.8e308)");
    p = test::loadProblems(R"({"luxplan": 1, "entities": [{"name": "a", "position": [1, -1e400]}]})", dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/entities/0/position/1: number overflow parsing '-1e400'", 0), 0u) << p[0];
}

TEST(SceneLimits, IntegersAndSeeds) {
    json s = smallScene();
    s["optimizer"] = {{"paths_per_point", 2147483648LL}};
    EXPECT_EQ(onlyProblem(s), "/optimizer/paths_per_point: value 2147483648 exceeds the limit of 2147483647");
    s["optimizer"] = {{"iterations", 1e300}};
    EXPECT_EQ(onlyProblem(s), "/optimizer/iterations: expected an integer, got 1e+300");
    // Seeds above 2^31 stay distinct (they once all became one).
    test::TempDir dir;
    std::set<uint64_t> seeds;
    for (uint64_t seed : {2147483648ull, 2147483649ull, 4294967296ull, 18446744073709551615ull}) {
        s["optimizer"] = {{"seed", seed}};
        seeds.insert(io::loadScene(dir.write("s.json", s.dump())).optimizer.seed);
    }
    EXPECT_EQ(seeds.size(), 4u);
    EXPECT_TRUE(seeds.count(18446744073709551615ull));
    s["optimizer"] = {{"seed", -1}};
    EXPECT_EQ(onlyProblem(s), "/optimizer/seed: value -1 outside [0, 18446744073709551615]");
    s["optimizer"] = {{"seed", 1e30}};
    EXPECT_EQ(onlyProblem(s).rfind("/optimizer/seed: expected a whole number in [0, 2^64 - 1], got 1e+30", 0), 0u);
}

TEST(SceneLimits, HierarchySchedule) {
    json s = smallScene();
    test::TempDir dir;
    s["optimizer"] = {{"inner_iterations", 0}, {"nested", true}};
    const Scene scene = io::loadScene(dir.write("s.json", s.dump()));
    EXPECT_EQ(scene.optimizer.innerIterations, 0);  // by degrees of freedom
    EXPECT_TRUE(scene.optimizer.nested);
    s["optimizer"] = {{"inner_iterations", -1}};
    EXPECT_EQ(onlyProblem(s), "/optimizer/inner_iterations: value -1 outside [0, 1000]");
    s["optimizer"] = {{"nested", "yes"}};
    EXPECT_EQ(onlyProblem(s).rfind("/optimizer/nested: ", 0), 0u) << onlyProblem(s);
}

TEST(SceneLimits, TinyTimeStep) {
    json s = smallScene();
    s["site"] = {{"latitude", 38}, {"longitude", 23.7}};
    s["daylight"] = {{"sky", {{"model", "preetham"}}},
                     {"from", "2026-06-21T09:00+03:00"}, {"to", "2026-06-21T12:00+03:00"}, {"step_minutes", 1e-20}};
    EXPECT_EQ(onlyProblem(s), "/daylight/step_minutes: from..to every 1e-20 minutes is 1.8e+22 time steps, which exceeds "
                              "the limit of 10000");
}

TEST(SceneLimits, SamplerPoints) {
    json s = smallScene();
    s["samplers"][0]["grid"] = {1024, 1024};
    EXPECT_EQ(onlyProblem(s), "/samplers/0/grid: 1048576 points exceeds the limit of 65536");
    s = smallScene();
    s["samplers"].push_back({{"name", "v"}, {"type", "volume"}, {"center", {3, 2, 1}},
                             {"axes", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {"points", 1000000}, {"target", {0, 100}}});
    EXPECT_EQ(onlyProblem(s), "/samplers/1/points: 1000000 points exceeds the limit of 65536");
    s = smallScene();
    s["samplers"].push_back({{"name", "d"}, {"type", "directional"}, {"origin", {3, 1, 1.2}}, {"direction", {0, 1, 0}},
                             {"strata", 256}, {"target", {0, 100}}});
    EXPECT_EQ(onlyProblem(s), "/samplers/1/strata: strata 256 (65536 strata) exceeds the limit of 32");
}

// A glare eye surveys each luminaire (and a DGP eye each sun disk) with six estimates of
// its own: at most 1024 sources, counted in the file (the sun disks of the steps with the
// sun up: 10:00-22:00 in Athens on 21 June, sunset about 20:50, every 0.5 minutes).
TEST(SceneLimits, GlareSources) {
    json s = smallScene();
    for (int k = 1; k < 1024; ++k) {
        json l = s["luminaires"][0];
        l["name"] = "panel" + std::to_string(k);
        s["luminaires"].push_back(l);
    }
    s["samplers"].push_back({{"name", "u"}, {"type", "ugr"}, {"origin", {3, 1, 1.2}}, {"direction", {0, 1, 0}}, {"target", {0, 19}}});
    {
        test::TempDir dir;
        EXPECT_TRUE(test::loadProblems(s.dump(), dir).empty());  // 1024 luminaires
    }
    s["luminaires"].push_back(s["luminaires"][0]);
    s["luminaires"].back()["name"] = "panel1024";
    EXPECT_EQ(onlyProblem(s), "/samplers/1: a ugr sampler surveys each luminaire as a glare source of its own: 1025 luminaires "
                              "exceed the limit of 1024");
    s = smallScene();
    s["site"] = {{"latitude", 37.98}, {"longitude", 23.73}};
    s["daylight"] = {{"sky", {{"model", "preetham"}}},
                     {"from", "2026-06-21T10:00+03:00"}, {"to", "2026-06-21T22:00+03:00"}, {"step_minutes", 0.5}};
    s["samplers"].push_back({{"name", "g"}, {"type", "dgp"}, {"origin", {3, 1, 1.2}}, {"direction", {0, 1, 0}}, {"target", {0, 0.35}}});
    const std::string p = onlyProblem(s);
    EXPECT_EQ(p.rfind("/samplers/1: a dgp sampler surveys each luminaire and sun disk as a glare source of its own: 1 luminaire "
                      "and ", 0), 0u) << p;
    EXPECT_NE(p.find(" sun disks (one per daylight step with the sun up) exceed the limit of 1024; a longer \"step_minutes\" "
                     "or a shorter period has fewer"), std::string::npos) << p;
    s["daylight"]["step_minutes"] = 1;  // about 650 disks
    test::TempDir dir;
    EXPECT_TRUE(test::loadProblems(s.dump(), dir).empty());
}

// A luminaire's light sampling loses its precision far below a tenth of a millimetre
// (a 1e-8 m rect read 1131, 0, 1371 and 0 lx where a point source gives 33, 71, 71 and
// 33; a sphere of 1e-8 m, nothing): its sides and radius are at least 0.1 mm.
TEST(SceneLimits, LuminairesTooSmallToSample) {
    json s = smallScene();
    s["luminaires"][0]["size"] = {1e-12, 0.02};
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/size/0: value 1e-12 outside >= 0.0001 m");
    s = smallScene();
    s["luminaires"][0] = {{"name", "bulb"}, {"shape", "sphere"}, {"center", {3, 2, 2}}, {"radius", 1e-8}, {"flux_lm", 1000}};
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/radius: value 1e-08 outside >= 0.0001 m");
    s["luminaires"][0]["radius"] = 1e-4;
    test::TempDir dir;
    EXPECT_TRUE(test::loadProblems(s.dump(), dir).empty());
}

TEST(SceneLimits, OnlyRegularFilesOfBoundedSize) {
    test::TempDir dir;
    auto fifo = dir.path() / "scene.json";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    try {
        io::loadScene(fifo);
        ADD_FAILURE() << "a FIFO loaded";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), fifo.string() + ": /: not a regular file (a folder, FIFO or device cannot be read)");
    }
    try {
        io::loadScene("/dev/zero");
        ADD_FAILURE() << "/dev/zero loaded";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "/dev/zero: /: not a regular file (a folder, FIFO or device cannot be read)");
    }
    // A mesh named in the scene that is a FIFO.
    ASSERT_EQ(mkfifo((dir.path() / "pipe.obj").c_str(), 0600), 0);
    json s = smallScene();
    s["geometry"].push_back({{"name", "m"}, {"mesh", "pipe.obj"}, {"material", "wall"}});
    auto p = test::loadProblems(s.dump(), dir, "with_fifo.json");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0], "/geometry/1/mesh: cannot read mesh \"" + (dir.path() / "pipe.obj").string() +
                        "\": not a regular file (a folder, FIFO or device cannot be read)");
}

// Found by luxplan_fuzz: rotations had no bound (an entity's, a region's, a transform's).
TEST(SceneLimits, RotationsAreBounded) {
    json s = smallScene();
    s["entities"][0]["rotation"] = -1e308;
    EXPECT_EQ(onlyProblem(s), "/entities/0/rotation: value -1e+308 exceeds the limit of -3600 deg");
    s = smallScene();
    s["entities"][0]["placement"]["regions"][0]["rotations"] = {0, 1e300};
    EXPECT_EQ(onlyProblem(s), "/entities/0/placement/regions/0/rotations/1: value 1e+300 exceeds the limit of 3600 deg");
    s = smallScene();
    s["entities"][0]["placement"]["regions"][0].erase("rotations");
    s["entities"][0]["placement"]["regions"][0]["rotation_range"] = {0, 1e6};
    EXPECT_EQ(onlyProblem(s), "/entities/0/placement/regions/0/rotation_range/1: value 1000000 exceeds the limit of 3600 deg");
    s = smallScene();
    s["entities"][0]["placement"]["regions"][0]["rotation_range"] = {-3600, 3600};
    s["entities"][0]["placement"]["regions"][0].erase("rotations");
    test::TempDir dir;
    EXPECT_TRUE(test::loadProblems(s.dump(), dir).empty());
}

TEST(LayoutLimits, PositionsAndNumbers) {
    test::TempDir dir;
    Scene scene = io::loadScene(dir.write("scene.json", smallScene().dump()));
    auto layoutProblem = [&](const std::string& text) {
        auto file = dir.write("layout.json", text);
        try {
            io::readLayout(file, scene);
        } catch (const SceneError& e) {
            EXPECT_EQ(e.diagnostics().size(), 1u) << e.what();
            EXPECT_EQ(e.diagnostics().front().file, file.string());
            return e.diagnostics().front().jsonPath + ": " + e.diagnostics().front().message;
        }
        ADD_FAILURE() << "accepted " << text;
        return std::string();
    };
    EXPECT_EQ(layoutProblem(R"({"entities": {"desk": {"position": [1e9, 2, 0]}}})"),
              "/entities/desk/position/0: value 1000000000 exceeds the limit of 100000 m");
    EXPECT_EQ(layoutProblem(R"({"entities": {"desk": {"position": [2, 2, 1e400]}}})"),
              "/entities/desk/position/2: number overflow parsing '1e400' (the largest number is about 1.8e308)");
    EXPECT_EQ(layoutProblem(R"({"entities": {"desk": {"rotation": 0, "rotation": 90}}})"),
              "/entities/desk/rotation: duplicate key (JSON objects need unique keys)");
    // Found by luxplan_fuzz (tests/fuzz/regressions/wrong-accept-layout.rotation-range-*):
    // a rotation of 1e300 degrees was accepted.
    EXPECT_EQ(layoutProblem(R"({"entities": {"desk": {"position": [2, 2, 0], "rotation": 1e300}}})"),
              "/entities/desk/rotation: value 1e+300 exceeds the limit of 3600 deg");
    auto fifo = dir.path() / "fifo.json";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    try {
        io::readLayout(fifo, scene);
        ADD_FAILURE() << "a FIFO layout loaded";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), fifo.string() + ": /: not a regular file (a folder, FIFO or device cannot be read)");
    }
}

}  // namespace
}  // namespace luxplan
