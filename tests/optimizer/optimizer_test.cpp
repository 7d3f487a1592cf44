// The optimizer loop on a small office: feasible results, the geometric gate in
// front of the lighting hook, determinism, cancellation, early stop at C = 0,
// progress, levels, and the report and trace outputs (tests/roundtrip reads the
// layout back from layout.json).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/report.h>
#include "support/desk_light.h"
#include "support/scene_builder.h"
#include "support/shared_scenes.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

class OptimizerTest : public ::testing::Test {
protected:
    test::TempDir dir;
    Scene scene = test::optimizerOffice();
};

TEST_F(OptimizerTest, FindsAFeasibleLayoutAndReportsConsistentCosts) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    EXPECT_EQ(o.iterations, 3000);
    EXPECT_EQ(o.seed, 3u);
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_TRUE(r.feasible);
    EXPECT_FALSE(r.bestEvaluation.rejected);
    EXPECT_LE(r.bestEvaluation.cost, r.startEvaluation.cost);
    EXPECT_LT(r.bestEvaluation.cost, 0.1) << reportJson(scene, r, RunSettings::object());
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
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 1500;
    o.stopAtZeroCost = false;  // every iteration, whenever C reaches 0
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_TRUE(r.startFeasible);
    EXPECT_EQ(light.rejectedCalls, 0);
    int64_t evaluatedFeasible = 0, rejected = 0, screened = 0;
    for (const auto& level : r.levels)
        for (const auto& m : level.moves) {
            evaluatedFeasible += m.proposed - m.outside - m.rejectedGeometry - m.screened;
            rejected += m.rejectedGeometry;
            screened += m.screened;
        }
    EXPECT_GT(rejected, 0);  // the room is tight enough that some proposals collide
    EXPECT_GT(screened, 0);  // delayed acceptance: some fail on their rules' change alone
    // The confirmations, the candidates' re-measures and the report's are the rest, and
    // each polish's measurement of the best it starts from: one per restart cycle (450,
    // 450 and 600 iterations at restartShare 0.3).
    EXPECT_EQ(r.polishFrom, 1380);
    EXPECT_EQ(light.calls, 1 + evaluatedFeasible + r.independentMeasurements + 3);
}

TEST_F(OptimizerTest, NoLightingHookMeansLZero) {
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 300;
    OptimizerResult r = Optimizer(scene, o).run();
    EXPECT_EQ(r.bestEvaluation.lighting, 0);
    EXPECT_FALSE(r.bestEvaluation.lightingEvaluated);
    EXPECT_DOUBLE_EQ(r.bestEvaluation.cost, 0.5 * r.bestEvaluation.geometry);
    // report.json's report_measurement is there for scripts, null: no light was measured.
    const nlohmann::json j = nlohmann::json::parse(reportJson(scene, r, RunSettings::object()));
    EXPECT_TRUE(j["report_measurement"]["seed"].is_null()) << j["report_measurement"];
    EXPECT_TRUE(j["report_measurement"]["paths_per_point"].is_null());
    EXPECT_TRUE(j["L"].is_null());  // the scene has samplers, but nothing measured them
}

