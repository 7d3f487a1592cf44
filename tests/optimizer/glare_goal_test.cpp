// A glare goal drives the search. A bright lamp on a rail 1 m above eye height is in
// full view 2 m ahead of an eye (UGR about 21): the UGR goal [0, 19] alone moves it
// out of view. A chair faces a small window onto a bright sky: the DGP goal [0, 0.35]
// alone turns it away, and only because the window is a glare source (E_v alone
// would give a DGP within the target).
#include <cmath>

#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/glare_sources.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

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

OptimizerResult optimize(const Scene& scene, const DaylightEnvironment* daylight = nullptr) {
    MeasureOptions measure;
    measure.pathsPerPoint = 64, measure.seed = 3, measure.adaptive = true, measure.minPaths = 16;
    PathTracedLighting lighting(scene, daylight, measure);
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

// A black 6 x 4 m room with a 0.6 x 0.6 m east window onto a uniform sky of 50 000
// cd/m2 (about 0.04 sr from the chair, E_v about 2000 lx); the chair at the centre may
// face east (rotation 0, where it starts) or west.
Scene chairFacingAWindow(double thresholdNits) {
    OptimizerSettings settings;
    settings.iterations = 60;
    settings.seed = 5;
    settings.startFromScene = true;
    test::SceneBuilder b;
    b.material("black", test::diffuse(0))
        .uniformSky(50000)
        .room({0, 0, 0}, {6, 4, 3}, "black", "black", "black")
        .window(Wall::East, 1.7, 0.6, 0.9, 0.6)
        .entity("chair", {3, 2, 0}, 0).region({2.9, 1.9}, {3.1, 2.1}, {0, 180})
        .sampler("view", dgpSampler({0, 0, 1.2}, {1, 0, 0}, thresholdNits, 24), 0, 0.35).end();
    return b.lightingWeight(1).optimizer(settings).build();
}

TEST(GlareGoal, TheDgpGoalTurnsTheChairAwayFromTheWindow) {
    const Scene scene = chairFacingAWindow(2000);
    // Facing the window: the window's region of sky makes the glare, E_v alone does not.
    test::SceneLab facing(scene);
    const SamplerResult withSources = facing.measure(64).samplers[0];
    const SamplerResult evAlone = test::SceneLab(chairFacingAWindow(1e9)).measure(64).samplers[0];
    EXPECT_GT(withSources.value, 0.36) << "DGP " << withSources.value << ", E_v alone " << evAlone.value;
    EXPECT_LT(evAlone.value, 0.32);

    const OptimizerResult r = optimize(scene, &*facing.daylight);
    EXPECT_GT(r.startEvaluation.lighting, 0);
    EXPECT_EQ(r.bestEvaluation.cost, 0);
    const double rotation = r.best.placements[size_t(scene.findEntity("chair"))].rotationDeg;
    EXPECT_NEAR(std::abs(std::remainder(rotation, 360.0)), 180, 1e-9) << "the chair faces " << rotation << " degrees";
}

// The search traces the glare surveys with the report's tracing (the sunlit patches),
// the other samplers with its own: a survey's E_v from few paths misses the light off
// a sunlit floor, with an error that does not show it, and its adaptive stops go wrong.
TEST(GlareGoal, TheSearchTracesGlareSurveysWithTheSunlitPatches) {
    const Scene scene = test::SceneBuilder()
                            .material("wall", test::diffuse(0.7))
                            .material("floor", test::diffuse(0.3))
                            .sunAndUniformSky({35, 160, 60000}, 2000, 0.2)
                            .room({0, 0, 0}, {6, 4, 3}, "floor", "wall", "wall")
                            .window(Wall::South, 1, 3, 0.9, 1.5)
                            .sampler("desk", planarSampler({3, 3, 0.8}, {0, 0, 1}, {0, 1, 0}, {1, 0.6}, {2, 2}), 0)
                            .sampler("beside the window", dgpSampler({3, 2, 1.2}, {1, 0, 0}, 2000, 8), 0, 0.35)
                            .build();
    PathTracerOptions search, report;
    search.sunPatches = false;
    const test::SceneLab with(scene, report), without(scene, search);
    const MeasureResult a = with.measure(64, 7), b = without.measure(64, 7);
    // The patches change the survey's paths (or this test could not fail).
    ASSERT_NE(a.samplers[1].value, b.samplers[1].value);

    MeasureOptions measure;
    measure.pathsPerPoint = 64, measure.seed = 7;
    PathTracedLighting lighting(scene, &*with.daylight, measure, search, report);
    const Layout layout = initialLayout(scene);
    lighting.evaluate(layout, worldTransforms(scene, layout), nullptr);
    const MeasureResult& r = lighting.lastMeasurement();
    EXPECT_EQ(r.samplers[0].value, b.samplers[0].value);
    EXPECT_EQ(r.samplers[1].value, a.samplers[1].value);
    EXPECT_EQ(r.samplers[1].standardError, a.samplers[1].standardError);
}

}  // namespace
}  // namespace luxplan
