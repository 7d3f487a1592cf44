// The optimizer loop on a small office: feasible results, the geometric gate in
// front of the lighting hook, determinism, cancellation, early stop at C = 0,
// progress, levels, and the report/trace/layout outputs.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/penalty.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/report.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

const char* kOffice = R"({
  "luxplan": 1,
  "name": "office",
  "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
  "geometry": [
    {"name": "room", "room": {"min": [0, 0, 0], "max": [6, 4, 3]}, "materials": {"floor": "m", "walls": "m", "ceiling": "m"}},
    {"name": "door", "box": {"min": [2.5, 0, 0], "max": [3.5, 1, 2]}, "invisible": true}
  ],
  "samplers": [{"name": "desk_light", "type": "planar", "center": [0, 0, 0.75], "size": [1, 1], "target": [300, 500]}],
  "entities": [
    {"name": "workstation", "position": [2, 2],
     "placement": {"regions": [{"min": [1, 1], "max": [5, 3], "rotations": [0, 90, 180, 270]}]},
     "children": [
       {"name": "desk", "parts": [{"box": {"size": [1.2, 0.6, 0.75]}, "material": "m"}],
        "children": [{"name": "monitor", "position": [0, 0.1, 0.75],
                      "placement": {"regions": [{"min": [-0.4, 0], "max": [0.4, 0.2], "rotation_range": [-20, 20]}]},
                      "parts": [{"box": {"size": [0.5, 0.15, 0.4]}, "material": "m"}]}]},
       {"name": "chair", "position": [0, -0.7], "rotation": 180,
        "placement": {"regions": [{"min": [-0.5, -1.0], "max": [0.5, -0.5], "rotation_range": [120, 240]}]},
        "parts": [{"box": {"size": [0.5, 0.5, 0.9]}, "material": "m"}]}]},
    {"name": "shelf", "position": [0.2, 3], "rotation": 90,
     "placement": {"regions": [{"min": [0.2, 1], "max": [0.2, 3.5], "rotations": [90]},
                               {"min": [5.8, 1], "max": [5.8, 3.5], "rotations": [270]}]},
     "parts": [{"box": {"size": [0.8, 0.3, 1.8]}, "material": "m"}]},
    {"name": "plant", "position": [5, 3.5],
     "placement": {"regions": [{"min": [0.4, 0.4], "max": [5.6, 3.6]}]},
     "parts": [{"box": {"size": [0.4, 0.4, 1.0]}, "material": "m"}]}
  ],
  "constraints": [
    {"type": "alignment", "a": "workstation.desk", "b": "room", "tolerance_deg": 5},
    {"type": "distance", "a": "workstation.desk", "b": "workstation.chair", "min": 0.5, "max": 0.9},
    {"type": "focus", "a": "workstation.chair", "b": "workstation.desk", "tolerance_deg": 20},
    {"type": "focus", "a": "workstation.desk.monitor", "b": "workstation.chair", "tolerance_deg": 15},
    {"type": "distance", "a": "plant", "b": "workstation", "min": 1.5, "max": 100}
  ],
  "objective": {"lighting_weight": 0.5},
  "optimizer": {"iterations": 3000, "seed": 3}
})";

// Desk illuminance falls off towards +x: E = 600 - 100 x lx, target [300, 500].
class DeskLight : public LightingEvaluator {
public:
    explicit DeskLight(const Scene& scene) : scene_(scene) {}
    double evaluate(const Layout&, const std::vector<Transform>& world, LightingBreakdown* out) override {
        ++calls;
        if (GeometryEvaluator(scene_).evaluate(world).rejected) ++rejectedCalls;
        double e = 600 - 100 * world[size_t(scene_.findEntity("workstation.desk"))].t.x;
        if (out) out->samplers = {{e, 0, {e, e}, {0, 0}}};
        return lightingCost(scene_, {e});
    }
    int calls = 0, rejectedCalls = 0;

private:
    const Scene& scene_;
};