TEST_F(OptimizerTest, DeterministicForAFixedSeed) {
    auto run = [&](uint64_t seed) {
        test::DeskLight light(scene);
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

// Snapshots: the best layout so far at iterations ceil(n (k/N)^2), each the state the
// trace shows there (an early stop's own snapshot: OptimizerStop.StopsAtZeroCost).
TEST_F(OptimizerTest, SnapshotsHoldTheBestSoFarAtTheirCheckpoints) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 800;
    o.traceEvery = 1;
    o.snapshots = 4;
    o.stopAtZeroCost = false;
    const OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_EQ(r.snapshots.size(), 4u);
    const std::vector<int> at = {50, 200, 450, 800};  // 800 (k/4)^2
    for (size_t k = 0; k < at.size(); ++k) {
        const Snapshot& s = r.snapshots[k];
        EXPECT_EQ(s.iteration, at[k]);
        EXPECT_EQ(s.searchCost, r.trace[size_t(at[k])].best) << "at " << at[k];  // trace row i is iteration i
        EXPECT_EQ(s.feasible, std::isfinite(s.searchCost));
        if (k == 0) continue;
        EXPECT_GE(s.seconds, r.snapshots[k - 1].seconds);
        EXPECT_GE(s.lightingEvaluations, r.snapshots[k - 1].lightingEvaluations);
        EXPECT_LE(s.searchCost, r.snapshots[k - 1].searchCost);
    }
    // The last one's lighting evaluations are the run's.
    EXPECT_EQ(r.snapshots.back().lightingEvaluations, r.lightingEvaluations);
    EXPECT_GT(r.lightingEvaluations, 0);
    // Without snapshots asked for, none.
    o.snapshots = 0;
    EXPECT_TRUE(Optimizer(scene, o, &light).run().snapshots.empty());
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
    o.polishShare = 0;  // the polish's own level: OptimizerTest.ThePolish...
    // By default (0) the levels' degrees of freedom set the cycle: the object level's
    // (a monitor's x, y and turn, a chair's x and y: 5) over the group level's (5).
    OptimizerResult byDof = Optimizer(scene, o).run();
    o.innerIterations = 4;
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
    EXPECT_EQ(proposals(byDof.levels[0]), 500);
    EXPECT_EQ(proposals(byDof.levels[1]), 500);
    o.hierarchy = Hierarchy::Flat;
    r = Optimizer(scene, o).run();
    ASSERT_EQ(r.levels.size(), 1u);
    EXPECT_EQ(r.levels[0].name, "flat");
    EXPECT_EQ(r.levels[0].entities.size(), 5u);
    EXPECT_EQ(proposals(r.levels[0]), 1000);
}

TEST_F(OptimizerTest, CancellationKeepsTheBestLayout) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.progressEvery = 100;
    o.stopAtZeroCost = false;
    std::atomic<bool> cancel{false};
    std::vector<int> seen;
    OptimizerResult r = Optimizer(scene, o, &light).run(
        [&](const Progress& p) {
            seen.push_back(p.iteration);
            // The time left: the time per iteration so far times the iterations left.
            EXPECT_DOUBLE_EQ(p.etaSeconds, p.seconds / p.iteration * (p.iterations - p.iteration));
            EXPECT_GT(p.etaSeconds, 0);  // 2500 iterations and more to go
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
    Scene s = test::SceneBuilder()
                  .entity("a").region({0, 0}, {4, 4}).end()
                  .entity("b", {9, 9, 0}).region({0, 0}, {4, 4}).end()
                  .constraint(distanceConstraint({0.5, 1.0, std::nullopt}), "a", "b")
                  .build();
    OptimizerOptions o;
    o.iterations = 20000;
    o.snapshots = 3;
    o.start = StartFrom::Scene;  // 12.7 m apart: rejected, repaired, then solved
    OptimizerResult r = Optimizer(s, o).run();
    // The early stop leaves a snapshot of its own, the solved layout.
    ASSERT_FALSE(r.snapshots.empty());
    EXPECT_EQ(r.snapshots.back().iteration, r.iterations);
    EXPECT_EQ(r.snapshots.back().searchCost, 0);
    EXPECT_EQ(r.snapshots.back().lightingEvaluations, 0);
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
    double measureIndependently(const Layout&, const std::vector<Transform>&, LightingBreakdown*, uint64_t,
                                IndependentUse) override {
        ++confirms;
        return truth_;
    }
    int confirms = 0;

private:
    double truth_;
};

TEST(OptimizerStop, ZeroCostIsConfirmedBeforeStopping) {
    Scene s = test::SceneBuilder()
                  .sampler("s", planarSampler({2, 2, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 100, 200)
                  .entity("a").region({0, 0}, {4, 4}).end()
                  .entity("b", {1, 0, 0}).region({0, 0}, {4, 4}).end()
                  .constraint(distanceConstraint({0.5, 1.5, std::nullopt}), "a", "b")
                  .build();
    OptimizerOptions o;
    o.iterations = 500;
    o.start = StartFrom::Scene;  // feasible, G = 0: the estimate says C = 0 at once
    OptimisticLight wrong(0.4);
    OptimizerResult r = Optimizer(s, o, &wrong).run();
    EXPECT_EQ(r.stop, StopReason::Iterations);
    EXPECT_GE(r.confirmations, 1);
    // Every confirmation, then the final choice's and the report's measurements.
    EXPECT_EQ(r.independentMeasurements, wrong.confirms);
    EXPECT_GT(r.independentMeasurements, r.confirmations);
    EXPECT_DOUBLE_EQ(r.bestEvaluation.lighting, 0.4);  // the confirmed value, not the estimate
    EXPECT_DOUBLE_EQ(r.bestEvaluation.cost, 0.2);

    OptimisticLight right(0.0);
    r = Optimizer(s, o, &right).run();
    EXPECT_EQ(r.stop, StopReason::ZeroCost);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.confirmations, 1);
}

TEST(OptimizerStop, NothingToMove) {
    Scene s = test::SceneBuilder().entity("a", {1, 1, 0}).end().build();
    OptimizerResult r = Optimizer(s, OptimizerOptions()).run();
    EXPECT_EQ(r.stop, StopReason::NothingToMove);
    EXPECT_EQ(r.iterations, 0);
}

TEST(OptimizerStart, RepairsAnInfeasibleStart) {
    // Four 1 m cubes in a 2.2 m square room: a uniform draw almost always collides.
    test::SceneBuilder b;
    b.material("m", test::diffuse(0.5)).room({0, 0, 0}, {2.2, 2.2, 2}, "m", "m", "m");
    for (int i = 0; i < 4; ++i)
        b.entity("box" + std::to_string(i), {1, 1, 0}).region({0.5, 0.5}, {1.7, 1.7}).part({1, 1, 1}, "m").end();
    Scene s = b.build();
    OptimizerOptions o;
    o.iterations = 4000;
    o.startAttempts = 1;
    o.seed = 2;
    OptimizerResult r = Optimizer(s, o).run();
    EXPECT_FALSE(r.startFeasible);
    EXPECT_TRUE(r.feasible);
    EXPECT_FALSE(GeometryEvaluator(s).evaluate(worldTransforms(s, r.best)).rejected);
}

// A desk that cannot fit (7 m long in a 6 x 4 m room): no layout passes the geometric
// rules, so the report gives no C and no G (null, and what rejects it), but the light of
// the least violating layout, which layout.json holds. It once said C = L = G = 0 with
// no samplers.
TEST(OptimizerStart, AnInfeasibleResultHasNoCostButItsLight) {
    Scene s = test::SceneBuilder()
                  .material("m", test::diffuse(0.5))
                  .room({0, 0, 0}, {6, 4, 3}, "m", "m", "m")
                  .sampler("desk_light", planarSampler({0, 0, 0.75}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2}), 300, 500)
                  .entity("workstation", {3, 2, 0}).region({1, 1}, {5, 3}, {0, 90})
                  .entity("desk").part({7, 0.6, 0.75}, "m").end()
                  .end()
                  .lightingWeight(0.5)
                  .build();
    test::DeskLight light(s);
    OptimizerOptions o = optimizerOptions(s);
    o.iterations = 20;
    o.startAttempts = 3;
    OptimizerResult r = Optimizer(s, o, &light).run();
    ASSERT_FALSE(r.feasible);
    const nlohmann::json j = nlohmann::json::parse(reportJson(s, r, RunSettings::object()));
    EXPECT_TRUE(j["C"].is_null()) << j["C"];
    EXPECT_TRUE(j["G"].is_null()) << j["G"];
    EXPECT_TRUE(j["C_std_error"].is_null());
    EXPECT_EQ(j["feasible"], false);
    EXPECT_NE(j["rejected_by"].get<std::string>().find("overlap \"workstation.desk\""), std::string::npos) << j["rejected_by"];
    const double x = worldTransforms(s, r.best)[size_t(s.findEntity("workstation.desk"))].t.x, lux = 600 - 100 * x;
    EXPECT_DOUBLE_EQ(j["L"].get<double>(), lightingCost(s, {lux}));
    ASSERT_EQ(j["samplers"].size(), 1u);
    EXPECT_DOUBLE_EQ(j["samplers"][0]["value"].get<double>(), lux);
    EXPECT_TRUE(j["start"]["C"].is_null());
    EXPECT_TRUE(j["start"]["L"].is_null());  // the start's light was never measured
}

TEST_F(OptimizerTest, WritesReportAndTrace) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 500;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    auto out = dir.path() / "out";
    const RunSettings settings = {{"seed", 3}, {"polish_share", 0.2}};  // as the command passes them
    writeOptimizerOutputs(out, scene, r, settings);

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
    EXPECT_EQ(report["samplers"][0]["description"], scene.samplers[0].type->describe());
    EXPECT_EQ(report["samplers"][0]["target"][0], 300);
    int64_t proposed = 0;
    // Every iteration is one proposal of the group or object level, or of the polish
    // after polish_from; the polish's level also holds the snaps tried before a zero is
    // confirmed (one per turning entity, not iterations).
    auto levelProposals = [&](size_t l) {
        int64_t n = 0;
        for (auto& [name, m] : report["levels"][l]["moves"].items()) n += m["proposed"].get<int64_t>();
        return n;
    };
    ASSERT_GE(report["levels"].size(), 2u);
    const int64_t polished = r.polishFrom < r.iterations ? r.iterations - r.polishFrom : 0;
    proposed = levelProposals(0) + levelProposals(1);
    EXPECT_EQ(proposed + polished, r.iterations);
    if (report["levels"].size() == 3u) {
        EXPECT_EQ(report["levels"][2]["name"], "polish");
        EXPECT_GE(levelProposals(2), polished);
    } else {
        EXPECT_EQ(report["levels"].size(), 2u);
    }
    EXPECT_EQ(report["settings"], settings);
    EXPECT_EQ(report["polish_from"], r.polishFrom);

    std::ifstream trace(out / "trace.csv");
    std::string header, line;
    std::getline(trace, header);
    EXPECT_EQ(header, "iteration,current,best,feasible,temperature,acceptance");
    int rows = 0;
    while (std::getline(trace, line)) ++rows;
    EXPECT_EQ(rows, int(r.trace.size()));
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// The polish: the last share of the run starts from the best layout and never lets
// the current cost rise (zero temperature), its proposals are counted in a level of
// their own, and its temperature in the trace is 0. The rules-only search (no light)
// reaches it too.
TEST_F(OptimizerTest, ThePolishDescendsFromTheBestAndNeverRises) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.stopAtZeroCost = false;
    o.iterations = 2000;
    o.polishShare = 0.25;
    o.restartShare = 0;  // one cycle: the polish ends the run
    o.traceEvery = 1;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_TRUE(r.feasible);
    EXPECT_EQ(r.polishFrom, 1500);
    ASSERT_EQ(r.levels.back().name, "polish");
    int64_t proposed = 0;
    for (const MoveStats& m : r.levels.back().moves) proposed += m.proposed;
    EXPECT_EQ(proposed, 500);
    EXPECT_EQ(r.levels.back().moves[int(MoveType::Swap)].proposed, 0);  // translate, rotate and snap only
    EXPECT_EQ(r.levels.back().moves[int(MoveType::Guided)].proposed, 0);
    double before = kInf;
    for (const TracePoint& t : r.trace) {
        if (t.iteration <= 1500) {
            if (t.iteration > 0) {
                EXPECT_GT(t.temperature, 0);
            }
            continue;
        }
        EXPECT_EQ(t.temperature, 0);
        EXPECT_LE(t.current, before + 1e-15) << "iteration " << t.iteration;
        EXPECT_GE(t.current, t.best);
        before = t.current;
    }
    // The polish starts at the best of the chain before it, and ends at the best.
    EXPECT_LE(r.trace.back().current, r.trace[1500].best);
    EXPECT_DOUBLE_EQ(r.trace.back().current, r.trace.back().best);
}

// Restarts: cycles of 30% of the run (600 of 2000; the last takes the 800 left), each
// cooling to its own polish (its last 25%), each later one warm again from the
// polished best at the restart temperature.
TEST_F(OptimizerTest, RestartsWarmTheChainAgainFromThePolishedBest) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.stopAtZeroCost = false;
    o.iterations = 2000;
    o.polishShare = 0.25;
    o.restartShare = 0.3;
    o.restartTemperature = 0.02;
    o.traceEvery = 1;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_TRUE(r.feasible);
    EXPECT_EQ(r.polishFrom, 1800);  // the last cycle's polish
    ASSERT_EQ(r.trace.size(), 2001u);
    auto polishing = [](int i) { return (i > 450 && i <= 600) || (i > 1050 && i <= 1200) || i > 1800; };
    double before = kInf;
    for (const TracePoint& t : r.trace) {
        if (t.iteration == 0) continue;
        if (!polishing(t.iteration)) {
            EXPECT_GT(t.temperature, 0) << "iteration " << t.iteration;
            before = kInf;
            continue;
        }
        EXPECT_EQ(t.temperature, 0) << "iteration " << t.iteration;
        EXPECT_LE(t.current, before + 1e-15) << "iteration " << t.iteration;
        before = t.current;
    }
    EXPECT_NEAR(r.trace[1].temperature, 0.1, 0.002);  // the first cycle from the schedule's start
    for (auto [start, cooling] : {std::pair{600, 450}, std::pair{1200, 600}}) {
        // The polish ended at the best; the next cycle starts there, warm again.
        EXPECT_DOUBLE_EQ(r.trace[size_t(start)].current, r.trace[size_t(start)].best) << start;
        EXPECT_NEAR(r.trace[size_t(start) + 1].temperature, 0.02, 0.0005) << start;
        EXPECT_NEAR(r.trace[size_t(start + cooling)].temperature, 0.001, 1e-4) << start;  // cooled to the end
    }
}

