// Light budgets against what is known: one luminaire in a black room is the whole
// budget; two identical panels share in proportion to their flux; under an open sky
// with the sun, the shares are pi L and E_n sin(altitude) over their sum; the
// interreflected share of a grey room matches 1 - E(black walls) / E(grey walls),
// measured apart; the thread count does not matter; a path's light by bounces is
// what each more surface vertex adds to the same path cut shorter.
#include <gtest/gtest.h>

#include <luxplan/daylight/daylight.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/light_budget.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"
#include "support/threads.h"

namespace luxplan {
namespace {

// A 4 x 4 x 3 m room of reflectance rho, a 0.6 m panel at (x, 2) on the ceiling for
// each flux, and a 2 x 2 point planar sampler 0.1 m across at (2, 2, 0.8).
Scene panelRoom(double rho, std::vector<std::pair<double, double>> panels) {
    test::SceneBuilder b;
    b.material("m", test::diffuse(rho)).room({0, 0, 0}, {4, 4, 3}, "m", "m", "m");
    int k = 0;
    for (auto [x, flux] : panels)
        b.emitter("panel" + std::to_string(++k), rectEmitter({x, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), flux);
    b.sampler("desk", planarSampler({2, 2, 0.8}, {0, 0, 1}, {0, 1, 0}, {0.1, 0.1}, {2, 2}), 0, kInf);
    return b.build();
}

TEST(LightBudget, OneLuminaireInABlackRoomIsTheWholeBudget) {
    test::SceneLab lab(panelRoom(0, {{2, 3000}}));
    std::vector<SamplerBudget> b = measureLightBudgets(*lab.tracer, 32, 1);
    ASSERT_EQ(b.size(), 1u);
    ASSERT_EQ(b[0].emitters.size(), 1u);
    EXPECT_NEAR(b[0].emitters[0], 1, 1e-12);
    EXPECT_EQ(b[0].interreflected, 0);
    EXPECT_EQ(b[0].sun, 0);
    EXPECT_EQ(b[0].sky, 0);
    EXPECT_EQ(b[0].paths, 4u * 32u);
    EXPECT_EQ(describeBudget(lab.scene, b[0]), "panel1 100%");
}

TEST(LightBudget, IdenticalPanelsShareInProportionToTheirFlux) {
    // Symmetric about the sampler: each panel's illuminance is proportional to its flux.
    test::SceneLab lab(panelRoom(0, {{1, 3000}, {3, 1000}}));
    SamplerBudget b = measureLightBudgets(*lab.tracer, 512, 2)[0];
    EXPECT_NEAR(b.emitters[0], 0.75, 0.02);
    EXPECT_NEAR(b.emitters[1], 0.25, 0.02);
    EXPECT_NEAR(b.emitters[0] + b.emitters[1], 1, 1e-12);
    EXPECT_EQ(describeBudget(lab.scene, b).rfind("panel1 7", 0), 0u) << describeBudget(lab.scene, b);
}

TEST(LightBudget, SunAndSkyUnderAnOpenSky) {
    // No room: a uniform sky of L and a sun at 30 deg with E_n at normal incidence over
    // a black ground. E_sky = pi L, E_sun = E_n sin 30.
    const double L = 2000, En = 40000;
    DaylightParams d;
    d.model = SkyModelType::Uniform;
    d.luminanceNits = L;
    d.sunOverride = SunOverride{30, 180, En};
    d.groundReflectance = 0;
    test::SceneLab lab(test::SceneBuilder()
                           .material("m", test::diffuse(0.5))
                           .daylight(d)
                           .sampler("ground", planarSampler({0, 0, 0.8}, {0, 0, 1}, {0, 1, 0}, {0.1, 0.1}, {2, 2}), 0, kInf)
                           .build());
    SamplerBudget b = measureLightBudgets(*lab.tracer, 512, 3)[0];
    const double sky = kPi * L, sun = En * 0.5;
    EXPECT_NEAR(b.sky, sky / (sky + sun), 0.02);
    EXPECT_NEAR(b.sun, sun / (sky + sun), 0.02);
    EXPECT_EQ(b.interreflected, 0);  // nothing to reflect off
}

TEST(LightBudget, InterreflectionIsWhatGreyWallsAddToTheDirectLight) {
    // The direct part does not depend on the walls' reflectance: measured with black
    // walls, it gives the interreflected share of the grey room as 1 - E_black / E_grey.
    test::SceneLab grey(panelRoom(0.6, {{2, 3000}}));
    test::SceneLab black(panelRoom(0, {{2, 3000}}));
    const SamplerResult g = grey.measure(4096).samplers[0], k = black.measure(4096).samplers[0];
    const double expected = 1 - k.value / g.value;
    SamplerBudget b = measureLightBudgets(*grey.tracer, 2048, 4)[0];
    // Tolerance: the two measurements' errors through the ratio, and the budget's own.
    const double sigma = (k.value / g.value) * std::hypot(k.standardError / k.value, g.standardError / g.value);
    EXPECT_GT(expected, 0.1);  // about 0.2: the walls matter
    EXPECT_NEAR(b.interreflected, expected, 4 * sigma + 0.02);
    EXPECT_NEAR(b.interreflected + b.emitters[0], 1, 1e-12);
}

TEST(LightBudget, EachBounceIsWhatOneMoreSurfaceVertexAdds) {
    // The same random numbers with the path cut after b surface vertices (maxDepth b)
    // and uncut: the light credited after b scatterings is the difference between the
    // cuts at b + 1 and b, path by path, sky, sun and luminaire together.
    // panelRoom's, with an open window in the south wall under a sky and a sun that
    // reach the point straight through it.
    DaylightParams d;
    d.model = SkyModelType::Uniform;
    d.luminanceNits = 3000;
    d.sunOverride = SunOverride{40, 180, 50000};
    test::SceneBuilder b;
    b.material("m", test::diffuse(0.6)).room({0, 0, 0}, {4, 4, 3}, "m", "m", "m").window(Wall::South, 1, 2, 0.8, 1.8);
    b.emitter("panel", rectEmitter({2, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000);
    b.sampler("desk", planarSampler({2, 2, 0.8}, {0, 0, 1}, {0, 1, 0}, {0.1, 0.1}, {2, 2}), 0, kInf);
    b.daylight(d);
    test::SceneLab lab(b.build());
    const auto placed = placeSampler(lab.scene.samplers[0], *lab.tracer);
    auto tracerCutAt = [&](int depth) {
        PathTracerOptions o;
        o.maxDepth = depth;
        return std::make_unique<PathTracer>(*lab.rt, &*lab.daylight, o);
    };
    std::vector<std::unique_ptr<PathTracer>> cut;
    for (int depth = 1; depth <= 4; ++depth) cut.push_back(tracerCutAt(depth));
    double bySun = 0, bySky = 0, byLuminaire = 0;
    for (int path = 0; path < 400; ++path) {
        auto value = [&](const PathTracer& tracer, LightBudget* budget) {
            Rng rng(hashValues({7, uint64_t(path)}));
            PathSamples samples(rng);
            RayStats stats;
            PathParams params;
            params.budget = budget;
            PathContributions c(0);
            placed->sample(tracer, 0, samples, stats, params, c);
            return c.size() > 0 ? c.valueAt(0) : 0.0;
        };
        LightBudget budget;
        const double whole = value(*lab.tracer, &budget);
        std::vector<double> upTo = {0};  // cut after 0, 1, ... 4 surface vertices
        for (const auto& t : cut) upTo.push_back(value(*t, nullptr));
        double sum = 0;
        for (int b = 0; b < LightBudget::kBounces; ++b) {
            double bounce = 0;
            for (int kind = 0; kind < LightBudget::kKinds; ++kind) bounce += budget.byBounce[size_t(kind)][size_t(b)];
            sum += bounce;
            if (b < 4) {
                EXPECT_NEAR(bounce, upTo[size_t(b) + 1] - upTo[size_t(b)], 1e-9 * (1 + whole)) << "path " << path << ", bounce " << b;
            }
        }
        EXPECT_NEAR(sum, whole, 1e-9 * (1 + whole)) << "path " << path;
        EXPECT_NEAR(budget.byBounce[LightBudget::kSunKind][0], budget.sun, 1e-9 * (1 + whole));
        EXPECT_NEAR(budget.byBounce[LightBudget::kSkyKind][0], budget.sky, 1e-9 * (1 + whole));
        bySun += budget.byBounce[LightBudget::kSunKind][0];
        bySky += budget.byBounce[LightBudget::kSkyKind][0];
        byLuminaire += budget.byBounce[LightBudget::kLuminaireKind][0];
    }
    // Every kind reaches the point directly, so the test covers each.
    EXPECT_GT(bySun, 0);
    EXPECT_GT(bySky, 0);
    EXPECT_GT(byLuminaire, 0);
}

TEST(LightBudget, DoesNotDependOnTheThreadCount) {
    test::SceneLab lab(panelRoom(0.5, {{1, 3000}, {3, 1000}}));
    auto one = test::withThreads(1, [&] { return measureLightBudgets(*lab.tracer, 64, 5); });
    auto two = test::withThreads(2, [&] { return measureLightBudgets(*lab.tracer, 64, 5); });
    EXPECT_EQ(one[0].emitters, two[0].emitters);
    EXPECT_EQ(one[0].interreflected, two[0].interreflected);
}

}  // namespace
}  // namespace luxplan
