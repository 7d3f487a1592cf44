// The Perez all-weather sky (1993) and the Perez 1990 luminous efficacies
// (daylight/perez_sky.h): the published tables at known points, the formulas against
// hand computations, the sky's own consistency, and (with a weather file) an open field
// over Chicago's TMY3 year against the file's measured global illuminance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/perez_sky.h>
#include <luxplan/daylight/weather.h>

namespace luxplan::perez_sky_test {
namespace {

Vec3 skyDirection(double zenithDeg, double azimuthDeg) {
    const double t = radians(zenithDeg), p = radians(azimuthDeg);
    return {std::sin(t) * std::sin(p), std::sin(t) * std::cos(p), std::cos(t)};
}

PerezSkyInput hour(double directNormal, double diffuseHorizontal, double zenithDeg, int day = 80) {
    PerezSkyInput in;
    in.directNormalWm2 = directNormal;
    in.diffuseHorizontalWm2 = diffuseHorizontal;
    in.sunZenithDeg = zenithDeg;
    in.dayOfYear = day;
    return in;
}

// Horizontal illuminance of a sky by a quadrature independent of the sky's own: midpoint
// rule in (theta, phi) over the whole hemisphere, 384 x 768 cells.
double horizontalIlluminance(const PerezAllWeatherSky& sky) {
    const int nt = 384, np = 768;
    double sum = 0;
    for (int i = 0; i < nt; ++i) {
        const double t = (i + 0.5) * (kPi / 2) / nt;
        double row = 0;
        for (int j = 0; j < np; ++j) row += sky.luminance(skyDirection(degrees(t), (j + 0.5) * 360.0 / np));
        sum += row * std::cos(t) * std::sin(t);
    }
    return sum * (kPi / 2 / nt) * (2 * kPi / np);
}

TEST(PerezSky, AirMassEccentricityAndWaterAtHandComputedValues) {
    // Kasten (1966): m = 1 / (cos Z + 0.15 (93.885 - Z)^-1.253), evaluated by hand.
    EXPECT_NEAR(perezAirMass(0), 1 / (1 + 0.15 * std::pow(93.885, -1.253)), 1e-12);
    EXPECT_NEAR(perezAirMass(60), 1.99276, 1e-4);   // the secant gives 2
    EXPECT_NEAR(perezAirMass(85), 10.3231, 1e-3);   // the secant gives 11.47
    EXPECT_DOUBLE_EQ(perezAirMass(95), perezAirMass(90));  // limited to the horizon
    // Spencer (1971): 1.035 near perihelion (3 January), 0.967 near aphelion (4 July).
    EXPECT_NEAR(perezEccentricity(3), 1.0350, 1e-3);
    EXPECT_NEAR(perezEccentricity(185), 0.9670, 1e-3);
    // W = exp(0.07 Td - 0.075): gendaylit's default dew point 10.97353115 C gives its 2 cm.
    EXPECT_NEAR(perezPrecipitableWater(10.97353115), 2.0, 1e-7);
    EXPECT_NEAR(perezPrecipitableWater(0), std::exp(-0.075), 1e-12);
    EXPECT_DOUBLE_EQ(perezPrecipitableWater(std::nan("")), 2.0);
    EXPECT_DOUBLE_EQ(perezPrecipitableWater(55), 2.0);
}

TEST(PerezSky, ClearnessBrightnessAndBins) {
    // Edn 800, Edh 100, Z 30 deg: 1.041 Z^3 = 0.149424; epsilon = (9 + k)/(1 + k).
    const double k = 1.041 * std::pow(kPi / 6, 3);
    EXPECT_NEAR(perezClearness(800, 100, 30), (9 + k) / (1 + k), 1e-12);
    EXPECT_NEAR(perezClearness(800, 100, 30), 7.95999, 1e-4);
    EXPECT_DOUBLE_EQ(perezClearness(0, 100, 50), 1.0);  // no beam: overcast
    // Delta = Edh m / (1367 E0): on day 1, E0 = 1.00011 + 0.034221 + 0.000719.
    EXPECT_NEAR(perezBrightness(100, 60, 1), 100 * perezAirMass(60) / (1367 * 1.03505), 1e-9);
    // Bin edges of Perez et al. 1990 / 1993: 1, 1.065, 1.23, 1.5, 1.95, 2.8, 4.5, 6.2.
    EXPECT_EQ(perezClearnessBin(1.0), 1);
    EXPECT_EQ(perezClearnessBin(1.0649), 1);
    EXPECT_EQ(perezClearnessBin(1.065), 2);
    EXPECT_EQ(perezClearnessBin(1.3), 3);
    EXPECT_EQ(perezClearnessBin(1.95), 5);
    EXPECT_EQ(perezClearnessBin(4.4999), 6);
    EXPECT_EQ(perezClearnessBin(6.2), 8);
    EXPECT_EQ(perezClearnessBin(12), 8);
}

TEST(PerezSky, CoefficientsAtKnownPointsOfThe1993Table) {
    // At Z = 0, Delta = 0 each coefficient is its table's x1 (Perez et al. 1993, Table 1).
    const auto clear = perezCoefficients(8, 0, 0);
    const double bin8[5] = {-1.0500, -0.3250, 31.0625, -7.2312, 1.5000};
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(clear[size_t(i)], bin8[i], 1e-12) << i;
    // Bin 6, Z = 1 rad, Delta = 0.3: x1 + x2 + 0.3 (x3 + x4), row by row of the table.
    const auto b6 = perezCoefficients(6, 1.0, 0.3);
    EXPECT_NEAR(b6[0], -1.0156 - 0.3670 + 0.3 * (1.0078 + 1.4051), 1e-12);
    EXPECT_NEAR(b6[1], 0.2875 - 0.5328 + 0.3 * (-3.8500 + 3.3750), 1e-12);
    EXPECT_NEAR(b6[2], 14.0000 - 0.9999 + 0.3 * (-7.1406 + 7.5469), 1e-12);
    EXPECT_NEAR(b6[3], -3.4000 - 0.1078 + 0.3 * (-1.0750 + 1.5702), 1e-12);
    EXPECT_NEAR(b6[4], -0.0672 + 0.4016 + 0.3 * (0.3017 - 0.4844), 1e-12);
    // Bin 1's c and d: c = exp((Delta (c1 + c2 Z))^c3) - c4, d = -exp(Delta (d1 + d2 Z)) + d3 + Delta d4.
    const auto b1 = perezCoefficients(1, 0.5, 0.3);
    EXPECT_NEAR(b1[0], 1.3525 - 0.2576 * 0.5 + 0.3 * (-0.2690 - 1.4366 * 0.5), 1e-12);
    EXPECT_NEAR(b1[2], std::exp(std::pow(0.3 * (2.8000 + 0.6004 * 0.5), 1.2375)) - 1.0000, 1e-12);
    EXPECT_NEAR(b1[3], -std::exp(0.3 * (1.8734 + 0.6297 * 0.5)) + 0.9738 + 0.3 * 0.2809, 1e-12);
    EXPECT_NEAR(b1[4], 0.0356 - 0.1246 * 0.5 + 0.3 * (-0.5718 + 0.9938 * 0.5), 1e-12);
    // gendaylit's correction: in bins 2..5 a brightness below 0.2 counts as 0.2; not in 6..8.
    for (int bin : {2, 3, 4, 5}) EXPECT_EQ(perezCoefficients(bin, 0.7, 0.05), perezCoefficients(bin, 0.7, 0.2)) << bin;
    EXPECT_NE(perezCoefficients(6, 0.7, 0.05), perezCoefficients(6, 0.7, 0.2));
    EXPECT_NE(perezCoefficients(1, 0.7, 0.05), perezCoefficients(1, 0.7, 0.2));
}

TEST(PerezSky, LuminousEfficaciesOfPerez1990) {
    // Table 4 of Perez et al. 1990 by hand: bin 1 diffuse a + b W + c cos Z + d ln Delta.
    EXPECT_NEAR(perezDiffuseEfficacy(1, 2, 60, 0.2), 97.24 - 0.46 * 2 + 12.00 * 0.5 - 8.91 * std::log(0.2), 1e-9);
    EXPECT_NEAR(perezDiffuseEfficacy(8, 1.5, 0, 0.1), 152.23 + 0.35 * 1.5 - 45.27 - 7.98 * std::log(0.1), 1e-9);
    EXPECT_NEAR(perezGlobalEfficacy(5, 2, 60, 0.2), 86.73 + 0.98 * 2 + 7.10 * 0.5 - 10.94 * std::log(0.2), 1e-9);
    // Direct: a + b W + c exp(5.73 Z - 5) + d Delta.
    EXPECT_NEAR(perezDirectEfficacy(8, 2, 30, 0.15),
                101.18 + 1.58 * 2 - 1.10 * std::exp(5.73 * kPi / 6 - 5) - 8.29 * 0.15, 1e-9);
    EXPECT_NEAR(perezDirectEfficacy(8, 2, 30, 0.15), 102.948, 0.001);
    // Bin 1's direct efficacy at a low sun goes negative in the fit and is held at 0.
    EXPECT_DOUBLE_EQ(perezDirectEfficacy(1, 4, 89, 0.05), 0.0);
    // The papers' orders of magnitude: daylight diffuse 100-150 lm/W, a clear sun ~100 lm/W.
    for (int bin = 1; bin <= 8; ++bin) {
        const double d = perezDiffuseEfficacy(bin, 2, 40, 0.2);
        EXPECT_GT(d, 95);
        EXPECT_LT(d, 150);
    }
}

TEST(PerezSky, HourFromIrradiances) {
    // A clear noon: Edn 850, Edh 90, Z 30, day 172, dew point 12 C.
    PerezSkyInput in = hour(850, 90, 30, 172);
    in.dewPointC = 12;
    const PerezSkyCondition c = perezSkyCondition(in);
    ASSERT_TRUE(c.lit);
    const double k = 1.041 * std::pow(kPi / 6, 3);
    EXPECT_NEAR(c.epsilon, (940.0 / 90 + k) / (1 + k), 1e-12);
    EXPECT_EQ(c.bin, 8);
    EXPECT_NEAR(c.delta, 90 * perezAirMass(30) / (1367 * perezEccentricity(172)), 1e-12);
    EXPECT_NEAR(c.precipitableWaterCm, std::exp(0.07 * 12 - 0.075), 1e-12);
    EXPECT_NEAR(c.diffuseHorizontalLx, 90 * perezDiffuseEfficacy(8, c.precipitableWaterCm, 30, c.delta), 1e-9);
    EXPECT_NEAR(c.directNormalLx, 850 * perezDirectEfficacy(8, c.precipitableWaterCm, 30, c.delta), 1e-9);
    EXPECT_EQ(c.coefficients, perezCoefficients(8, radians(30), c.delta));
    // Limits (gendaylit): epsilon below 12.01, Delta in [0.01, 0.6].
    const PerezSkyCondition beamOnly = perezSkyCondition(hour(500, 0, 40));
    EXPECT_TRUE(beamOnly.lit);
    EXPECT_NEAR(beamOnly.epsilon, 12.009, 1e-12);
    EXPECT_DOUBLE_EQ(beamOnly.delta, 0.01);
    EXPECT_DOUBLE_EQ(beamOnly.diffuseHorizontalLx, 0.0);
    EXPECT_GT(beamOnly.directNormalLx, 0.0);
    EXPECT_DOUBLE_EQ(perezSkyCondition(hour(0, 600, 80)).delta, 0.6);
    EXPECT_DOUBLE_EQ(perezSkyCondition(hour(0, 0.1, 30)).delta, 0.01);
    // A sun above 87 deg is taken at 87 deg by the formulas.
    EXPECT_DOUBLE_EQ(perezSkyCondition(hour(800, 100, 1)).epsilon, perezSkyCondition(hour(800, 100, 3)).epsilon);
    // Dark skies: the sun down, nothing measured, a beam above the solar constant.
    EXPECT_FALSE(perezSkyCondition(hour(100, 50, 90.5)).lit);
    EXPECT_FALSE(perezSkyCondition(hour(0, 0, 40)).lit);
    EXPECT_FALSE(perezSkyCondition(hour(1400, 50, 40)).lit);
    EXPECT_EQ(PerezAllWeatherSky(perezSkyCondition(hour(0, 0, 40)), {0, 0.5, 0.8}).luminance({0, 0, 1}), 0.0);
}

// Hours of every bin, at a high and a low sun.
std::vector<PerezSkyInput> hoursOfEveryBin() {
    std::vector<PerezSkyInput> out;
    for (double z : {25.0, 70.0})
        for (double ratio : {0.0, 0.1, 0.3, 0.6, 1.2, 2.5, 4.5, 9.0})  // Edn / Edh: epsilon ~ 1 + ratio
            out.push_back(hour(120 * ratio, 120, z, 100));
    return out;
}

TEST(PerezSky, SkyGivesTheDiffuseIlluminanceOnAHorizontalPlane) {
    std::vector<int> bins;
    for (const PerezSkyInput& in : hoursOfEveryBin()) {
        const PerezSkyCondition c = perezSkyCondition(in);
        bins.push_back(c.bin);
        const PerezAllWeatherSky sky(c, skyDirection(in.sunZenithDeg, 135));
        EXPECT_NEAR(horizontalIlluminance(sky) / c.diffuseHorizontalLx, 1.0, 2e-4)
            << "bin " << c.bin << " Z " << in.sunZenithDeg;
    }
    for (int bin = 1; bin <= 8; ++bin) EXPECT_NE(std::find(bins.begin(), bins.end(), bin), bins.end()) << bin;
}

TEST(PerezSky, SymmetricAboutTheSunsVerticalPlane) {
    const double sunAzimuth = 200;
    for (const PerezSkyInput& in : hoursOfEveryBin()) {
        const PerezAllWeatherSky sky(perezSkyCondition(in), skyDirection(in.sunZenithDeg, sunAzimuth));
        for (double t : {5.0, 30.0, 60.0, 85.0})
            for (double da : {10.0, 45.0, 90.0, 160.0}) {
                const double l = sky.luminance(skyDirection(t, sunAzimuth + da));
                EXPECT_NEAR(sky.luminance(skyDirection(t, sunAzimuth - da)), l, 1e-9 * l) << t << " " << da;
            }
    }
}

TEST(PerezSky, ClearSkyBrightestAroundTheSun) {
    const PerezSkyCondition c = perezSkyCondition(hour(800, 80, 40));
    ASSERT_EQ(c.bin, 8);
    const PerezAllWeatherSky sky(c, skyDirection(40, 180));
    const double nearSun = sky.luminance(skyDirection(35, 180)), zenith = sky.luminance({0, 0, 1});
    const double opposite = sky.luminance(skyDirection(50, 0));
    EXPECT_GT(nearSun, 4 * zenith);
    EXPECT_GT(zenith, opposite);  // the darkest part of a clear sky is ~90 deg from the sun
}

TEST(PerezSky, OvercastBinIsNearlyCieOvercastShaped) {
    // Bin 1 (no beam), usual overcast brightness. The CIE overcast sky is rotationally
    // symmetric with Lz = 9 E / (7 pi) and L(theta)/Lz = (1 + 2 cos theta)/3; Perez's
    // overcast is as symmetric and as bright at the zenith, and less dark at the horizon.
    for (const PerezSkyInput& in : {hour(0, 150, 20), hour(0, 80, 45)}) {
        const PerezSkyCondition c = perezSkyCondition(in);
        ASSERT_EQ(c.bin, 1);
        const PerezAllWeatherSky sky(c, skyDirection(in.sunZenithDeg, 180));
        const double lz = sky.luminance({0, 0, 1});
        EXPECT_NEAR(lz / (9 * c.diffuseHorizontalLx / (7 * kPi)), 1.0, 0.15);
        double previous = lz;
        for (double t : {30.0, 60.0, 80.0}) {
            double lo = 1e300, hi = 0;
            for (double a = 0; a < 360; a += 15) {
                const double l = sky.luminance(skyDirection(t, a));
                lo = std::min(lo, l);
                hi = std::max(hi, l);
            }
            EXPECT_LT(hi / lo, 1.1) << "theta " << t;  // nearly no azimuthal structure
            EXPECT_LT(hi, previous) << "theta " << t;  // darker towards the horizon
            const double cie = (1 + 2 * std::cos(radians(t))) / 3;
            EXPECT_GT(lo / lz, cie - 0.02) << "theta " << t;
            EXPECT_LT(hi / lz, cie + 0.25) << "theta " << t;
            previous = lo;
        }
    }
}

// Chicago O'Hare's TMY3 year (tests/data/weather), read once.
std::shared_ptr<const WeatherFile> chicago() {
    static const auto file = std::make_shared<const WeatherFile>(readEpw(LUXPLAN_TEST_DATA "/weather/chicago.epw"));
    return file;
}

DaylightParams perezParams(std::optional<DateTime> from = {}, std::optional<DateTime> to = {}) {
    DaylightParams p;
    p.model = SkyModelType::Perez;
    p.weather = chicago();
    p.from = from;
    p.to = to;
    return p;
}

Site siteOf(const WeatherFile& w) { return {w.latitudeDeg, w.longitudeDeg, 0}; }

DateTime chicagoTime(int month, int day, int hour, int minute) {
    DateTime t;
    t.year = 2026;  // the year is ignored with a weather file
    t.month = month;
    t.day = day;
    t.hour = hour;
    t.minute = minute;
    t.utcOffsetMinutes = -360;
    return t;
}

TEST(PerezDaylight, OneInstantPerHourAtItsMiddle) {
    const DaylightParams year = perezParams();
    const std::vector<DaylightInstant> all = daylightInstants(year, siteOf(*chicago()));
    ASSERT_EQ(all.size(), chicago()->hours.size());
    // 21 June, hour 13 (12:00-13:00 CST): reported at 12:30, the sun high in the south.
    const DaylightParams at = perezParams(chicagoTime(6, 21, 12, 10));
    const std::vector<DaylightInstant> one = daylightInstants(at, siteOf(*chicago()));
    ASSERT_EQ(one.size(), 1u);
    const WeatherHour& h = chicago()->hours[*one[0].weatherHour];
    EXPECT_EQ(h.month, 6);
    EXPECT_EQ(h.day, 21);
    EXPECT_EQ(h.hour, 13);
    EXPECT_EQ(one[0].time->hour, 12);
    EXPECT_EQ(one[0].time->minute, 30);
    EXPECT_EQ(one[0].time->utcOffsetMinutes, -360);
    EXPECT_NEAR(one[0].sunAltitudeDeg, 90 - 41.98 + 23.44, 1.5);  // near solar noon
    EXPECT_NEAR(one[0].sunNormalIlluminanceLx, perezConditionOf(at, one[0]).directNormalLx, 1e-9);
    // A day: 24 hours; the night ones have no sun; the sun follows the file's irradiance.
    const std::vector<DaylightInstant> day =
        daylightInstants(perezParams(chicagoTime(6, 21, 0, 30), chicagoTime(6, 21, 23, 30)), siteOf(*chicago()));
    ASSERT_EQ(day.size(), 24u);
    for (const DaylightInstant& i : day) {
        const WeatherHour& w = chicago()->hours[*i.weatherHour];
        if (i.sunAltitudeDeg < 0) {
            EXPECT_EQ(i.sunNormalIlluminanceLx, 0.0) << i.time->str();
        } else {
            EXPECT_EQ(i.sunNormalIlluminanceLx > 0, w.directNormalWm2 > 0) << i.time->str();
        }
    }
    // A period over New Year: 31 December 12:30 to 1 January 11:30 is 24 hours.
    EXPECT_EQ(daylightInstants(perezParams(chicagoTime(12, 31, 12, 30), chicagoTime(1, 1, 11, 30)), siteOf(*chicago())).size(), 24u);
}

TEST(PerezDaylight, ValidationOfThePerezSky) {
    DaylightParams p = perezParams();
    EXPECT_TRUE(p.sunEnabled());  // the weather file's sun
    EXPECT_TRUE(validateDaylight(p, siteOf(*chicago())).empty());
    p.sunOverride = SunOverride{};
    auto d = validateDaylight(p, siteOf(*chicago()));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].jsonPath, "/daylight/sun");
    EXPECT_NE(d[0].message.find("takes its sun from the weather file"), std::string::npos) << d[0].message;
    // No hour has its middle in [12:00, 12:10].
    d = validateDaylight(perezParams(chicagoTime(3, 1, 12, 0), chicagoTime(3, 1, 12, 10)), siteOf(*chicago()));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].jsonPath, "/daylight/to");
    EXPECT_NE(d[0].message.find("no hour of the weather file"), std::string::npos) << d[0].message;
}

