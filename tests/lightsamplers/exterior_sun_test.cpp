// The sun's light off surfaces outside the room, taken where the sky's portal samples
// meet them (PathTracerOptions::exteriorSun): against the analytic light a sunlit
// facade sends through an opening, and as one more way to find light BSDF sampling
// finds too, which leaves every estimate where it was, with less noise.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/scene/room.h>
#include "support/scene_builder.h"
#include "support/rect_illuminance.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;

constexpr double kSunNormalLx = 60000;

// A black 4 x 4 x 3 m room with an open 1 x 1 m east window; 6 m east of it a white
// facade facing it, lit over the room by the sun in the west at an altitude of atan(2),
// so the room's shadow falls below the part of the facade the window shows. A sky of
// a micro-nit keeps the portals.
SceneBuilder facadeScene(double sunAzimuthDeg, double skyNits = 1e-6) {
    SceneBuilder b;
    b.material("black", test::diffuse(0))
        .material("white", test::diffuse(0.8))
        .sunAndUniformSky({std::atan(2.0) * 180 / kPi, sunAzimuthDeg, kSunNormalLx}, skyNits, 0)
        .room({0, 0, 0}, {4, 4, 3}, "black", "black", "black")
        .window(Wall::East, 1.5, 1, 1, 1)
        .box("facade", {10, -50, -20}, {12, 50, 40}, "white");
    return b;
}

TEST(ExteriorSun, AgreesWithTheLightASunlitFacadeSendsThroughAWindow) {
    const Scene scene = facadeScene(270).sampler("p", planarSampler({2, 2, 1.5}, {1, 0, 0}, {0, 0, 1}, {0.01, 0.01}, {1, 1}), 0).build();
    const Rect3 window = openingQuad(scene.room()->box, scene.room()->openings[0]);
    const Vec3 lo = window.corner, hi = window.corner + window.edgeU + window.edgeV;
    ASSERT_NEAR(lo.x, 4, 1e-12);
    // E = rho / pi * (E_sun cos) * projected solid angle of the window.
    const double facadeLuminance = 0.8 / kPi * kSunNormalLx / std::sqrt(5.0);
    const double expected = test::rectIlluminance(facadeLuminance, std::min(lo.y, hi.y), std::max(lo.y, hi.y),
                                                  std::min(lo.z, hi.z), std::max(lo.z, hi.z), 2, 1.5, 2);
    PathTracerOptions off;
    off.exteriorSun = false;
    SceneLab with(scene), without(scene, off);
    ASSERT_TRUE(with.tracer->samplesExteriorSun());
    ASSERT_FALSE(without.tracer->samplesExteriorSun());
    const SamplerResult a = with.measure(4000).samplers[0], b = without.measure(4000).samplers[0];
    EXPECT_NEAR(a.value, expected, 4 * a.standardError + 2e-3 * expected) << a.standardError;
    EXPECT_NEAR(b.value, expected, 4 * b.standardError + 2e-3 * expected) << b.standardError;
    EXPECT_LT(a.standardError, 0.3 * b.standardError);
}

// The same with a bright sky, which lights the facade about as much as the sun (the
// window shows the facade alone): the sky's light off it is taken at z too, so the
// value is the one BSDF sampling finds, with far less noise.
TEST(ExteriorSun, TakesTheSkysLightOffTheFacadeToo) {
    const Scene scene =
        facadeScene(270, 20000).sampler("p", planarSampler({2, 2, 1.5}, {1, 0, 0}, {0, 0, 1}, {0.01, 0.01}, {1, 1}), 0).build();
    PathTracerOptions off;
    off.exteriorSun = false;
    SceneLab with(scene), without(scene, off);
    const SamplerResult a = with.measure(8000).samplers[0], b = without.measure(8000).samplers[0];
    EXPECT_NEAR(a.value, b.value, 4 * std::hypot(a.standardError, b.standardError))
        << a.standardError << " " << b.standardError;
    EXPECT_LT(a.standardError, 0.3 * b.standardError);
}

// Only where the sun can light a side of something outside that an opening sees:
// with the sun in the east the facade's lit side faces away (a box is never seen
// from inside); without anything outside there is nothing to follow.
TEST(ExteriorSun, OnlyWhereTheSunLightsWhatTheRoomSees) {
    EXPECT_TRUE(SceneLab(facadeScene(270).build()).tracer->samplesExteriorSun());
    EXPECT_FALSE(SceneLab(facadeScene(90).build()).tracer->samplesExteriorSun());
    const Scene nothingOutside = SceneBuilder()
                                     .material("white", test::diffuse(0.8))
                                     .sunAndUniformSky({40, 270, kSunNormalLx}, 1000, 0.2)
                                     .room({0, 0, 0}, {4, 4, 3}, "white", "white", "white")
                                     .window(Wall::East, 1.5, 1, 1, 1)
                                     .build();
    EXPECT_FALSE(SceneLab(nothingOutside).tracer->samplesExteriorSun());
}

// A white room behind a glazed window, the same facade and a brighter sky: the strategy
// only adds a way to the light BSDF sampling finds, so a desk, a wall point and a
// glare sampler facing the window read the same with and without it, with less noise.
TEST(ExteriorSun, LeavesEveryEstimateAsItWasWithLessNoise) {
    const Scene scene = SceneBuilder()
                            .material("wall", test::diffuse(0.7))
                            .material("white", test::diffuse(0.8))
                            .material("glass", test::glass(0.8))
                            .sunAndUniformSky({std::atan(2.0) * 180 / kPi, 270, kSunNormalLx}, 2000, 0.2)
                            .room({0, 0, 0}, {4, 4, 3}, "wall", "wall", "wall")
                            .window(Wall::East, 1, 2, 0.9, 1.5, "glass")
                            .box("facade", {10, -50, -20}, {12, 50, 40}, "white")
                            .sampler("desk", planarSampler({2.5, 2, 0.75}, {0, 0, 1}, {0, 1, 0}, {1, 0.6}, {2, 2}), 0)
                            .sampler("wall", planarSampler({0.01, 2, 1.5}, {1, 0, 0}, {0, 0, 1}, {0.1, 0.1}, {1, 1}), 0)
                            .sampler("glare", directionalSampler({1, 2, 1.2}, {1, 0, 0}, {0, 0, 1}, 60, 2), 0)
                            .build();
    PathTracerOptions off;
    off.exteriorSun = false;
    SceneLab with(scene), without(scene, off);
    const MeasureResult a = with.measure(4000), b = without.measure(4000);
    for (size_t k = 0; k < a.samplers.size(); ++k) {
        const SamplerResult &x = a.samplers[k], &y = b.samplers[k];
        EXPECT_NEAR(x.value, y.value, 4 * std::hypot(x.standardError, y.standardError))
            << scene.samplers[k].name << ": " << x.value << " +- " << x.standardError << " against " << y.value << " +- "
            << y.standardError;
        EXPECT_LT(x.standardError, 0.8 * y.standardError) << scene.samplers[k].name;
    }
}

}  // namespace
}  // namespace luxplan
