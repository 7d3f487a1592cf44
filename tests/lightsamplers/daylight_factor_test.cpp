// The daylight factor (lightsamplers/daylight_factor.h) against hand values: open ground
// under the CIE overcast sky reads 100% facing up and (0.396 + rho / 2) x 100% facing a
// side (the sky's E_v = Lz (pi/6 + 4/9) = 0.396 E_h, and half the ground, of luminance
// rho E_h / pi); a room without openings reads 0; the scene's own daylight and its
// luminaires change nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <luxplan/daylight/daylight.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/daylight_factor.h>
#include <luxplan/rt/embree_scene.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace daylight_factor_test {

// A plane 0.8 m above open ground (nothing else in the scene), facing up, and one
// facing south, under a uniform sky that the daylight factor's replaces.
Scene openGround(double groundReflectance) {
    return test::SceneBuilder()
        .uniformSky(5000, groundReflectance)
        .sampler("up", planarSampler({0, 0, 0.8}, {0, 0, 1}, {0, 1, 0}, {2, 2}, {3, 3}), 0)
        .sampler("south", planarSampler({0, 0, 0.8}, {0, -1, 0}, {0, 0, 1}, {2, 1}, {2, 2}), 0)
        .build();
}

MeasureOptions paths(int n, uint64_t seed = 1) {
    MeasureOptions o;
    o.pathsPerPoint = n, o.seed = seed;
    return o;
}

TEST(DaylightFactor, OpenGroundFacingUpIs100Percent) {
    const Scene scene = openGround(0.2);
    ASSERT_EQ(daylightFactorRefusal(scene), "");
    const DaylightFactorResult r = measureDaylightFactors(scene, initialLayout(scene), paths(4000));
    EXPECT_NEAR(r.outdoorLx, kDaylightFactorSkyLx, 1e-3 * kDaylightFactorSkyLx);
    ASSERT_EQ(r.factors.size(), 2u);
    const DaylightFactor& up = r.factors[0];
    EXPECT_GT(up.stdError, 0);
    EXPECT_LT(up.stdError, 1);
    EXPECT_NEAR(up.percent, 100, 4 * up.stdError) << "std error " << up.stdError;
    ASSERT_EQ(up.points.size(), 9u);
    EXPECT_NEAR(up.min, *std::min_element(up.points.begin(), up.points.end()), 1e-12);
    EXPECT_NEAR(r.measured.samplers[0].value * 100 / r.outdoorLx, up.percent, 1e-9 * up.percent);
}

TEST(DaylightFactor, OpenGroundFacingASideIsTheSkysVerticalShareAndHalfTheGround) {
    for (double rho : {0.0, 0.2}) {
        const Scene scene = openGround(rho);
        const DaylightFactorResult r = measureDaylightFactors(scene, initialLayout(scene), paths(4000));
        const DaylightFactor& south = r.factors[1];
        const double expected = 100 * ((kPi / 6 + 4.0 / 9) * 9 / (7 * kPi) + rho / 2);  // 39.6% + 50 rho
        EXPECT_NEAR(south.percent, expected, 4 * south.stdError + 1e-3 * expected) << "rho " << rho << ", std error " << south.stdError;
    }
}

// The scene's ground reflectance, and 0.2 without daylight; never its sky or sun.
TEST(DaylightFactor, TheSkyIsOvercastWithTheScenesGround) {
    Scene scene = openGround(0.35);
    DaylightParams sky = daylightFactorSky(scene);
    EXPECT_EQ(sky.model, SkyModelType::CieOvercast);
    EXPECT_EQ(*sky.horizontalIlluminanceLx, kDaylightFactorSkyLx);
    EXPECT_FALSE(sky.sunEnabled());
    EXPECT_EQ(sky.groundReflectance, 0.35);
    scene.daylight.reset();
    EXPECT_EQ(daylightFactorSky(scene).groundReflectance, 0.2);
    // The same daylight factors with the scene's own daylight or none (same ground).
    Scene day = openGround(0.2), night = openGround(0.2);
    night.daylight.reset();
    const DaylightFactorResult a = measureDaylightFactors(day, initialLayout(day), paths(64));
    const DaylightFactorResult b = measureDaylightFactors(night, initialLayout(night), paths(64));
    for (size_t k = 0; k < 2; ++k) EXPECT_EQ(a.factors[k].percent, b.factors[k].percent) << k;
}