TEST(PerezDaylight, MissingIrradianceWithTheSunUpIsAnErrorNamingTheLine) {
    auto broken = std::make_shared<WeatherFile>(*chicago());
    const DaylightParams at = perezParams(chicagoTime(6, 21, 12, 30));
    const size_t index = *daylightInstants(at, siteOf(*chicago()))[0].weatherHour;
    broken->hours[index].diffuseHorizontalWm2 = std::nan("");
    DaylightParams p = at;
    p.weather = broken;
    try {
        daylightInstants(p, siteOf(*chicago()));
        FAIL() << "no error";
    } catch (const FileError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("chicago.epw:" + std::to_string(broken->hours[index].line) + ": "), std::string::npos) << m;
        EXPECT_NE(m.find("diffuse horizontal irradiance"), std::string::npos) << m;
        EXPECT_NE(m.find(std::to_string(chicago()->calendarYear) + "-06-21T12:30-06:00"), std::string::npos) << m;
    }
    // At night the file's data do not matter.
    const DaylightParams night = perezParams(chicagoTime(6, 21, 2, 30));
    auto dark = std::make_shared<WeatherFile>(*chicago());
    dark->hours[*daylightInstants(night, siteOf(*chicago()))[0].weatherHour].directNormalWm2 = std::nan("");
    DaylightParams q = night;
    q.weather = dark;
    EXPECT_NO_THROW(daylightInstants(q, siteOf(*chicago())));
}

