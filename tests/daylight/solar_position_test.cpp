// The NREL SPA against its published worked example, pvlib's reference values and
// NREL's sunrise/transit/sunset tables; delta T; horizon <-> scene conversions.
#include <gtest/gtest.h>

#include <luxplan/daylight/solar_position.h>
#include "support/iso_time.h"

namespace luxplan {
namespace {

using test::at;

// Golden, Colorado: the site of NREL's example (Reda and Andreas 2004; docs/daylight.md, "Validation").
SolarObserver golden() {
    SolarObserver o;
    o.latitudeDeg = 39.742476;
    o.longitudeDeg = -105.1786;
    o.elevationM = 1830.14;
    o.pressureMbar = 820;
    o.temperatureC = 11;
    o.deltaTSeconds = 67;
    return o;
}

double wrap180(double deg) {
    double r = std::fmod(deg + 180.0, 360.0);
    return (r < 0 ? r + 360.0 : r) - 180.0;
}

TEST(SolarPosition, NrelWorkedExampleIntermediateValues) {
    SolarPosition p = solarPosition(at("2003-10-17T12:30:30-07:00"), golden());
    EXPECT_NEAR(p.julianDay, 2452930.312847, 1e-6);
    EXPECT_NEAR(p.julianEphemerisDay, 2452930.313623, 1e-6);
    EXPECT_NEAR(p.heliocentricLongitudeDeg, 24.0182616917, 1e-6);
    EXPECT_NEAR(p.heliocentricLatitudeDeg, -0.0001011219, 1e-9);
    EXPECT_NEAR(p.earthSunDistanceAU, 0.9965422974, 1e-9);
    EXPECT_NEAR(p.nutationLongitudeDeg, -0.00399840, 1e-8);
    EXPECT_NEAR(p.nutationObliquityDeg, 0.00166657, 1e-8);
    EXPECT_NEAR(p.trueObliquityDeg, 23.440465, 1e-6);
    EXPECT_NEAR(p.apparentSunLongitudeDeg, 204.0085519281, 1e-6);
    EXPECT_NEAR(p.rightAscensionDeg, 202.227408, 1e-6);
    EXPECT_NEAR(p.declinationDeg, -9.31434, 1e-5);
    EXPECT_NEAR(p.hourAngleDeg, 11.105902, 1e-5);
    EXPECT_NEAR(p.topocentricRightAscensionDeg, 202.22704, 1e-5);
    EXPECT_NEAR(p.topocentricDeclinationDeg, -9.316179, 1e-6);
    EXPECT_NEAR(p.topocentricHourAngleDeg, 11.10627, 1e-5);
    EXPECT_NEAR(p.trueAltitudeDeg, 39.872046, 1e-6);
    EXPECT_NEAR(p.refractionDeg, 0.016332, 1e-6);
}

TEST(SolarPosition, NrelWorkedExampleZenithAzimuth) {
    // spa_tester.c: zenith 50.111622, azimuth 194.340241 (required: 0.01 deg; SPA gives 1e-6).
    SolarPosition p = solarPosition(at("2003-10-17T12:30:30-07:00"), golden());
    EXPECT_NEAR(p.zenithDeg, 50.111622, 1e-5);
    EXPECT_NEAR(p.altitudeDeg, 39.888378, 1e-5);
    EXPECT_NEAR(p.azimuthDeg, 194.340241, 1e-5);
    // The same instant written in UTC or in daylight time gives the same position.
    SolarPosition q = solarPosition(at("2003-10-17T19:30:30Z"), golden());
    SolarPosition r = solarPosition(at("2003-10-17T13:30:30-06:00"), golden());
    EXPECT_DOUBLE_EQ(q.azimuthDeg, p.azimuthDeg);
    EXPECT_DOUBLE_EQ(r.altitudeDeg, p.altitudeDeg);
}

TEST(SolarPosition, PvlibSecondDay) {
    // pvlib test_solarposition.py, expected_solpos_multi, 2003-10-18 12:30:30 MST.
    SolarPosition p = solarPosition(at("2003-10-18T12:30:30-07:00"), golden());
    EXPECT_NEAR(p.trueAltitudeDeg, 39.505196, 1e-4);
    EXPECT_NEAR(p.zenithDeg, 50.478260, 1e-4);
    EXPECT_NEAR(p.azimuthDeg, 194.311132, 1e-4);
}

// NREL SPA calculator rise/transit/set times (as quoted by pvlib's test_solarposition.py,
// delta T 65 s). SPA defines sunrise/sunset as the geocentric altitude of the sun's centre
// reaching -0.8333 deg and transit as local hour angle 0; the times are rounded to the
// second, which moves these angles by at most ~0.003 deg. SPA's rise/set routine interpolates
// ephemerides within the UT day; for an event past 24h UT (Golden's August sunset,
// 02:13:58 UT next day) its time is off by ~63 s (USNO via pvlib: 19:13 +-30 s, where this
// SPA puts the -0.8333 deg crossing at 19:12:55), so that event is not used here.
struct RiseSetCase {
    double lat, lon;
    const char* sunrise;
    const char* transit;
    const char* sunset;
};

class SolarRiseSet : public ::testing::TestWithParam<RiseSetCase> {};

double geocentricAltitude(const SolarPosition& p, double latDeg) {
    double phi = radians(latDeg), d = radians(p.declinationDeg), h = radians(p.hourAngleDeg);
    return degrees(std::asin(std::sin(phi) * std::sin(d) + std::cos(phi) * std::cos(d) * std::cos(h)));
}

TEST_P(SolarRiseSet, MatchesNrelCalculator) {
    const RiseSetCase& c = GetParam();
    SolarObserver o;
    o.latitudeDeg = c.lat;
    o.longitudeDeg = c.lon;
    o.deltaTSeconds = 65;
    SolarPosition rise = solarPosition(at(c.sunrise), o);
    SolarPosition transit = solarPosition(at(c.transit), o);
    EXPECT_NEAR(geocentricAltitude(rise, c.lat), -0.8333, 0.01) << c.sunrise;
    if (c.sunset) {
        SolarPosition set = solarPosition(at(c.sunset), o);
        EXPECT_NEAR(geocentricAltitude(set, c.lat), -0.8333, 0.01) << c.sunset;
        EXPECT_GT(set.azimuthDeg, 180.0);
    }
    EXPECT_NEAR(wrap180(transit.hourAngleDeg), 0.0, 0.01) << c.transit;
    EXPECT_LT(rise.azimuthDeg, 180.0);  // rising in the east
}

INSTANTIATE_TEST_SUITE_P(
    NrelCalculator, SolarRiseSet,
    ::testing::Values(
        RiseSetCase{39.742476, -105.1786, "2015-01-02T07:21:55-07:00", "2015-01-02T12:04:45-07:00",
                    "2015-01-02T16:47:43-07:00"},
        RiseSetCase{39.742476, -105.1786, "2015-08-02T05:00:27-07:00", "2015-08-02T12:06:58-07:00", nullptr},
        RiseSetCase{-35.0, 0.0, "1996-07-05T07:08:15Z", "1996-07-05T12:04:36Z", "1996-07-05T17:01:04Z"},
        RiseSetCase{-35.0, 0.0, "2004-12-04T04:38:57Z", "2004-12-04T11:50:22Z", "2004-12-04T19:02:03Z"}));

TEST(SolarPosition, TransitAzimuthFacesTheEquator) {
    SolarObserver north;
    north.latitudeDeg = 37.98;
    north.longitudeDeg = 23.73;
    // Athens, solar noon on 2026-06-21 is near 12:25 local (+03:00): sun due south.
    SolarPosition p = solarPosition(at("2026-06-21T13:25+03:00"), north);
    EXPECT_NEAR(p.azimuthDeg, 180.0, 3.0);
    EXPECT_NEAR(p.altitudeDeg, 90 - 37.98 + 23.44, 0.2);
    SolarObserver south;
    south.latitudeDeg = -33.87;
    south.longitudeDeg = 151.21;
    SolarPosition s = solarPosition(at("2026-06-21T11:57+10:00"), south);
    EXPECT_NEAR(wrap180(s.azimuthDeg), 0.0, 3.0);
}

TEST(SolarPosition, RefractionUsesPressureAndTemperature) {
    SolarObserver o = golden();
    SolarPosition p = solarPosition(at("2003-10-17T12:30:30-07:00"), o);
    o.pressureMbar = 1010;
    o.temperatureC = 10;
    SolarPosition q = solarPosition(at("2003-10-17T12:30:30-07:00"), o);
    EXPECT_NEAR(q.refractionDeg / p.refractionDeg, (1010.0 / 820) * (284.0 / 283.0), 1e-12);
    // Far below the horizon no refraction is applied.
    SolarPosition night = solarPosition(at("2003-10-17T00:30:00-07:00"), o);
    EXPECT_LT(night.altitudeDeg, -10);
    EXPECT_EQ(night.refractionDeg, 0.0);
}

TEST(DeltaT, EspenakMeeusPolynomials) {
    // Observed values (Espenak & Meeus 2006 Table 1): 1950 29.07, 1970 40.18, 1990 56.86, 2000 63.83, 2005 64.69.
    EXPECT_NEAR(deltaTSeconds(1950.0), 29.07, 0.05);
    EXPECT_NEAR(deltaTSeconds(1970.0), 40.18, 0.3);
    EXPECT_NEAR(deltaTSeconds(1990.0), 56.86, 0.1);
    EXPECT_NEAR(deltaTSeconds(2000.0), 63.83, 0.1);
    EXPECT_NEAR(deltaTSeconds(2005.0), 64.69, 0.1);
    // Continuity at the polynomial joins (within a second).
    for (double y : {1920.0, 1941.0, 1961.0, 1986.0, 2005.0, 2050.0, 2150.0})
        EXPECT_NEAR(deltaTSeconds(y - 1e-9), deltaTSeconds(y), 1.0) << y;
    // With the default delta T the NREL example moves by far less than 0.01 deg.
    SolarObserver o = golden();
    o.deltaTSeconds.reset();
    SolarPosition p = solarPosition(at("2003-10-17T12:30:30-07:00"), o);
    EXPECT_NEAR(p.deltaTSeconds, 64.5, 0.5);
    EXPECT_NEAR(p.zenithDeg, 50.111622, 0.01);
    EXPECT_NEAR(p.azimuthDeg, 194.340241, 0.01);
}

TEST(HorizonScene, NorthAndEastAxes) {
    auto near = [](const Vec3& a, const Vec3& b) { return length(a - b) < 1e-12; };
    EXPECT_TRUE(near(horizonToScene(0, 0, 0), {0, 1, 0}));     // north = +y
    EXPECT_TRUE(near(horizonToScene(0, 90, 0), {1, 0, 0}));    // east = +x
    EXPECT_TRUE(near(horizonToScene(90, 123, 40), {0, 0, 1}));  // zenith = +z
    // north_deg = 90: scene +y points east, so an eastern sun lies along +y and north along -x.
    EXPECT_TRUE(near(horizonToScene(0, 90, 90), {0, 1, 0}));
    EXPECT_TRUE(near(horizonToScene(0, 0, 90), {-1, 0, 0}));
    for (double alt : {-30.0, 0.0, 12.5, 60.0})
        for (double az : {0.0, 45.0, 181.0, 359.0}) {
            HorizonAngles h = sceneToHorizon(horizonToScene(alt, az, 30), 30);
            EXPECT_NEAR(h.altitudeDeg, alt, 1e-9);
            EXPECT_NEAR(wrap180(h.azimuthDeg - az), 0, 1e-9);
        }
}

}  // namespace
}  // namespace luxplan
