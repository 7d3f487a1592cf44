// Russian roulette (PathTracerOptions::rouletteLevel): a path goes on with probability
// min(0.95, throughput / (level x the first surface's)). Any level leaves every
// estimate where it was; survivors that carry a third of the first vertex's weight
// instead of all of it make the rare bright deep hits far less noisy.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <luxplan/core/estimator.h>

#include <luxplan/lightsamplers/light_samplers.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;

// A closed grey room lit by a small bulb: every lumen is absorbed after 1 / (1 - rho)
// reflections on average, so the area-weighted mean illuminance is flux / (A (1 - rho))
// whatever the roulette does (rho = 0.8: five bounces on average, most of them past
// the roulette's start).
TEST(RussianRoulette, EveryLevelKeepsTheClosedRoomsEnergyBalance) {
    const double rho = 0.8, flux = 2000, A = 2 * (4 * 3 + 4 * 2.5 + 3 * 2.5);
    const Scene scene = SceneBuilder()
                            .material("grey", test::diffuse(rho))
                            .room({0, 0, 0}, {4, 3, 2.5}, "grey", "grey", "grey")
                            .emitter("bulb", sphereEmitter({2.1, 1.4, 1.3}, 0.01), flux)
                            .sampler("floor", planarSampler({2, 1.5, 0.001}, {0, 0, 1}, {0, 1, 0}, {4, 3}, {4, 3}), 0, 1e9)
                            .sampler("ceiling", planarSampler({2, 1.5, 2.499}, {0, 0, -1}, {0, 1, 0}, {4, 3}, {4, 3}), 0, 1e9)
                            .sampler("south", planarSampler({2, 0.001, 1.25}, {0, 1, 0}, {0, 0, 1}, {4, 2.5}, {4, 3}), 0, 1e9)
                            .sampler("north", planarSampler({2, 2.999, 1.25}, {0, -1, 0}, {0, 0, 1}, {4, 2.5}, {4, 3}), 0, 1e9)
                            .sampler("west", planarSampler({0.001, 1.5, 1.25}, {1, 0, 0}, {0, 0, 1}, {3, 2.5}, {3, 3}), 0, 1e9)
                            .sampler("east", planarSampler({3.999, 1.5, 1.25}, {-1, 0, 0}, {0, 0, 1}, {3, 2.5}, {3, 3}), 0, 1e9)
                            .build();
    const double areas[6] = {12, 12, 10, 10, 7.5, 7.5};
    const double expected = flux / (A * (1 - rho));
    for (double level : {1.0, 1.0 / 3.0, 0.05}) {
        PathTracerOptions options;
        options.rouletteLevel = level;
        const MeasureResult r = SceneLab(scene, options).measure(400);
        double mean = 0, variance = 0;
        for (int k = 0; k < 6; ++k) {
            mean += areas[k] * r.samplers[size_t(k)].value / A;
            variance += std::pow(areas[k] / A * r.samplers[size_t(k)].standardError, 2);
        }
        // The grid points' mean stands for each face's: 2% for that quadrature.
        EXPECT_NEAR(mean, expected, 4 * std::sqrt(variance) + 0.02 * expected) << "level " << level;
    }
}

// A wall lit by a window under an overcast sky, seen through 8 x 8 strata (the room
// of scenes/checks/window-lit-wall.json): half its light has bounced, and that half
// carries nearly all the noise. Survivors at a third of the first weight read the
// same strata with clearly less error per ray.
TEST(RussianRoulette, SurvivorsAtAThirdOfTheFirstWeightReadTheSameWithLessNoisePerRay) {
    const Scene scene = SceneBuilder()
                            .material("wall", test::diffuse(0.6))
                            .material("floor", test::diffuse(0.3))
                            .overcastSky(10000)
                            .room({0, 0, 0}, {5, 5, 3}, "floor", "wall", "wall")
                            .window(Wall::South, 0.5, 1.5, 0.9, 1.4)
                            .sampler("wall", directionalSampler({2.5, 2.5, 1.2}, {1, 0, 0}, {0, 0, 1}, 60, 8), 0, 100)
                            .build();
    PathTracerOptions whole, third;
    whole.rouletteLevel = 1;
    third.rouletteLevel = 1.0 / 3.0;
    // Each stratum's error is the spread of its mean over seeds; the cost, the rays.
    const int seeds = 16, strata = 64;
    const SceneLab a(scene, third), b(scene, whole);
    std::vector<MeanEstimator> x(strata), y(strata);
    double raysA = 0, raysB = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        const MeasureResult ra = a.measure(32, uint64_t(seed)), rb = b.measure(32, uint64_t(seed));
        raysA += double(ra.rays.closest + ra.rays.shadow), raysB += double(rb.rays.closest + rb.rays.shadow);
        for (int i = 0; i < strata; ++i) x[size_t(i)].add(ra.samplers[0].points[size_t(i)]), y[size_t(i)].add(rb.samplers[0].points[size_t(i)]);
    }
    double varianceA = 0, varianceB = 0, meanA = 0, meanB = 0, errorA = 0, errorB = 0;
    for (int i = 0; i < strata; ++i) {
        varianceA += x[size_t(i)].variance(), varianceB += y[size_t(i)].variance();
        meanA += x[size_t(i)].mean() / strata, meanB += y[size_t(i)].mean() / strata;
        errorA += x[size_t(i)].varianceOfMean() / (strata * strata), errorB += y[size_t(i)].varianceOfMean() / (strata * strata);
    }
    EXPECT_NEAR(meanA, meanB, 4 * std::sqrt(errorA + errorB));
    // Measured: 0.60 of the variance for 1.18 times the rays, 1.41 times the efficiency.
    const double efficiency = (varianceB * raysB) / (varianceA * raysA);
    EXPECT_GT(efficiency, 1.2) << "variance " << varianceA / varianceB << " of level 1's, rays x" << raysA / raysB;
}

}  // namespace
}  // namespace luxplan
