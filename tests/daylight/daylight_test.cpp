// buildDaylight: parameter validation, time steps, time averaging (average of the instants,
// exactly), fixed-sun overrides, site rotation, ground light.
#include <gtest/gtest.h>

#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/preetham.h>
#include "support/iso_time.h"

namespace luxplan {
namespace {

using test::at;

const Site kAthens{37.98, 23.73, 0};
const DaylightBakeOptions kSmall{64, 32, 2, {}};

DaylightParams preethamDay(const char* from, const char* to, double step) {
    DaylightParams p;
    p.turbidity = 3;
    p.from = at(from);
    if (to) p.to = at(to);
    p.stepMinutes = step;
    return p;
}

std::vector<std::string> messages(const DaylightParams& p, const Site& s = kAthens) {
    std::vector<std::string> out;
    for (const Diagnostic& d : validateDaylight(p, s)) out.push_back(d.jsonPath + ": " + d.message);
    return out;
}

bool hasMessage(const std::vector<std::string>& all, const std::string& m) {
    for (const std::string& s : all)
        if (s == m) return true;
    return false;
}

TEST(DaylightParams, ValidScenesHaveNoDiagnostics) {
    EXPECT_TRUE(messages(preethamDay("2026-06-21T09:00+03:00", "2026-06-21T12:00+03:00", 15)).empty());
    DaylightParams fixed;
    fixed.sunOverride = SunOverride{40, 180, 80000.0};
    EXPECT_TRUE(messages(fixed).empty());
    DaylightParams overcast;
    overcast.model = SkyModelType::CieOvercast;
    overcast.horizontalIlluminanceLx = 10000;
    EXPECT_TRUE(messages(overcast).empty());
    EXPECT_FALSE(overcast.sunEnabled());
    EXPECT_TRUE(preethamDay("2026-06-21T09:00+03:00", nullptr, 15).sunEnabled());
}

TEST(DaylightParams, EveryProblemIsReportedWithItsPath) {
    DaylightParams p = preethamDay("2026-06-21T12:00+03:00", "2026-06-21T09:00+03:00", 15);
    p.turbidity = 12;
    p.groundReflectance = 1.5;
    auto m = messages(p, Site{95, 0, 0});
    EXPECT_TRUE(hasMessage(m, "/daylight/sky/turbidity: turbidity 12 outside [1.7, 10]"));
    EXPECT_TRUE(hasMessage(m, "/daylight/ground_reflectance: ground_reflectance 1.5 outside [0, 1]"));
    EXPECT_TRUE(hasMessage(m, "/site/latitude: latitude 95 outside [-90, 90]"));
    EXPECT_TRUE(hasMessage(m, "/daylight/to: \"to\" 2026-06-21T09:00+03:00 is before \"from\" 2026-06-21T12:00+03:00"));
    EXPECT_EQ(m.size(), 4u);

    DaylightParams o;
    o.sunOverride = SunOverride{95, 400, -1.0};
    o.from = at("2026-06-21T09:00+03:00");
    m = messages(o);
    EXPECT_TRUE(hasMessage(m, "/daylight/sun/altitude_deg: altitude_deg 95 outside [0, 90]"));
    EXPECT_TRUE(hasMessage(m, "/daylight/sun/azimuth_deg: azimuth_deg 400 outside [0, 360]"));
    EXPECT_TRUE(hasMessage(m, "/daylight/sun/normal_illuminance_lx: normal_illuminance_lx -1 must be >= 0"));
    EXPECT_TRUE(hasMessage(m, "/daylight/sun: only one of \"sun\" override and \"from\"/\"to\""));

    DaylightParams overcast;
    overcast.model = SkyModelType::CieOvercast;
    overcast.sun = true;
    m = messages(overcast);
    EXPECT_TRUE(hasMessage(m, "/daylight/sky: sky model \"cie_overcast\" needs \"horizontal_illuminance_lx\""));
    EXPECT_TRUE(hasMessage(m, "/daylight/sun: sky model \"cie_overcast\" has no sun of its own; set \"sun\": false "
                              "or give a fixed sun with \"normal_illuminance_lx\""));

    DaylightParams noTime;
    m = messages(noTime);
    EXPECT_TRUE(hasMessage(m, "/daylight: sky model \"preetham\" needs a time (\"from\") or a fixed \"sun\" "
                              "{\"altitude_deg\", \"azimuth_deg\"}"));

    DaylightParams uniform;
    uniform.model = SkyModelType::Uniform;
    uniform.stepMinutes = 0;
    m = messages(uniform);
    EXPECT_TRUE(hasMessage(m, "/daylight/sky: sky model \"uniform\" needs \"luminance_nits\""));
    EXPECT_TRUE(hasMessage(m, "/daylight/step_minutes: step_minutes 0 must be > 0"));

    DaylightParams longRange = preethamDay("2026-01-01T00:00Z", "2027-12-31T00:00Z", 15);
    EXPECT_EQ(messages(longRange).size(), 1u);
    EXPECT_THROW(buildDaylight(longRange, kAthens, kSmall), SceneError);
    EXPECT_EQ(skyModelNames().parse("cie_overcast"), SkyModelType::CieOvercast);
    EXPECT_FALSE(skyModelNames().parse("gendaylit"));
    DaylightParams perez;
    perez.model = SkyModelType::Perez;  // without a weather file
    EXPECT_EQ(messages(perez), std::vector<std::string>{"/daylight/sky/model: sky model \"perez\" needs \"weather\" (an EPW file): it builds each hour's sky from the file"});
}

TEST(DaylightInstants, StepsFromFromToToInclusive) {
    auto steps = daylightInstants(preethamDay("2026-06-21T09:00+03:00", "2026-06-21T12:00+03:00", 15), kAthens);
    ASSERT_EQ(steps.size(), 13u);
    EXPECT_EQ(steps.front().time->str(), "2026-06-21T09:00+03:00");
    EXPECT_EQ(steps.back().time->str(), "2026-06-21T12:00+03:00");
    // `to` off the grid: the last step is the last one not after `to`.
    EXPECT_EQ(daylightInstants(preethamDay("2026-06-21T09:00+03:00", "2026-06-21T09:50+03:00", 15), kAthens).size(), 4u);
    EXPECT_EQ(daylightInstants(preethamDay("2026-06-21T09:00+03:00", nullptr, 15), kAthens).size(), 1u);
    // The sun climbs through the morning and its illuminance follows Preetham's model.
    for (size_t k = 1; k < steps.size(); ++k) EXPECT_GT(steps[k].sunAltitudeDeg, steps[k - 1].sunAltitudeDeg);
    const DaylightInstant& noon = steps.back();
    EXPECT_NEAR(noon.sunNormalIlluminanceLx, preethamSunNormalIlluminance(3, radians(90 - noon.sunAltitudeDeg)), 1e-9);
    EXPECT_NEAR(length(noon.sunDirection), 1.0, 1e-12);
}

// The bake's progress: one call per time step with the sun up (the dark one bakes
// nothing), in order, and the same map as without it.
TEST(DaylightBake, SaysHowManyOfItsStepsAreBaked) {
    DaylightParams p = preethamDay("2026-06-21T05:00+03:00", "2026-06-21T11:00+03:00", 120);
    std::vector<std::pair<int, int>> calls;
    DaylightBakeOptions options = kSmall;
    options.onStep = [&](int baked, int total) { calls.emplace_back(baked, total); };
    const DaylightEnvironment told = buildDaylight(p, kAthens, options);
    EXPECT_EQ(calls, (std::vector<std::pair<int, int>>{{1, 3}, {2, 3}, {3, 3}}));
    const DaylightEnvironment silent = buildDaylight(p, kAthens, kSmall);
    ASSERT_EQ(told.skyMap().pixels().size(), silent.skyMap().pixels().size());
    for (size_t k = 0; k < told.skyMap().pixels().size(); ++k)
        ASSERT_EQ(luminance(told.skyMap().pixels()[k]), luminance(silent.skyMap().pixels()[k]));
}

TEST(DaylightAverage, EqualsTheMeanOfItsInstants) {
    // 05:00..11:00 every 2 h in Athens (sunrise ~06:02): the 05:00 step is dark, the others not.
    DaylightParams p = preethamDay("2026-06-21T05:00+03:00", "2026-06-21T11:00+03:00", 120);
    DaylightEnvironment avg = buildDaylight(p, kAthens, kSmall);
    auto steps = daylightInstants(p, kAthens);
    ASSERT_EQ(steps.size(), 4u);
    EXPECT_LT(steps[0].sunAltitudeDeg, 0);
    double sky = 0, sun = 0, ground = 0, vertical = 0;
    std::vector<Vec3> meanPixels(avg.skyMap().pixels().size());
    for (const DaylightInstant& i : steps) {
        DaylightParams one = p;
        one.from = i.time;
        one.to.reset();
        DaylightEnvironment e = buildDaylight(one, kAthens, kSmall);
        sky += e.skyHorizontalIlluminance() / 4;
        sun += e.sunHorizontalIlluminance() / 4;
        ground += e.groundLuminance() / 4;
        vertical += e.illuminance({0, -1, 0}) / 4;
        for (size_t k = 0; k < meanPixels.size(); ++k) meanPixels[k] += e.skyMap().pixels()[k] * 0.25;
    }
    EXPECT_GT(sun, 0);
    EXPECT_NEAR(avg.skyHorizontalIlluminance(), sky, 1e-9 * sky);
    EXPECT_NEAR(avg.sunHorizontalIlluminance(), sun, 1e-9 * sun);
    EXPECT_NEAR(avg.totalHorizontalIlluminance(), sky + sun, 1e-9 * (sky + sun));
    EXPECT_NEAR(avg.groundLuminance(), ground, 1e-9 * ground);
    EXPECT_NEAR(avg.illuminance({0, -1, 0}), vertical, 1e-9 * vertical);
    for (size_t k = 0; k < meanPixels.size(); ++k)
        ASSERT_NEAR(luminance(avg.skyMap().pixels()[k]), luminance(meanPixels[k]), 1e-9 * (1 + luminance(meanPixels[k])));
    // One sharp disk per step with the sun up, each weighted 1/4.
    ASSERT_EQ(avg.sunDisks().size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
        const SunDisk& d = avg.sunDisks()[k];
        EXPECT_DOUBLE_EQ(d.weight, 0.25);
        EXPECT_NEAR(d.normalIlluminanceLx, steps[k + 1].sunNormalIlluminanceLx, 1e-9);
        EXPECT_NEAR(d.luminance * kSunDiskProjectedSolidAngle, 0.25 * d.normalIlluminanceLx, 1e-6);
        EXPECT_NEAR(length(d.direction - steps[k + 1].sunDirection), 0, 1e-12);
    }
}

TEST(DaylightOverride, FixedSunWithGivenIlluminanceAndSiteRotation) {
    DaylightParams p;
    p.sunOverride = SunOverride{30, 90, 80000.0};  // east, 30 deg up
    DaylightEnvironment e = buildDaylight(p, Site{10, 20, 90}, kSmall);
    ASSERT_EQ(e.sunDisks().size(), 1u);
    const SunDisk& d = e.sunDisks()[0];
    // north_deg 90: scene +y points east, so the sun lies in the y-z plane.
    EXPECT_NEAR(d.direction.x, 0, 1e-12);
    EXPECT_NEAR(d.direction.y, std::cos(radians(30)), 1e-12);
    EXPECT_NEAR(d.direction.z, 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(d.weight, 1.0);
    EXPECT_NEAR(e.sunHorizontalIlluminance(), 80000 * 0.5, 1e-6);
    EXPECT_GT(e.sunLv(d.direction), 1e9);  // ~1.2e9 cd/m^2
    // The sky is brightest towards the sun: compare the sun side with the opposite side.
    EXPECT_GT(e.Lv(normalize(Vec3(0, 1, 0.7))), 2 * e.Lv(normalize(Vec3(0, -1, 0.7))));
    // Ground: rho (E_sky + E_sun) / pi.
    EXPECT_NEAR(e.groundLuminance(), 0.2 * e.totalHorizontalIlluminance() / kPi, 1e-9 * e.groundLuminance());
    EXPECT_NEAR(e.Lv({0.2, 0.1, -0.5}), e.groundLuminance(), 1e-9 * e.groundLuminance());
    // Without normal_illuminance_lx the sun comes from Preetham's model.
    p.sunOverride->normalIlluminanceLx.reset();
    DaylightEnvironment q = buildDaylight(p, Site{10, 20, 90}, kSmall);
    EXPECT_NEAR(q.sunDisks()[0].normalIlluminanceLx, preethamSunNormalIlluminance(3, radians(60)), 1e-9);
    // "sun": false keeps the sky and drops the disk.
    p.sun = false;
    p.sunOverride.reset();
    p.from = at("2026-06-21T12:00+03:00");
    DaylightEnvironment noSun = buildDaylight(p, kAthens, kSmall);
    EXPECT_FALSE(noSun.hasSun());
    EXPECT_GT(noSun.skyHorizontalIlluminance(), 10000);
}

TEST(DaylightPreetham, BakedZenithMatchesTheModel) {
    DaylightParams p;
    p.turbidity = 4;
    p.sunOverride = SunOverride{50, 200, std::nullopt};
    DaylightEnvironment e = buildDaylight(p, Site{}, {512, 256, 2, {}});
    // The top row averages a 0.7 deg cap; the zenith luminance varies slowly there.
    double yz = preethamZenithLuminance(4, radians(40));
    EXPECT_NEAR(e.Lv({0, 0, 1}), yz, 0.01 * yz);
    // Sun-up skies at sea level: diffuse horizontal illuminance of order 10-40 klx.
    EXPECT_GT(e.skyHorizontalIlluminance(), 10000);
    EXPECT_LT(e.skyHorizontalIlluminance(), 40000);
}

TEST(DaylightNight, DarkSkyAndNoSun) {
    DaylightEnvironment e = buildDaylight(preethamDay("2026-06-21T01:00+03:00", nullptr, 15), kAthens, kSmall);
    EXPECT_FALSE(e.hasSun());
    EXPECT_FALSE(e.hasSky());
    EXPECT_EQ(e.totalHorizontalIlluminance(), 0.0);
    EXPECT_EQ(e.sampleSun(0.3, {0.2, 0.1}).pdf, 0.0);
}

TEST(DaylightCieGeneral, SkyGivesItsIlluminanceAndSunComesFromTurbidity) {
    DaylightParams p;
    p.model = SkyModelType::CieGeneral;
    p.cieSkyType = 12;
    p.horizontalIlluminanceLx = 15000;
    p.sunOverride = SunOverride{45, 180, std::nullopt};
    DaylightEnvironment e = buildDaylight(p, Site{}, {256, 128, 2, {}});
    EXPECT_NEAR(e.skyHorizontalIlluminance(), 15000, 0.01 * 15000);
    ASSERT_TRUE(e.hasSun());
    EXPECT_NEAR(e.sunDisks()[0].normalIlluminanceLx, preethamSunNormalIlluminance(3, radians(45)), 1e-9);
}

}  // namespace

// Issue 58 reported a period starting at a fractional second hanging measure. Its
// instants are those of the grid from `from`, and the bake ends.
namespace fractional_period {

TEST(DaylightFractionalSeconds, ThePeriodsInstantsAndItsBake) {
    auto steps = daylightInstants(preethamDay("2026-06-21T09:00:00.5+03:00", "2026-06-21T12:00+03:00", 15), kAthens);
    ASSERT_EQ(steps.size(), 12u);  // 12:00:00.5 is after `to`
    EXPECT_EQ(steps.front().time->str(), "2026-06-21T09:00:00.500+03:00");
    EXPECT_EQ(steps.back().time->str(), "2026-06-21T11:45:00.500+03:00");
    EXPECT_EQ(daylightInstants(preethamDay("2026-06-21T09:00:00.5+03:00", "2026-06-21T12:00:00.5+03:00", 15), kAthens).size(),
              13u);
    const DaylightEnvironment env =
        buildDaylight(preethamDay("2026-06-21T09:00:00.5Z", nullptr, 15), kAthens, kSmall);
    EXPECT_TRUE(env.hasSun());
    EXPECT_GT(env.sunHorizontalIlluminance(), 0);
}

}  // namespace fractional_period
}  // namespace luxplan
