// Daylight coefficients against truth: the sky patches' geometry exactly, an open
// point's coefficients against each patch's projected solid angle, and a windowed
// room's hours against tracing each hour's sky and sun directly.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/annual/daylight_coefficients.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/rt/embree_scene.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace daylight_coefficients_test {

using test::SceneBuilder;

TEST(SkyPatches, ReinhartCountsAndTheirAnglesFillTheSky) {
    for (int m : {1, 2, 4}) {
        const SkyPatches sky(m);
        EXPECT_EQ(sky.count(), 1 + 144 * m * m + 1) << "MF:" << m;  // the ground, the bands, the cap
        double omega = 0, projected = 0;
        for (int p = 1; p < sky.count(); ++p) {
            omega += sky.solidAngle(p), projected += sky.projectedSolidAngle(p);
            EXPECT_EQ(sky.patchOf(sky.centre(p)), p) << "MF:" << m << " patch " << p;
            for (const Vec3& d : sky.directions(p, 3)) EXPECT_EQ(sky.patchOf(d), p);
        }
        EXPECT_NEAR(omega, 2 * kPi, 1e-9);
        EXPECT_NEAR(projected, kPi, 1e-9);
        EXPECT_EQ(sky.patchOf({0, 0.6, -0.8}), 0);
    }
    EXPECT_EQ(SkyPatches(1).count(), 146);  // Tregenza's 145 and the ground
    EXPECT_THROW(SkyPatches(0), std::invalid_argument);
}

// A point facing up over a black floor, nothing else: under the basis sky each patch
// gives it its projected solid angle (its illuminance per cd/m2), the ground nothing.
TEST(DaylightCoefficients, AnOpenPointGetsEachPatchsProjectedSolidAngle) {
    Scene scene = SceneBuilder()
                      .material("black", test::diffuse(0))
                      .box("floor", {-50, -50, -1}, {50, 50, 0}, "black")
                      .uniformSky(1000)
                      .sampler("point", planarSampler({0, 0, 0.8}, {0, 0, 1}, {0, 1, 0}, {0.1, 0.1}, {1, 1}), 0)
                      .build();
    const DaylightCoefficients dc({DaylightInstant{}}, [](size_t) -> SkyLuminance { return [](const Vec3&) { return 1.0; }; },
                                  DaylightCoefficientOptions{});
    EmbreeScene rt(scene, initialLayout(scene));
    const PathTracer tracer(rt, &dc.basis(), DaylightCoefficients::tracing());
    const PointCoefficients p = dc.coefficients(tracer, *placeSampler(scene.samplers[0], tracer), 0, 0, 20000, 1);
    const SkyPatches& sky = dc.skyPatches();
    EXPECT_EQ(p.sky[0], 0.0);
    double sum = 0;
    for (int k = 1; k < sky.count(); ++k) sum += p.sky[size_t(k)];
    EXPECT_NEAR(sum, kPi, 0.01 * kPi);
    // Bands of patches (each band's sum), against their projected solid angle: a
    // cosine-weighted sample of 20000 paths lands n ~ 20000 * share in a band, so each
    // band's relative error is about 1/sqrt(n).
    for (int band = 0; band < 3; ++band) {
        double got = 0, want = 0;
        for (int k = 1; k < sky.count(); ++k) {
            const double alt = std::asin(sky.centre(k).z);
            if (int(alt / radians(90.0 / 7.5)) != band) continue;
            got += p.sky[size_t(k)], want += sky.projectedSolidAngle(k);
        }
        const double n = 20000 * want / kPi;
        EXPECT_NEAR(got, want, want * 4 / std::sqrt(n)) << "band " << band;
    }
}

DaylightParams springDay() {
    DaylightParams d;
    d.model = SkyModelType::Preetham;
    d.turbidity = 3;
    d.from = parseIso8601("2026-03-21T08:00+02:00");
    d.to = parseIso8601("2026-03-21T16:00+02:00");
    d.stepMinutes = 120;
    d.groundReflectance = 0.2;
    return d;
}

// A room with a south window and a desk-high grid: the coefficients' hours against each
// hour traced directly (its own baked sky and sun), within their noise.
TEST(DaylightCoefficients, HoursAgreeWithTracingEachHourDirectly) {
    const Site athens{37.97, 23.72, 0};
    DaylightParams day = springDay();
    Scene scene = SceneBuilder()
                      .material("white", test::diffuse(0.6))
                      .material("grey", test::diffuse(0.3))
                      .room({0, 0, 0}, {5, 4, 3}, "grey", "white", "white")
                      .window(Wall::South, 1, 3, 0.9, 1.5)
                      .daylight(day)
                      .sampler("desk", planarSampler({2.5, 1.5, 0.75}, {0, 0, 1}, {0, 1, 0}, {2, 2}, {3, 3}), 300)
                      .build();
    scene.site = athens;
    const std::vector<DaylightInstant> hours = daylightInstants(day, athens);
    ASSERT_EQ(hours.size(), 5u);
    DaylightCoefficientOptions o;
    o.groundReflectance = day.groundReflectance;
    const Layout layout = initialLayout(scene);
    const DaylightCoefficients dc(hours, [&](size_t h) -> SkyLuminance {
        auto sky = std::make_shared<PreethamSky>(day.turbidity, hours[h].sunDirection);
        return [sky](const Vec3& w) { return sky->luminance(w); };
    }, o);
    EmbreeScene rt(scene, layout);
    const PathTracer basis(rt, &dc.basis(), DaylightCoefficients::tracing());
    const AnnualSeries series = dc.measure(basis, {0}, 4000, 1);
    ASSERT_EQ(series.samplers.size(), 1u);
    ASSERT_EQ(series.samplers[0].points.size(), 9u);

    for (size_t h : {size_t(0), size_t(2), size_t(4)}) {
        DaylightParams at = day;
        at.from = hours[h].time;
        at.to.reset();
        const DaylightEnvironment env = buildDaylight(at, athens);
        PathTracer tracer(rt, &env);
        MeasureOptions m;
        m.pathsPerPoint = 4000;
        m.seed = 11;
        const SamplerResult direct = measureSamplers(tracer, m).samplers[0];
        const double dcValue = series.samplers[0].values[h];
        // The direct trace's error, and the coefficients' (their paths as many): a
        // relative 3% beside them for the basis's approximations (each patch at its
        // mean luminance, each sun bin's interreflected light at its mean direction).
        const double tolerance = 4 * std::sqrt(2.0) * direct.standardError + 0.03 * direct.value;
        EXPECT_NEAR(dcValue, direct.value, tolerance) << "hour " << hours[h].time->str();
        for (size_t k = 0; k < 9; ++k) {
            const double tol = 4 * std::sqrt(2.0) * direct.pointErrors[k] + 0.05 * direct.points[k];
            EXPECT_NEAR(series.samplers[0].points[k][h], direct.points[k], tol) << "hour " << h << " point " << k;
        }
    }
}

}  // namespace daylight_coefficients_test
}  // namespace luxplan