// A closed room reads 0 at every point, its lamp off.
TEST(DaylightFactor, ARoomWithoutOpeningsReadsZero) {
    const Scene scene = test::SceneBuilder()
                            .material("grey", test::diffuse(0.5))
                            .room({0, 0, 0}, {4, 3, 2.5}, "grey", "grey", "grey")
                            .overcastSky(10000)
                            .emitter("panel", rectEmitter({2, 1.5, 2.49}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
                            .sampler("work", planarSampler({2, 1.5, 0.8}, {0, 0, 1}, {0, 1, 0}, {3, 2}, {3, 2}), 0)
                            .build();
    EXPECT_NE(daylightFactorRefusal(scene).find("the room has no openings"), std::string::npos);
    const DaylightFactorScene df = daylightFactorScene(scene);
    const DaylightFactorResult r = [&] {
        // Measured all the same (the refusal is the command's): the sky never reaches it.
        const DaylightEnvironment sky = buildDaylight(*df.scene.daylight, df.scene.site);
        const EmbreeScene rt(df.scene, initialLayout(df.scene));
        const PathTracer tracer(rt, &sky);
        DaylightFactorResult out;
        out.measured = measureSamplers(tracer, paths(256));
        return out;
    }();
    ASSERT_EQ(r.measured.samplers.size(), 1u);
    EXPECT_EQ(r.measured.samplers[0].value, 0);
    for (double p : r.measured.samplers[0].points) EXPECT_EQ(p, 0);
    // With a window it is measured, and lies between 0 and 100%.
    const Scene windowed = test::SceneBuilder()
                               .material("grey", test::diffuse(0.5))
                               .room({0, 0, 0}, {4, 3, 2.5}, "grey", "grey", "grey")
                               .window(Wall::South, 1, 2, 0.9, 1.2)
                               .sampler("work", planarSampler({2, 1.5, 0.8}, {0, 0, 1}, {0, 1, 0}, {3, 2}, {3, 2}), 0)
                               .build();
    EXPECT_EQ(daylightFactorRefusal(windowed), "");
    const DaylightFactorResult w = measureDaylightFactors(windowed, initialLayout(windowed), paths(256));
    EXPECT_GT(w.factors[0].percent, 0.5);
    EXPECT_LT(w.factors[0].percent, 20);
}

// Only planar samplers are measured; a scene without one is refused.
TEST(DaylightFactor, PlanarSamplersOnly) {
    const Scene scene = test::SceneBuilder()
                            .uniformSky(1000)
                            .sampler("face", cylindricalSampler({0, 0, 1.2}), 0)
                            .sampler("up", planarSampler({0, 0, 0.8}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {1, 1}), 0)
                            .build();
    const DaylightFactorScene df = daylightFactorScene(scene);
    ASSERT_EQ(df.samplers, std::vector<size_t>{1});
    ASSERT_EQ(df.scene.samplers.size(), 1u);
    EXPECT_EQ(df.scene.samplers[0].name, "up");
    const Scene none = test::SceneBuilder().uniformSky(1000).sampler("face", cylindricalSampler({0, 0, 1.2}), 0).build();
    EXPECT_NE(daylightFactorRefusal(none).find("the scene has no planar sampler"), std::string::npos);
    EXPECT_THROW(measureDaylightFactors(none, initialLayout(none), paths(4)), std::runtime_error);
}

}  // namespace daylight_factor_test
}  // namespace luxplan
