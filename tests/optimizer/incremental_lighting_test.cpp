// The search with exact incremental re-evaluation (PathTracedLighting, whose path cache
// the chain commits on acceptance and reverts on refusal) runs the same chain as with
// every path traced for every layout: the same trace, the same best layout and costs.
#include <gtest/gtest.h>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::SceneBuilder;

Scene litStudy() {
    OptimizerSettings settings;
    settings.iterations = 150;
    settings.seed = 5;
    DaylightParams d;
    d.model = SkyModelType::Uniform;
    d.luminanceNits = 2000;
    d.sunOverride = SunOverride{40, 160, 40000};
    const Vec3 kZ(0, 0, 1);
    return SceneBuilder()
        .material("wall", test::diffuse(0.6))
        .material("wood", test::diffuse(0.4))
        .material("glass", test::glass(0.8))
        .daylight(d)
        .room({0, 0, 0}, {5, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 1, 2, 0.9, 1.4, "glass")
        .emitter("panel", rectEmitter({2.5, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
        .entity("desk", {2, 2.5, 0}).region({0.8, 0.5}, {4.2, 3.5}, {0, 90, 180, 270})
        .part({1.4, 0.7, 0.75}, "wood", Vec3(0, 0, 0.375))
        .sampler("task", planarSampler({0, 0, 0.76}, kZ, {0, 1, 0}, {1.2, 0.6}, {2, 2}), 500, 700, 100)
        .entity("lamp", {0.5, 0.2, 0.75}).part({0.1, 0.1, 0.4}, "wood", Vec3(0, 0, 0.2))
        .emitter("shade", diskEmitter({0, 0, 0.45}, {0, 0, -1}, 0.08), 400)
        .end()
        .end()
        .entity("cabinet", {4, 3.5, 0}).region({0.5, 0.3}, {4.5, 3.7}, {0, 180}).part({0.8, 0.4, 1.2}, "wood", Vec3(0, 0, 0.6)).end()
        .sampler("view", directionalSampler({2.5, 3.5, 1.2}, {0, -1, 0}, kZ, 60, 3), 0, 1500)
        .overlap(0.05)
        .lightingWeight(0.7)
        .optimizer(settings)
        .build();
}

TEST(IncrementalLighting, TheSearchIsTheSameWithAndWithoutThePathCache) {
    const Scene scene = litStudy();
    const DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    MeasureOptions measure;
    measure.pathsPerPoint = 48, measure.seed = 5, measure.adaptive = true, measure.minPaths = 16;
    OptimizerResult runs[2];
    uint64_t reused[2] = {};
    for (int incremental = 0; incremental < 2; ++incremental) {
        PathTracedLighting lighting(scene, &daylight, measure);
        lighting.setIncremental(incremental == 1);
        runs[incremental] = Optimizer(scene, optimizerOptions(scene), &lighting).run();
        reused[incremental] = lighting.reusedPaths();
    }
    const OptimizerResult &full = runs[0], &cached = runs[1];
    EXPECT_EQ(reused[0], 0u);
    EXPECT_GT(reused[1], 0u);
    ASSERT_EQ(full.trace.size(), cached.trace.size());
    for (size_t i = 0; i < full.trace.size(); ++i) {
        EXPECT_EQ(full.trace[i].current, cached.trace[i].current) << "row " << i;
        EXPECT_EQ(full.trace[i].best, cached.trace[i].best) << "row " << i;
    }
    EXPECT_EQ(full.bestIteration, cached.bestIteration);
    EXPECT_EQ(full.bestEvaluation.cost, cached.bestEvaluation.cost);
    EXPECT_EQ(full.bestEvaluation.lighting, cached.bestEvaluation.lighting);
    for (size_t e = 0; e < scene.entities.size(); ++e) {
        EXPECT_EQ(full.best.placements[e].position.x, cached.best.placements[e].position.x);
        EXPECT_EQ(full.best.placements[e].position.y, cached.best.placements[e].position.y);
        EXPECT_EQ(full.best.placements[e].rotationDeg, cached.best.placements[e].rotationDeg);
    }
    int64_t accepted = 0;
    for (const auto& level : full.levels)
        for (const MoveStats& m : level.moves) accepted += m.accepted;
    EXPECT_GT(accepted, 10);  // commits and reverts both happened
}

// Each move type counts the paths its proposals' light traced afresh: together, all
// the evaluator traced for the chain's proposals; none for proposals never lit; and the
// path cache shows there, fewer for the same chain.
TEST(IncrementalLighting, EachMoveCountsThePathsItsLightTraced) {
    const Scene scene = litStudy();
    const DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    MeasureOptions measure;
    measure.pathsPerPoint = 48, measure.seed = 5, measure.adaptive = true, measure.minPaths = 16;
    uint64_t traced[2] = {};
    for (int incremental = 0; incremental < 2; ++incremental) {
        PathTracedLighting lighting(scene, &daylight, measure);
        lighting.setIncremental(incremental == 1);
        OptimizerOptions o = optimizerOptions(scene);
        o.polishShare = 0;  // its start measures the best layout again, no move's paths
        Optimizer optimizer(scene, o, &lighting);
        optimizer.initialize();
        const uint64_t start = lighting.tracedPaths();
        for (int i = 0; i < 150; ++i) optimizer.step();
        for (const LevelStats& level : optimizer.levels())
            for (const MoveStats& m : level.moves) {
                traced[incremental] += m.pathsTraced;
                if (m.proposed - m.outside - m.rejectedGeometry - m.screened == 0) {
                    EXPECT_EQ(m.pathsTraced, 0u);
                }
            }
        EXPECT_EQ(traced[incremental], lighting.tracedPaths() - start);
    }
    EXPECT_GT(traced[1], 0u);
    EXPECT_LT(traced[1], traced[0]);
}

}  // namespace
}  // namespace luxplan
