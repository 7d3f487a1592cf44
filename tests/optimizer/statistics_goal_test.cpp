// A statistics goal drives the search: a lamp on a rail 2 m above a 2 x 2 m table
// lights it well enough anywhere (the mean's target is met along the whole rail),
// but only near the table's centre is the light uniform enough for U0 >= 0.75
// (closed form: U0 = 0.81 centred, 0.74 at 0.2 m, 0.54 at 1.2 m). From 1.2 m the
// U0 goal alone brings the lamp over the table; without it the search has nothing
// to do.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/constraints/penalty.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::SceneBuilder;

Scene lampOverTable(bool uniformityGoal) {
    OptimizerSettings settings;
    settings.iterations = 400;
    settings.seed = 3;
    settings.startFromScene = true;
    SceneBuilder b;
    b.entity("lamp", {1.2, 0, 0}).region({-1.5, 0}, {1.5, 0}).emitter("bulb", sphereEmitter({0, 0, 2.75}, 0.01), 2000).end()
        .sampler("table", planarSampler({0, 0, 0.75}, {0, 0, 1}, {0, 1, 0}, {2, 2}, {5, 5}), 10);  // E_m is 20 to 32 lx
    if (uniformityGoal) b.statistic(Statistic::U0, 0.75, 1, 0.1);
    return b.lightingWeight(1).optimizer(settings).build();
}

OptimizerResult optimize(const Scene& scene) {
    MeasureOptions measure;
    measure.pathsPerPoint = 32, measure.seed = 3, measure.adaptive = true, measure.minPaths = 16;
    PathTracedLighting lighting(scene, nullptr, measure);
    return Optimizer(scene, optimizerOptions(scene), &lighting).run();
}

TEST(StatisticsGoal, OnlyTheU0GoalMovesTheLampOverTheTable) {
    const Scene scene = lampOverTable(true);
    const OptimizerResult r = optimize(scene);
    EXPECT_GT(r.startEvaluation.lighting, 0.5);  // U0 = 0.54 at the start: (0.75 - 0.54) / 0.1 over two terms
    EXPECT_EQ(r.stop, StopReason::ZeroCost);
    EXPECT_EQ(r.bestEvaluation.cost, 0);
    const double x = r.best.placements[size_t(scene.findEntity("lamp"))].position.x;
    EXPECT_LT(std::abs(x), 0.3) << "the lamp stopped at x = " << x;
    const std::vector<LightingTerm> terms = lightingTerms(scene.samplers[0], r.bestEvaluation.samplers.samplers[0]);
    ASSERT_EQ(terms.size(), 2u);
    EXPECT_GE(terms[1].value, 0.75);

    const Scene free = lampOverTable(false);
    const OptimizerResult still = optimize(free);
    EXPECT_EQ(still.startEvaluation.cost, 0);  // the mean's target is met where the lamp starts
    EXPECT_EQ(still.stop, StopReason::ZeroCost);
    EXPECT_EQ(still.best.placements[size_t(free.findEntity("lamp"))].position.x, 1.2);
}

}  // namespace
}  // namespace luxplan
