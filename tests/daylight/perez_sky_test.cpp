// The Perez all-weather sky (1993) and the Perez 1990 luminous efficacies
// (daylight/perez_sky.h): the published tables at known points, the formulas against
// hand computations, the sky's own consistency, and (with a weather file) an open field
// over Chicago's TMY3 year against the file's measured global illuminance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <luxplan/daylight/perez_sky.h>

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

}  // namespace
}  // namespace luxplan::perez_sky_test