class OptimizerTest : public ::testing::Test {
protected:
    void SetUp() override { scene = io::loadScene(dir.write("office.json", kOffice)); }
    test::TempDir dir;
    Scene scene;
};

TEST_F(OptimizerTest, FindsAFeasibleLayoutAndReportsConsistentCosts) {
    DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    EXPECT_EQ(o.iterations, 3000);
    EXPECT_EQ(o.seed, 3u);
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_TRUE(r.feasible);
    EXPECT_FALSE(r.bestEvaluation.rejected);
    EXPECT_LE(r.bestEvaluation.cost, r.startEvaluation.cost);
    EXPECT_LT(r.bestEvaluation.cost, 0.1) << reportJson(scene, r);
    // The best layout's costs are what a fresh evaluation gives.
    auto world = worldTransforms(scene, r.best);
    GeometryResult g = GeometryEvaluator(scene).evaluate(world);
    EXPECT_DOUBLE_EQ(g.cost, r.bestEvaluation.geometry);
    EXPECT_DOUBLE_EQ(r.bestEvaluation.cost, 0.5 * r.bestEvaluation.lighting + 0.5 * r.bestEvaluation.geometry);
    EXPECT_DOUBLE_EQ(r.bestGeometry.cost, g.cost);
    EXPECT_EQ(r.bestEvaluation.samplers.samplers.size(), 1u);
    for (const auto& t : r.bestGeometry.terms) EXPECT_FALSE(t.rejects) << describe(scene, t);
    // Every movable entity inside one of its regions.
    for (size_t e = 0; e < scene.entities.size(); ++e) {
        if (!scene.entities[e].movable()) continue;
        const Placement& p = r.best.placements[e];
        ASSERT_GE(p.region, 0);
        EXPECT_TRUE(regionContains(scene.entities[e].regions[p.region], {p.position.x, p.position.y}, p.rotationDeg));
    }
    // The trace never loses the best cost.
    for (size_t i = 1; i < r.trace.size(); ++i) {
        if (std::isfinite(r.trace[i - 1].best)) {
            EXPECT_LE(r.trace[i].best, r.trace[i - 1].best);
        }
        EXPECT_GT(r.trace[i].iteration, r.trace[i - 1].iteration);
    }
    EXPECT_EQ(r.trace.back().iteration, r.iterations);
}

TEST_F(OptimizerTest, LightingOnlyForLayoutsThatPassTheGeometricTest) {
    DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 1500;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_TRUE(r.startFeasible);
    EXPECT_EQ(light.rejectedCalls, 0);
    int64_t evaluatedFeasible = 0, rejected = 0;
    for (const auto& level : r.levels)
        for (const auto& m : level.moves) {
            evaluatedFeasible += m.proposed - m.outside - m.rejectedGeometry;
            rejected += m.rejectedGeometry;
        }
    EXPECT_GT(rejected, 0);  // the room is tight enough that some proposals collide
    EXPECT_EQ(light.calls, 1 + evaluatedFeasible + r.confirmations);
}

TEST_F(OptimizerTest, NoLightingHookMeansLZero) {
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 300;
    OptimizerResult r = Optimizer(scene, o).run();
    EXPECT_EQ(r.bestEvaluation.lighting, 0);
    EXPECT_FALSE(r.bestEvaluation.lightingEvaluated);
    EXPECT_DOUBLE_EQ(r.bestEvaluation.cost, 0.5 * r.bestEvaluation.geometry);
}

