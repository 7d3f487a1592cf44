// The path tracer with and without the sunlit patches (pathtracer/sun_patches.h): the
// strategy only adds a way to find the same light, weighed by MIS against the BSDF ways,
// so every estimate stays where it was; where the light comes off the patches, with
// less noise.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/lightsamplers/light_samplers.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;

// A sunlit office-like room: light walls and ceiling, a mid-grey floor, a desk in the
// sun's patch, a translucent screen. The strategy only adds a way to find the same light,
// so with and without it the estimates agree; where the light comes off the patches
// (an upward plane in the back, a wall point), it has less noise.
TEST(SunPatches, LeaveEveryEstimateAsItWasWithLessNoise) {
    Material translucent = test::diffuse(0.3);
    translucent.type = MaterialType::Translucent;
    translucent.diffuseTransmittance = Vec3(0.3, 0.3, 0.3);
    const Scene scene = SceneBuilder()
                            .material("wall", test::diffuse(0.7))
                            .material("ceiling", test::diffuse(0.8))
                            .material("floor", test::diffuse(0.3))
                            .material("glass", test::glass(0.8))
                            .material("translucent", translucent)
                            .sunAndUniformSky({35, 160, 60000}, 2000, 0.2)
                            .room({0, 0, 0}, {6, 4, 3}, "floor", "wall", "ceiling")
                            .window(Wall::South, 1, 3, 0.9, 1.5, "glass")
                            .box("desk", {2, 1.2, 0.7}, {3.2, 2, 0.75}, "wall")
                            .box("screen", {4, 2.5, 0}, {4.05, 3.5, 1.6}, "translucent")
                            .sampler("back", planarSampler({3, 3.3, 0.8}, {0, 0, 1}, {0, 1, 0}, {2, 0.6}, {4, 2}), 0)
                            .sampler("wall", planarSampler({1, 3.99, 1.5}, {0, -1, 0}, {0, 0, 1}, {0.1, 0.1}, {1, 1}), 0)
                            .sampler("desk", planarSampler({2.6, 1.6, 0.76}, {0, 0, 1}, {0, 1, 0}, {1, 0.6}, {2, 2}), 0)
                            // In the desk's shadow: lit by its underside, which the sunlit
                            // floor 0.7 m below lights (a connection that must not meet
                            // the floor it connects to).
                            .sampler("under", planarSampler({2.6, 1.6, 0.01}, {0, 0, 1}, {0, 1, 0}, {0.6, 0.3}, {2, 1}), 0)
                            .build();
    PathTracerOptions without;
    without.sunPatches = false;
    SceneLab with(scene), plain(scene, without);
    const MeasureResult a = with.measure(6000), b = plain.measure(6000);
    for (size_t k = 0; k < a.samplers.size(); ++k) {
        const SamplerResult &x = a.samplers[k], &y = b.samplers[k];
        EXPECT_NEAR(x.value, y.value, 4 * std::hypot(x.standardError, y.standardError))
            << scene.samplers[k].name << ": " << x.value << " +- " << x.standardError << " against " << y.value
            << " +- " << y.standardError;
    }
    // Measured: 0.45 and 0.81 of the errors without them (with the roulette's survivors
    // at a third of the first vertex's weight, which tames the same deep sunlit hits).
    EXPECT_LT(a.samplers[0].standardError, 0.6 * b.samplers[0].standardError);
    EXPECT_LT(a.samplers[1].standardError, 0.9 * b.samplers[1].standardError);
}

}  // namespace
}  // namespace luxplan