// Issue 60's first "Done when": an open field under each hour's Perez sky and sun (diffuse
// horizontal illuminance + direct normal illuminance x sin(altitude)) against the file's
// measured global horizontal illuminance, over the hours with the sun up at the hour's
// middle and a measured value of at least 100 lx: below that (sunrise and sunset hours,
// 5 of 4 409) a few lux of difference are a large ratio, and 100 lx is where useful
// daylight starts (UDI). Measured: mean +1.6 %, median +0.7 %, 99.3 % within 10 %.
TEST(PerezDaylight, OpenFieldGivesBackTheFilesGlobalIlluminanceOverAYear) {
    const DaylightParams p = perezParams();
    std::vector<double> ratios;
    double model = 0, measured = 0;
    for (const DaylightInstant& i : daylightInstants(p, siteOf(*chicago()))) {
        const double file = chicago()->hours[*i.weatherHour].globalHorizontalLx;
        if (i.sunAltitudeDeg <= 0 || std::isnan(file) || file < 100) continue;
        const PerezSkyCondition c = perezConditionOf(p, i);
        const double open = c.diffuseHorizontalLx + i.sunNormalIlluminanceLx * std::sin(radians(i.sunAltitudeDeg));
        model += open;
        measured += file;
        ratios.push_back(open / file - 1);
    }
    ASSERT_GT(ratios.size(), 4000u);
    std::sort(ratios.begin(), ratios.end());
    const double within = double(std::count_if(ratios.begin(), ratios.end(), [](double r) { return std::abs(r) <= 0.10; }));
    EXPECT_NEAR(model / measured, 1.0, 0.04);
    EXPECT_NEAR(ratios[ratios.size() / 2], 0.0, 0.03);
    EXPECT_GE(within / double(ratios.size()), 0.85);
    // What the figures are today, so that a change in the model shows.
    EXPECT_NEAR(model / measured - 1, 0.0161, 0.002);
    EXPECT_NEAR(ratios[ratios.size() / 2], 0.0067, 0.002);
}

