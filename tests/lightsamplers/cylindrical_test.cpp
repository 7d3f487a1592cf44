// The cylindrical sampler against analytic truth: under a uniform sky of luminance L
// over a black ground, E_z = (1/pi) * L * integral over the upper hemisphere of
// sin(theta) d omega = pi L / 2; under a point source, E_z relative to the horizontal
// illuminance at the same point is tan(theta) / pi, whatever the source's intensity.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

TEST(CylindricalSampler, UniformSkyGivesPiLOverTwo) {
    test::SceneLab lab(test::SceneBuilder().uniformSky(2000).sampler("face", cylindricalSampler({0, 0, 1.2}), 150).build());
    SamplerResult r = lab.measure(20000).samplers[0];
    const double expected = kPi * 2000 / 2;
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 1e-3 * expected) << "standard error " << r.standardError;
    EXPECT_GT(r.standardError, 0);
    EXPECT_LT(r.standardError, 0.01 * expected);
}

TEST(CylindricalSampler, SmallLampAgainstHorizontalIlluminance) {
    // A 1 cm sphere at height 2 m above and 1.5 m beside the point, in a black void: a
    // point source. E_h = I cos(theta) / r^2 and E_z = I sin(theta) / (pi r^2), so
    // E_z / E_h = tan(theta) / pi with tan(theta) = 1.5 / 2.
    test::SceneLab lab(test::SceneBuilder()
                           .material("black", test::diffuse(0))
                           .emitter("bulb", sphereEmitter({1.5, 0, 3}, 0.01), 1000)
                           .sampler("face", cylindricalSampler({0, 0, 1}), 0)
                           .sampler("plane", planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0.001, 0.001}, {1, 1}), 0)
                           .build());
    auto r = lab.measure(20000);
    double ez = r.samplers[0].value, eh = r.samplers[1].value;
    double sigma = std::hypot(r.samplers[0].standardError / eh, ez * r.samplers[1].standardError / (eh * eh));
    EXPECT_NEAR(ez / eh, 0.75 / kPi, 4 * sigma + 1e-3);
}

// Its reader asks for the centre and nothing else (tests/io/sampler_loader_test.cpp:
// the loader reports any other key as not applying to it).
TEST(CylindricalSampler, ReadsOnlyItsCentre) {
    const SamplerTypeEntry* entry = findSamplerType("cylindrical");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(json::probeKeys([&](const json::Fields& f) { entry->read(f); }), std::vector<std::string>{"center"});
    EXPECT_EQ(cylindricalSampler({0, 0, 1.2})->describe(), "cylindrical illuminance at a point");
}

}  // namespace
}  // namespace luxplan
