// Adaptive measurement (MeasureOptions::adaptive): a sampler stops once value +- z
// standard errors lies inside one linear piece of its penalty. A stopped sampler reads
// exactly what a fixed run of the paths it traced reads; one whose interval straddles
// a bound of its band runs to the most paths; stopping early leaves the value
// unbiased to within its own error.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/emitters/emitter_shape.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;

// A 1000 lm sphere 1 m above an upward point, under a grey ceiling: E is the direct
// (1000 / 4 pi) / 1^2 plus the ceiling's light.
const double kDirect = 1000 / (4 * kPi);

Scene bulbOver(double targetMin, double targetMax, double tolerance) {
    return SceneBuilder()
        .material("grey", test::diffuse(0.5))
        .emitter("bulb", sphereEmitter({0, 0, 1.8}, 0.05), 1000)
        .box("ceiling", {-3, -3, 2.5}, {3, 3, 2.6}, "grey")  // indirect light: noise
        .sampler("p", planarSampler({0, 0, 0.8}, {0, 0, 1}, {0, 1, 0}, {0.001, 0.001}, {1, 1}), targetMin, targetMax, tolerance)
        .build();
}

MeasureResult measure(const SceneLab& lab, int paths, bool adaptive, uint64_t seed = 1) {
    MeasureOptions o;
    o.pathsPerPoint = paths, o.seed = seed, o.adaptive = adaptive;
    return measureSamplers(*lab.tracer, o);
}

TEST(AdaptivePaths, FarFromTheBandStopsAfterOneBatchAndReadsAsAFixedRun) {
    SceneLab lab(bulbOver(300, 500, 100));  // E ~ 100 lx: far below
    MeasureResult a = measure(lab, 1000, true);
    const int batch = MeasureOptions().batchPaths;
    ASSERT_EQ(a.samplers[0].pathsPerPoint, batch);
    EXPECT_EQ(a.paths, uint64_t(batch));
    MeasureResult fixed = measure(lab, batch, false);
    EXPECT_EQ(a.samplers[0].value, fixed.samplers[0].value);
    EXPECT_EQ(a.samplers[0].standardError, fixed.samplers[0].standardError);
    EXPECT_EQ(a.samplers[0].points, fixed.samplers[0].points);
}

TEST(AdaptivePaths, AnIntervalAcrossABoundRunsToTheMost) {
    const double E = measure(SceneLab(bulbOver(0, kInf, 1)), 20000, false).samplers[0].value;
    ASSERT_GT(E, kDirect);
    SceneLab lab(bulbOver(E, 500, 100));  // the true value sits on the band's lower bound
    MeasureResult a = measure(lab, 400, true);
    EXPECT_EQ(a.samplers[0].pathsPerPoint, 400);
    EXPECT_EQ(a.samplers[0].value, measure(lab, 400, false).samplers[0].value);
}

TEST(AdaptivePaths, NotAdaptiveTracesExactlyTheAskedPaths) {
    SceneLab lab(bulbOver(300, 500, 100));
    EXPECT_EQ(measure(lab, 100, false).samplers[0].pathsPerPoint, 100);
}

// Optional stopping: over many seeds, the stopped values average to the truth within
// the noise of that average (no bias on the scale of one run's error), and each stop
// put the value in the right piece of the penalty.
TEST(AdaptivePaths, StoppingEarlyLeavesTheValueUnbiased) {
    const SamplerResult truth = measure(SceneLab(bulbOver(0, kInf, 1)), 50000, false).samplers[0];
    const double E = truth.value, top = 0.8 * E;
    SceneLab lab(bulbOver(0, top, 0.1 * E));  // E is two tolerances above the band
    const int seeds = 200;
    double sum = 0, sumSquares = 0, error = 0;
    int wrongPiece = 0, stoppedEarly = 0;
    for (int s = 0; s < seeds; ++s) {
        SamplerResult r = measure(lab, 1000, true, 10 + s).samplers[0];
        stoppedEarly += r.pathsPerPoint < 1000;
        double d = r.value / E - 1;
        sum += d, sumSquares += d * d, error += r.standardError / E;
        wrongPiece += r.value <= top;
    }
    const double bias = sum / seeds, sd = std::sqrt(sumSquares / seeds - bias * bias);
    EXPECT_GT(stoppedEarly, seeds * 9 / 10);
    EXPECT_LT(std::abs(bias), 4 * sd / std::sqrt(double(seeds)) + 4 * truth.standardError / E)
        << "relative bias " << bias << ", one run's relative error " << error / seeds;
    EXPECT_EQ(wrongPiece, 0);
}

}  // namespace
}  // namespace luxplan