TEST_F(OptimizerTest, DeterministicForAFixedSeed) {
    auto run = [&](uint64_t seed) {
        DeskLight light(scene);
        OptimizerOptions o = optimizerOptions(scene);
        o.iterations = 800;
        o.seed = seed;
        o.traceEvery = 1;
        return Optimizer(scene, o, &light).run();
    };
    OptimizerResult a = run(5), b = run(5), c = run(6);
    ASSERT_EQ(a.trace.size(), b.trace.size());
    for (size_t i = 0; i < a.trace.size(); ++i) {
        EXPECT_EQ(a.trace[i].current, b.trace[i].current);
        EXPECT_EQ(a.trace[i].best, b.trace[i].best);
    }
    for (size_t e = 0; e < a.best.placements.size(); ++e) {
        EXPECT_EQ(a.best.placements[e].position, b.best.placements[e].position);
        EXPECT_EQ(a.best.placements[e].rotationDeg, b.best.placements[e].rotationDeg);
    }
    bool differs = false;
    for (size_t i = 0; i < std::min(a.trace.size(), c.trace.size()); ++i) differs = differs || a.trace[i].current != c.trace[i].current;
    EXPECT_TRUE(differs);
}

TEST_F(OptimizerTest, InitializeRestartsTheSameChain) {
    OptimizerOptions o = optimizerOptions(scene);
    Optimizer chain(scene, o);
    auto walk = [&] {
        chain.initialize();
        for (int i = 0; i < 200; ++i) chain.step();
        return chain.current();
    };
    Layout a = walk(), b = walk();
    for (size_t e = 0; e < a.placements.size(); ++e) {
        EXPECT_EQ(a.placements[e].position, b.placements[e].position);
        EXPECT_EQ(a.placements[e].rotationDeg, b.placements[e].rotationDeg);
    }
    EXPECT_EQ(chain.iteration(), 200);
}

TEST_F(OptimizerTest, LevelsAndInnerIterations) {
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 1000;
    o.stopAtZeroCost = false;
    OptimizerResult r = Optimizer(scene, o).run();
    ASSERT_EQ(r.levels.size(), 2u);
    EXPECT_EQ(r.levels[0].name, "group");
    EXPECT_EQ(r.levels[0].entities, (std::vector<int>{scene.findEntity("workstation"), scene.findEntity("shelf"),
                                                      scene.findEntity("plant")}));
    EXPECT_EQ(r.levels[1].name, "object");
    EXPECT_EQ(r.levels[1].entities, (std::vector<int>{scene.findEntity("workstation.desk.monitor"),
                                                      scene.findEntity("workstation.chair")}));
    auto proposals = [](const LevelStats& l) {
        int64_t n = 0;
        for (const auto& m : l.moves) n += m.proposed;
        return n;
    };
    EXPECT_EQ(proposals(r.levels[0]), 200);  // one group-level proposal per 1 + 4 iterations
    EXPECT_EQ(proposals(r.levels[1]), 800);
    o.hierarchy = Hierarchy::Flat;
    r = Optimizer(scene, o).run();
    ASSERT_EQ(r.levels.size(), 1u);
    EXPECT_EQ(r.levels[0].name, "flat");
    EXPECT_EQ(r.levels[0].entities.size(), 5u);
    EXPECT_EQ(proposals(r.levels[0]), 1000);
}

TEST_F(OptimizerTest, CancellationKeepsTheBestLayout) {
    DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.progressEvery = 100;
    o.stopAtZeroCost = false;
    std::atomic<bool> cancel{false};
    std::vector<int> seen;
    OptimizerResult r = Optimizer(scene, o, &light).run(
        [&](const Progress& p) {
            seen.push_back(p.iteration);
            EXPECT_GE(p.etaSeconds, 0);
            for (double a : p.acceptance) EXPECT_TRUE(a >= 0 && a <= 1);
            if (p.iteration >= 500) cancel = true;
        },
        &cancel);
    EXPECT_EQ(r.stop, StopReason::Cancelled);
    EXPECT_EQ(r.iterations, 500);
    EXPECT_EQ(seen, (std::vector<int>{100, 200, 300, 400, 500}));
    EXPECT_TRUE(r.feasible);
    EXPECT_LE(r.bestEvaluation.cost, r.startEvaluation.cost);

    cancel = true;  // cancelled before the first iteration
    r = Optimizer(scene, o, &light).run({}, &cancel);
    EXPECT_EQ(r.stop, StopReason::Cancelled);
    EXPECT_EQ(r.iterations, 0);
}

