// Low-discrepancy path sampling (MeasureOptions::lowDiscrepancy): under a panel and
// through a window its estimates are unbiased (mean over seeds against quadrature) and
// their real error over seeds is well below that of PCG at the same paths; the
// standard error it reports (from the paths' spread) does not understate that error.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/emitters/emitter_shape.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;
using test::kZ;

struct Spread {
    double mean = 0, rms = 0, reportedError = 0;  // rms about the truth
};

Spread overSeeds(const SceneLab& lab, bool lowDiscrepancy, double truth, int seeds, int paths) {
    Spread s;
    for (int seed = 1; seed <= seeds; ++seed) {
        MeasureOptions o;
        o.pathsPerPoint = paths, o.seed = uint64_t(seed), o.lowDiscrepancy = lowDiscrepancy;
        const SamplerResult r = measureSamplers(*lab.tracer, o).samplers[0];
        s.mean += r.value / seeds;
        s.rms += (r.value - truth) * (r.value - truth) / seeds;
        s.reportedError += r.standardError / seeds;
    }
    s.rms = std::sqrt(s.rms);
    return s;
}

TEST(LowDiscrepancyPaths, PanelOverAPointIsUnbiasedWithLessError) {
    // A 1 x 1 m panel of 4000 lm, 2 m above an upward point in a black room.
    SceneLab lab(SceneBuilder()
                     .material("black", test::diffuse(0))
                     .room({-3, -3, 0}, {3, 3, 3}, "black", "black", "black")
                     .emitter("panel", rectEmitter({0.3, 0.2, 2.8}, {0, 0, -1}, {0, 1, 0}, {1, 1}), 4000)
                     .sampler("p", planarSampler({0, 0, 0.8}, kZ, {0, 1, 0}, {0.001, 0.001}, {1, 1}), 0, kInf)
                     .build());
    // E = L * integral of cos cos' / d^2 over the panel, L = flux / (pi A).
    const int n = 400;
    double truth = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Vec3 d = Vec3(-0.2 + (i + 0.5) / n, -0.3 + (j + 0.5) / n, 2.0);
            double d2 = dot(d, d), c = d.z / std::sqrt(d2);
            truth += (4000 / kPi) * c * c / d2 / (n * n);
        }
    const int seeds = 40, paths = 64;
    Spread sobol = overSeeds(lab, true, truth, seeds, paths), pcg = overSeeds(lab, false, truth, seeds, paths);
    EXPECT_NEAR(sobol.mean, truth, 3 * sobol.rms / std::sqrt(seeds) + 1e-9 * truth);
    EXPECT_NEAR(pcg.mean, truth, 4 * pcg.rms / std::sqrt(seeds));
    EXPECT_LT(sobol.rms, 0.5 * pcg.rms) << "sobol " << sobol.rms << " pcg " << pcg.rms;
    EXPECT_GE(sobol.reportedError, sobol.rms);  // conservative
    std::printf("panel: rms sobol %.4f pcg %.4f, reported %.4f\n", sobol.rms, pcg.rms, sobol.reportedError);
}

TEST(LowDiscrepancyPaths, WindowLightIsUnbiasedWithLessError) {
    // A uniform sky through a window onto a point facing it, nothing reflects: E by
    // quadrature over the window (as Analytic.GlazedOpeningScalesByThePanesTransmittance).
    SceneLab lab(SceneBuilder()
                     .material("black", test::diffuse(0))
                     .uniformSky(1000)
                     .room({0, 0, 0}, {4, 4, 3}, "black", "black", "black")
                     .window(Wall::South, 1, 2, 1, 1.5)
                     .sampler("p", planarSampler({2, 1.5, 1.2}, {0, -1, 0}, kZ, {0.001, 0.001}, {1, 1}), 0, kInf)
                     .build());
    const int n = 400;
    double truth = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Vec3 d = Vec3(1 + 2.0 * (i + 0.5) / n, 0, 1 + 1.5 * (j + 0.5) / n) - Vec3(2, 1.5, 1.2);
            if (d.z <= 0) continue;
            double dist = length(d), c = -d.y / dist;
            truth += 1000 * c * c * (2.0 * 1.5 / (n * n)) / (dist * dist);
        }
    const int seeds = 40, paths = 64;
    Spread sobol = overSeeds(lab, true, truth, seeds, paths), pcg = overSeeds(lab, false, truth, seeds, paths);
    EXPECT_NEAR(sobol.mean, truth, 3 * sobol.rms / std::sqrt(seeds) + 1e-9 * truth);
    EXPECT_LT(sobol.rms, 0.5 * pcg.rms) << "sobol " << sobol.rms << " pcg " << pcg.rms;
    EXPECT_GE(sobol.reportedError, sobol.rms);
    std::printf("window: rms sobol %.4f pcg %.4f, reported %.4f\n", sobol.rms, pcg.rms, sobol.reportedError);
}

}  // namespace
}  // namespace luxplan