// The bake of every sky model equals the weighted sum of skyLuminanceAt over its instants.
TEST(PerezDaylight, BakingThroughSkyLuminanceAtEqualsTheBake) {
    const DaylightBakeOptions small{64, 32, 2, {}};
    std::vector<std::pair<DaylightParams, Site>> cases;
    cases.push_back({perezParams(chicagoTime(7, 2, 5, 0), chicagoTime(7, 2, 19, 0)), siteOf(*chicago())});
    DaylightParams preetham;
    preetham.from = chicagoTime(3, 20, 9, 0);
    preetham.to = chicagoTime(3, 20, 12, 0);
    preetham.stepMinutes = 60;
    cases.push_back({preetham, siteOf(*chicago())});
    DaylightParams general = preetham;
    general.model = SkyModelType::CieGeneral;
    general.horizontalIlluminanceLx = 20000;
    cases.push_back({general, siteOf(*chicago())});
    DaylightParams overcast;
    overcast.model = SkyModelType::CieOvercast;
    overcast.horizontalIlluminanceLx = 10000;
    cases.push_back({overcast, Site{}});
    DaylightParams uniform;
    uniform.model = SkyModelType::Uniform;
    uniform.luminanceNits = 1000;
    cases.push_back({uniform, Site{}});
    for (const auto& [params, site] : cases) {
        const DaylightEnvironment baked = buildDaylight(params, site, small);
        const std::vector<DaylightInstant> instants = daylightInstants(params, site);
        SkyMap map(small.width, small.height);
        const double weight = params.model == SkyModelType::CieOvercast || params.model == SkyModelType::Uniform
                                  ? 1.0  // time-independent: baked once
                                  : 1.0 / double(instants.size());
        for (const DaylightInstant& i : instants) {
            const auto sky = skyLuminanceAt(params, i);
            map.accumulate([&](double) { return [&](const Vec3& w) { double l = sky(w); return Vec3(l, l, l); }; }, weight,
                           small.supersample, 0, small.height / 2);
            if (weight == 1.0) break;
        }
        double peak = 0;
        for (int iy = 0; iy < small.height / 2; ++iy)
            for (int ix = 0; ix < small.width; ++ix) peak = std::max(peak, luminance(baked.skyMap().at(ix, iy)));
        ASSERT_GT(peak, 0) << skyModelNames().name(params.model);
        for (int iy = 0; iy < small.height / 2; ++iy)
            for (int ix = 0; ix < small.width; ++ix)
                EXPECT_NEAR(map.at(ix, iy).x, luminance(baked.skyMap().at(ix, iy)), 1e-9 * peak)
                    << skyModelNames().name(params.model) << " pixel " << ix << " " << iy;
    }
}

TEST(PerezDaylight, BakedHourGivesItsIlluminanceOnAnOpenPlane) {
    // 21 June 12:30: the baked map's sky and the hour's sun disk on an open horizontal plane.
    const DaylightParams p = perezParams(chicagoTime(6, 21, 12, 30));
    const DaylightInstant i = daylightInstants(p, siteOf(*chicago()))[0];
    const PerezSkyCondition c = perezConditionOf(p, i);
    ASSERT_TRUE(c.lit);
    const DaylightEnvironment e = buildDaylight(p, siteOf(*chicago()));
    ASSERT_EQ(e.sunDisks().size(), 1u);
    const Vec3 up(0, 0, 1);
    EXPECT_NEAR(e.illuminance(up, false, false) / c.diffuseHorizontalLx, 1.0, 2e-3);
    EXPECT_NEAR(e.totalHorizontalIlluminance(),
                c.diffuseHorizontalLx + c.directNormalLx * std::sin(radians(i.sunAltitudeDeg)), 2e-3 * e.totalHorizontalIlluminance());
}

}  // namespace
}  // namespace luxplan::perez_sky_test
