// Russian roulette (PathTracerOptions::rouletteLevel): a path goes on with probability
// min(0.95, throughput / (level x the first surface's)). Any level leaves every
// estimate where it was; survivors that carry a third of the first vertex's weight
// instead of all of it make the rare bright deep hits far less noisy.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <luxplan/core/estimator.h>

#include <luxplan/lightsamplers/light_samplers.h>
#include "support/closed_grey_room.h"
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
    const test::ClosedGreyRoom room(0.8, 2000);
    for (double level : {1.0, 1.0 / 3.0, 0.05}) {
        PathTracerOptions options;
        options.rouletteLevel = level;
        const test::ClosedGreyRoom::Mean mean = test::ClosedGreyRoom::mean(SceneLab(room.scene, options).measure(400));
        // The grid points' mean stands for each face's: 2% for that quadrature.
        EXPECT_NEAR(mean.value, room.expected, 4 * mean.standardError + 0.02 * room.expected) << "level " << level;
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
