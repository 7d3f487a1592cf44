// Statistics over a sampler's points (min, max, U0 = min / mean, EN 12464-1) under a
// point source in a black void, against the closed form at the very points the
// sampler measures: E = I h / d^3 on a horizontal plane (exact for a sphere above
// it), I = flux / (4 pi); in a volume the mean spherical luminance, the sphere's
// luminance times the solid angle it fills over 4 pi. Tolerances are 4 of the
// statistic's own standard errors. And adaptive measurement waits for every goal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <luxplan/emitters/emitter_shape.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;

const Vec3 kLamp(0.3, 0.1, 1.5);
const double kFlux = 2000, kIntensity = kFlux / (4 * kPi), kRadius = 0.005;

// The lamp off the plane's centre, so that one corner is clearly the darkest point
// (17% below the next): the min of noisy points is then not biased low by a tie.
Scene lampOver(std::shared_ptr<const SamplerType> sampler) {
    return SceneBuilder()
        .material("black", test::diffuse(0))
        .emitter("lamp", sphereEmitter(kLamp, kRadius), kFlux)
        .sampler("s", std::move(sampler), 0)
        .build();
}

std::vector<Vec3> pointsOf(const SamplerType& type) {
    const auto placed = type.place(Transform());
    std::vector<Vec3> points = placed->drawing().dots;  // a planar sampler draws its points
    EXPECT_EQ(int(points.size()), placed->items());
    return points;
}

void expectStatistics(const SamplerResult& r, const std::vector<double>& truth) {
    const PointStatistics measured = pointStatistics(r.points, r.pointErrors);
    const PointStatistics exact = pointStatistics(truth, std::vector<double>(truth.size(), 0.0));
    for (Statistic s : {Statistic::Mean, Statistic::Min, Statistic::Max, Statistic::U0}) {
        const StatisticEstimate& m = measured.of(s);
        EXPECT_GT(m.standardError, 0) << statisticNames().name(s);
        EXPECT_NEAR(m.value, exact.of(s).value, 4 * m.standardError + 1e-9 * std::abs(exact.of(s).value))
            << statisticNames().name(s) << ": standard error " << m.standardError;
    }
    EXPECT_DOUBLE_EQ(measured.mean.value, r.value);  // the mean is the sampler's value
}

TEST(SamplerStatistics, PlanarMinAndU0UnderAPointSource) {
    const auto plane = planarSampler({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {2, 1.6}, {5, 4});
    SceneLab lab(lampOver(plane));
    const SamplerResult r = lab.measure(256).samplers[0];
    std::vector<double> truth;
    for (const Vec3& p : pointsOf(*plane)) truth.push_back(kIntensity * kLamp.z / std::pow(length(kLamp - p), 3));
    expectStatistics(r, truth);
    // The corner farthest from the lamp, (-0.8, -0.6): E = I h / (1.1^2 + 0.7^2 + 1.5^2)^1.5.
    EXPECT_NEAR(*std::min_element(truth.begin(), truth.end()), kIntensity * 1.5 / std::pow(3.95, 1.5), 1e-9);
}

TEST(SamplerStatistics, VolumeMinAndU0UnderAPointSource) {
    const auto box = volumeSampler({0, 0, 0.6}, {Vec3(2, 0, 0), Vec3(0, 1.6, 0), Vec3(0, 0, 1)}, 24);
    SceneLab lab(lampOver(box));
    const SamplerResult r = lab.measure(512).samplers[0];
    // The type's points: Halton points 1..24 of bases 2, 3, 5 in the box (volume.cpp).
    auto halton = [](int base, int i) {
        double f = 1, r = 0;
        for (; i > 0; i /= base) f /= base, r += f * (i % base);
        return r;
    };
    std::vector<double> truth;
    for (int i = 1; i <= 24; ++i) {
        const Vec3 p(-1 + 2 * halton(2, i), -0.8 + 1.6 * halton(3, i), 0.1 + halton(5, i));
        // The sphere's luminance over the solid angle it fills, 2 pi (1 - cos alpha).
        const double sinAlpha = kRadius / length(kLamp - p), L = kFlux / (4 * kPi * kPi * kRadius * kRadius);
        truth.push_back(L * 2 * kPi * (1 - std::sqrt(1 - sinAlpha * sinAlpha)) / (4 * kPi));
    }
    expectStatistics(r, truth);
}

TEST(SamplerStatistics, AdaptiveMeasurementWaitsForEveryGoal) {
    // The mean's open target settles at the first look; a U0 goal whose bound sits on
    // the plane's U0 keeps the sampler tracing to the most paths.
    const auto plane = planarSampler({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {2, 1.6}, {5, 4});
    MeasureOptions o;
    o.pathsPerPoint = 160, o.adaptive = true;
    SceneLab free(lampOver(plane));
    EXPECT_EQ(measureSamplers(*free.tracer, o).samplers[0].pathsPerPoint, o.minPaths);
    const SamplerResult exact = free.measure(160).samplers[0];
    const double u0 = pointStatistics(exact.points, exact.pointErrors).u0.value;
    SceneLab held(SceneBuilder()
                      .emitter("lamp", sphereEmitter(kLamp, kRadius), kFlux)
                      .sampler("s", plane, 0)
                      .statistic(Statistic::U0, u0, 1)
                      .build());
    EXPECT_EQ(measureSamplers(*held.tracer, o).samplers[0].pathsPerPoint, 160);
}

}  // namespace
}  // namespace luxplan