TEST(OptimizerStop, StopsAtZeroCost) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", R"({
      "luxplan": 1,
      "entities": [
        {"name": "a", "position": [0, 0], "placement": {"regions": [{"min": [0, 0], "max": [4, 4]}]}},
        {"name": "b", "position": [9, 9], "placement": {"regions": [{"min": [0, 0], "max": [4, 4]}]}}],
      "constraints": [{"type": "distance", "a": "a", "b": "b", "min": 0.5, "max": 1.0}]})"));
    OptimizerOptions o;
    o.iterations = 20000;
    o.start = StartFrom::Scene;  // 12.7 m apart: rejected, repaired, then solved
    OptimizerResult r = Optimizer(s, o).run();
    EXPECT_EQ(r.stop, StopReason::ZeroCost);
    EXPECT_FALSE(r.startFeasible);
    EXPECT_TRUE(r.feasible);
    EXPECT_EQ(r.bestEvaluation.cost, 0);
    EXPECT_LT(r.iterations, 20000);
    EXPECT_EQ(r.bestIteration, r.iterations);
}

// A lighting estimate that always says 0 while a more accurate measurement says
// `truth`: the run stops at C = 0 only once the measurement confirms it.
class OptimisticLight : public LightingEvaluator {
public:
    explicit OptimisticLight(double truth) : truth_(truth) {}
    double evaluate(const Layout&, const std::vector<Transform>&, LightingBreakdown*) override { return 0; }
    double confirm(const Layout&, const std::vector<Transform>&, LightingBreakdown*) override {
        ++confirms;
        return truth_;
    }
    int confirms = 0;

private:
    double truth_;
};

TEST(OptimizerStop, ZeroCostIsConfirmedBeforeStopping) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", R"({
      "luxplan": 1,
      "samplers": [{"name": "s", "type": "planar", "center": [2, 2, 1], "size": [1, 1], "target": [100, 200]}],
      "entities": [
        {"name": "a", "position": [0, 0], "placement": {"regions": [{"min": [0, 0], "max": [4, 4]}]}},
        {"name": "b", "position": [1, 0], "placement": {"regions": [{"min": [0, 0], "max": [4, 4]}]}}],
      "constraints": [{"type": "distance", "a": "a", "b": "b", "min": 0.5, "max": 1.5}]})"));
    OptimizerOptions o;
    o.iterations = 500;
    o.start = StartFrom::Scene;  // feasible, G = 0: the estimate says C = 0 at once
    OptimisticLight wrong(0.4);
    OptimizerResult r = Optimizer(s, o, &wrong).run();
    EXPECT_EQ(r.stop, StopReason::Iterations);
    EXPECT_GE(r.confirmations, 1);
    EXPECT_EQ(r.confirmations, wrong.confirms);
    EXPECT_DOUBLE_EQ(r.bestEvaluation.lighting, 0.4);  // the confirmed value, not the estimate
    EXPECT_DOUBLE_EQ(r.bestEvaluation.cost, 0.2);

    OptimisticLight right(0.0);
    r = Optimizer(s, o, &right).run();
    EXPECT_EQ(r.stop, StopReason::ZeroCost);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.confirmations, 1);
}

TEST(OptimizerStop, NothingToMove) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", R"({"luxplan": 1, "entities": [{"name": "a", "position": [1, 1]}]})"));
    OptimizerResult r = Optimizer(s, OptimizerOptions()).run();
    EXPECT_EQ(r.stop, StopReason::NothingToMove);
    EXPECT_EQ(r.iterations, 0);
}

