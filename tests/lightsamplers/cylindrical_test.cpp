// The cylindrical sampler against analytic truth: under a uniform sky of luminance L
// over a black ground, E_z = (1/pi) * L * integral over the upper hemisphere of
// sin(theta) d omega = pi L / 2; under a point source, E_z relative to the horizontal
// illuminance at the same point is tan(theta) / pi, whatever the source's intensity.
#include <gtest/gtest.h>

#include "support/lab.h"

namespace luxplan {
namespace {

TEST(CylindricalSampler, UniformSkyGivesPiLOverTwo) {
    test::Lab lab(R"({"luxplan": 1, "daylight": {"sky": {"model": "uniform", "luminance_nits": 2000}, "sun": false, "ground_reflectance": 0},
      "samplers": [{"name": "face", "type": "cylindrical", "center": [0, 0, 1.2], "target": [150, null]}]})");
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
    test::Lab lab(R"({"luxplan": 1, "materials": {"black": {"type": "diffuse", "reflectance": 0}},
      "luminaires": [{"name": "bulb", "shape": "sphere", "center": [1.5, 0, 3], "radius": 0.01, "flux_lm": 1000}],
      "samplers": [{"name": "face", "type": "cylindrical", "center": [0, 0, 1], "target": [0, null]},
                   {"name": "plane", "type": "planar", "center": [0, 0, 1], "size": [0.001, 0.001], "grid": [1, 1], "target": [0, null]}]})");
    auto r = lab.measure(20000);
    double ez = r.samplers[0].value, eh = r.samplers[1].value;
    double sigma = std::hypot(r.samplers[0].standardError / eh, ez * r.samplers[1].standardError / (eh * eh));
    EXPECT_NEAR(ez / eh, 0.75 / kPi, 4 * sigma + 1e-3);
}

TEST(CylindricalSampler, ReadsOnlyItsCentre) {
    test::TempDir dir;
    auto file = dir.write("scene.json", R"({"luxplan": 1,
      "samplers": [{"name": "face", "type": "cylindrical", "center": [0, 0, 1.2], "normal": [0, 0, 1], "target": [150, null]}]})");
    try {
        io::loadScene(file);
        FAIL() << "a cylindrical sampler has no normal";
    } catch (const SceneError& e) {
        ASSERT_EQ(e.diagnostics().size(), 1u);
        EXPECT_EQ(e.diagnostics()[0].jsonPath + ": " + e.diagnostics()[0].message,
                  "/samplers/0/normal: \"normal\" does not apply to a cylindrical sampler");
    }
}

}  // namespace
}  // namespace luxplan
