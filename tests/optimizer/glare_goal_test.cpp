// A glare goal drives the search: a bright lamp on a rail 1 m above eye height is in
// full view 2 m ahead of an eye (UGR about 21, DGP of a dim room); the UGR goal
// [0, 19] alone, or the DGP goal, moves it out of view.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/glare_sources.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

Scene lampInView(std::shared_ptr<const SamplerType> sampler, double targetMax) {
    OptimizerSettings settings;
    settings.iterations = 300;
    settings.seed = 3;
    settings.startFromScene = true;
    test::SceneBuilder b;
    b.uniformSky(100)
        .entity("lamp", {2, 0, 0}).region({-2, 0}, {2, 0}).emitter("bulb", sphereEmitter({0, 0, 1}, 0.05), 2000).end()
        .sampler("eye", sampler, 0, targetMax);
    return b.lightingWeight(1).optimizer(settings).build();
}

OptimizerResult optimize(const Scene& scene) {
    MeasureOptions measure;
    measure.pathsPerPoint = 64, measure.seed = 3, measure.adaptive = true;
    PathTracedLighting lighting(scene, nullptr, measure);
    return Optimizer(scene, optimizerOptions(scene), &lighting).run();
}

TEST(GlareGoal, TheUgrGoalMovesTheLampOutOfView) {
    const Scene scene = lampInView(ugrSampler({0, 0, 0}, {1, 0, 0}), 19);
    const OptimizerResult r = optimize(scene);
    EXPECT_GT(r.startEvaluation.lighting, 0);
    EXPECT_EQ(r.bestEvaluation.cost, 0);
    const double x = r.best.placements[size_t(scene.findEntity("lamp"))].position.x;
    EXPECT_LT(x, 1.5) << "the lamp stopped at x = " << x;
}

}  // namespace
}  // namespace luxplan