TEST(OptimizerStart, RepairsAnInfeasibleStart) {
    // Four 1 m cubes in a 2.2 m square room: a uniform draw almost always collides.
    test::TempDir dir;
    std::string entities;
    for (int i = 0; i < 4; ++i)
        entities += std::string(i ? "," : "") + R"({"name": "box)" + std::to_string(i) +
                    R"(", "position": [1, 1], "placement": {"regions": [{"min": [0.5, 0.5], "max": [1.7, 1.7]}]},
                       "parts": [{"box": {"size": [1, 1, 1]}, "material": "m"}]})";
    Scene s = io::loadScene(dir.write("scene.json", R"({"luxplan": 1,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [2.2, 2.2, 2]}, "materials": {"floor": "m", "walls": "m", "ceiling": "m"}}],
      "entities": [)" + entities + "]}"));
    OptimizerOptions o;
    o.iterations = 4000;
    o.startAttempts = 1;
    o.seed = 2;
    OptimizerResult r = Optimizer(s, o).run();
    EXPECT_FALSE(r.startFeasible);
    EXPECT_TRUE(r.feasible);
    EXPECT_FALSE(GeometryEvaluator(s).evaluate(worldTransforms(s, r.best)).rejected);
}

TEST_F(OptimizerTest, WritesLayoutReportAndTrace) {
    DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 500;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    auto out = dir.path() / "out";
    writeOptimizerOutputs(out, scene, r);
    io::writeLayout(out / "layout.json", scene, r.best);

    auto report = nlohmann::json::parse(std::ifstream(out / "report.json"));
    EXPECT_EQ(report["scene"], "office");
    EXPECT_DOUBLE_EQ(report["C"].get<double>(), r.bestEvaluation.cost);
    EXPECT_DOUBLE_EQ(report["L"].get<double>(), r.bestEvaluation.lighting);
    EXPECT_DOUBLE_EQ(report["G"].get<double>(), r.bestEvaluation.geometry);
    EXPECT_EQ(report["iterations"], r.iterations);
    EXPECT_TRUE(report["seconds"].is_number());
    ASSERT_EQ(report["constraints"].size(), 5u);
    EXPECT_EQ(report["constraints"][0]["type"], "alignment");
    EXPECT_EQ(report["constraints"][0]["b"], "room");
    EXPECT_EQ(report["constraints"][0]["unit"], "deg");
    EXPECT_EQ(report["constraints"][3]["a"], "workstation.desk.monitor");
    EXPECT_EQ(report["constraints"][4]["range"][1], 100);
    EXPECT_TRUE(report["constraints"][1]["penalty"].is_number());
    EXPECT_TRUE(report["overlap"]["pairs"].is_array());
    ASSERT_EQ(report["samplers"].size(), 1u);
    EXPECT_EQ(report["samplers"][0]["name"], "desk_light");
    EXPECT_EQ(report["samplers"][0]["unit"], "lx");
    EXPECT_EQ(report["samplers"][0]["target"][0], 300);
    int64_t proposed = 0;
    for (const char* m : {"translate", "rotate", "swap", "jump"}) proposed += report["moves"][m]["proposed"].get<int64_t>();
    EXPECT_EQ(proposed, r.iterations);
    EXPECT_EQ(report["levels"].size(), 2u);
    EXPECT_EQ(report["settings"]["seed"], 3);

    std::ifstream trace(out / "trace.csv");
    std::string header, line;
    std::getline(trace, header);
    EXPECT_EQ(header, "iteration,current,best,feasible");
    int rows = 0;
    while (std::getline(trace, line)) ++rows;
    EXPECT_EQ(rows, int(r.trace.size()));

    Layout back = io::readLayout(out / "layout.json", scene);
    for (size_t e = 0; e < scene.entities.size(); ++e) {
        EXPECT_NEAR(back.placements[e].position.x, r.best.placements[e].position.x, 1e-12);
        EXPECT_NEAR(back.placements[e].rotationDeg, r.best.placements[e].rotationDeg, 1e-12);
    }
}

}  // namespace
}  // namespace luxplan