// A constant schedule is a plain chain: no polish (the chain tests sample its law).
TEST_F(OptimizerTest, AConstantScheduleHasNoPolish) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.stopAtZeroCost = false;
    o.iterations = 400;
    o.schedule.kind = Schedule::Kind::Constant;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    EXPECT_NE(r.levels.back().name, "polish");
    EXPECT_EQ(r.polishFrom, 400);
}

// Suggestions at the optimizer's level: distinct, the result first, each measured.
TEST_F(OptimizerTest, SuggestionsAreDistinctAndTheResultComesFirst) {
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.stopAtZeroCost = false;
    o.iterations = 1500;
    o.suggestions = 3;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_FALSE(r.suggestions.empty());
    ASSERT_LE(r.suggestions.size(), 3u);
    for (size_t e = 0; e < scene.entities.size(); ++e) {
        EXPECT_EQ(r.suggestions[0].layout.placements[e].position, r.best.placements[e].position);
    }
    for (size_t i = 0; i < r.suggestions.size(); ++i) {
        ASSERT_TRUE(r.suggestions[i].independent.has_value());
        if (i >= 2) {
            EXPECT_GE(r.suggestions[i].independent->cost, r.suggestions[i - 1].independent->cost);
        }
        for (size_t j = i + 1; j < r.suggestions.size(); ++j)
            EXPECT_FALSE(sameCandidate(scene, r.suggestions[i].layout, r.suggestions[j].layout, o.suggestionSeparation));
    }
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// C from the group's place on its rail alone: 0.1 |x - 7.3| (its least at one point, so
// that small steps keep taking cost off); the member's moves change nothing.
class RailLight : public LightingEvaluator {
public:
    double evaluate(const Layout&, const std::vector<Transform>& world, LightingBreakdown* out) override {
        const double v = 0.1 * std::abs(world[0].t.x - 7.3);
        if (out) out->samplers = {{v, 0, {}, {}}};
        return v;
    }
};

// The adaptive share: the object level's moves take no cost off, so after their first
// 50 lit proposals they get the least share, 10%, not the two thirds their degrees of
// freedom give them (the member's x and y against the group's x). A constant schedule (a plain
// chain) keeps the fixed cycle, as does the option off.
TEST(AdaptiveShare, TheLevelsShareFollowsWhatTheirProposalsYield) {
    test::SceneBuilder b;
    b.material("m", test::diffuse(0.5)).lightingWeight(1);
    b.sampler("s", planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2}), 0, 0, 1.0);
    b.entity("g", {1, 1, 0}).region({0, 1}, {10, 1}).part({0.5, 0.5, 0.5}, "m")
        .entity("c", {0, 0, 0}).region({-1, -1}, {1, 1}).part({0.1, 0.1, 0.1}, "m", Vec3(0, 0, 1)).end()
        .end();
    const Scene scene = b.build();
    auto objectShare = [&](bool adaptive, Schedule::Kind kind) {
        RailLight light;
        OptimizerOptions o;
        o.iterations = 3000;
        o.stopAtZeroCost = false;
        o.polishShare = 0;
        o.adaptiveShare = adaptive;
        o.schedule.kind = kind;
        OptimizerResult r = Optimizer(scene, o, &light).run();
        EXPECT_EQ(r.levels.size(), 2u);
        int64_t group = 0, object = 0;
        for (const MoveStats& m : r.levels[0].moves) group += m.proposed;
        for (const MoveStats& m : r.levels[1].moves) object += m.proposed;
        return double(object) / double(group + object);
    };
    EXPECT_NEAR(objectShare(false, Schedule::Kind::Geometric), 2.0 / 3.0, 1e-9);  // 2 degrees of freedom to 1
    EXPECT_LT(objectShare(true, Schedule::Kind::Geometric), 0.2);
    EXPECT_NEAR(objectShare(true, Schedule::Kind::Constant), 2.0 / 3.0, 1e-9);
}

}  // namespace
}  // namespace luxplan
