// Sky and sun models: Preetham zenith fits and Perez normalization, the Preetham sun's
// spectral attenuation, CIE overcast/general skies, colour matching functions.
#include <gtest/gtest.h>

#include <luxplan/daylight/cie_sky.h>
#include <luxplan/daylight/photometry.h>
#include <luxplan/daylight/preetham.h>

namespace luxplan {
namespace {

Vec3 fromAngles(double zenith, double phi) {
    return {std::sin(zenith) * std::cos(phi), std::sin(zenith) * std::sin(phi), std::cos(zenith)};
}

TEST(PreethamSky, ZenithLuminanceMatchesFormula) {
    // REFERENCES.md 2.1: chi = (4/9 - T/120)(pi - 2 theta_s);
    // Yz = (4.0453 T - 4.9710) tan(chi) - 0.2155 T + 2.4192 [kcd/m^2].
    for (double t : {2.0, 3.0, 4.0, 5.0, 6.0})
        for (double deg : {0.0, 20.0, 45.0, 70.0, 85.0, 90.0}) {
            double ts = radians(deg);
            double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2 * ts);
            double yz = ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192) * 1000.0;
            EXPECT_NEAR(preethamZenithLuminance(t, ts), yz, 1e-9 * yz) << "T " << t << " theta_s " << deg;
            EXPECT_GT(preethamZenithLuminance(t, ts), 0);
        }
    // Spot value: T = 3, sun 45 deg high: chi = (4/9 - 1/40) pi/2 = 0.658862 rad -> 7.3204 kcd/m^2 [DERIVED].
    EXPECT_NEAR(preethamZenithLuminance(3, radians(45)), 7320.36, 0.01);
}

TEST(PreethamSky, PerezNormalizationGivesZenithValues) {
    for (double t : {2.0, 4.0, 6.0})
        for (double deg : {5.0, 30.0, 60.0, 89.0}) {
            PreethamSky sky(t, fromAngles(radians(deg), 1.0));
            Vec3 zenith = sky.xyY({0, 0, 1});
            EXPECT_NEAR(zenith.z, preethamZenithLuminance(t, radians(deg)), 1e-9 * zenith.z);
            Vec2 c = preethamZenithChromaticity(t, radians(deg));
            EXPECT_NEAR(zenith.x, c.x, 1e-12);
            EXPECT_NEAR(zenith.y, c.y, 1e-12);
            EXPECT_NEAR(luminance(sky.rgb({0, 0, 1})), zenith.z, 1e-9 * zenith.z);
            // The per-row evaluator and the direct luminance agree with xyY().
            Vec3 w = fromAngles(radians(70), 2.0);
            Vec3 a = sky.row(w.z).xyY(w), b = sky.xyY(w);
            EXPECT_NEAR(a.z, b.z, 1e-12 * b.z);
            EXPECT_NEAR(sky.luminance(w), b.z, 1e-9 * b.z);
        }
}

TEST(PreethamSky, PerezFunctionAndShape) {
    PerezCoefficients y = preethamPerezY(3);
    // F = (1 + A e^{B / cos theta}) (1 + C e^{D gamma} + E cos^2 gamma) (cos^2, not sqrt(cos)).
    double ct = 0.6, g = 0.8;
    double f = (1 + y.a * std::exp(y.b / ct)) * (1 + y.c * std::exp(y.d * g) + y.e * std::cos(g) * std::cos(g));
    EXPECT_DOUBLE_EQ(y(ct, g), f);
    // Brightest near the sun, darkest roughly 90 deg from it; finite at the horizon.
    Vec3 sun = fromAngles(radians(50), 0);
    PreethamSky sky(3, sun);
    double nearSun = sky.luminance(fromAngles(radians(45), 0));
    double away = sky.luminance(fromAngles(radians(40), kPi));
    EXPECT_GT(nearSun, 3 * away);
    double horizon = sky.luminance(fromAngles(kPi / 2, 2.0));
    EXPECT_TRUE(std::isfinite(horizon));
    EXPECT_GT(horizon, 0);
}

TEST(PreethamSun, ExtraterrestrialIlluminanceIsTheSolarConstant) {
    // Published solar illuminance constants: 127.5 klx (IES), 133.8 klx (Darula et al. 2005).
    double e0 = extraterrestrialSunIlluminance();
    EXPECT_GT(e0, 125000);
    EXPECT_LT(e0, 135000);
}

TEST(PreethamSun, AttenuationFollowsAirMassAndTurbidity) {
    // Air mass (Kasten 1966 form of PSS99): 1 at the zenith, ~2 at 60 deg, ~36.5 at the horizon.
    EXPECT_NEAR(relativeAirMass(0), 1.0, 1e-3);
    EXPECT_NEAR(relativeAirMass(radians(60)), 1.995, 0.005);
    EXPECT_NEAR(relativeAirMass(kPi / 2), 36.4, 0.5);
    double previous = kInf;
    for (double deg = 0; deg < 90; deg += 10) {
        double e = preethamSunNormalIlluminance(3, radians(deg));
        EXPECT_LT(e, previous);
        previous = e;
    }
    EXPECT_GT(preethamSunNormalIlluminance(2, radians(30)), preethamSunNormalIlluminance(5, radians(30)));
    EXPECT_EQ(preethamSunNormalIlluminance(3, kPi / 2), 0.0);
    // Clear high sun: direct normal illuminance in the usual 70-110 klx band.
    double high = preethamSunNormalIlluminance(2.5, radians(20));
    EXPECT_GT(high, 70000);
    EXPECT_LT(high, 110000);
    // The illuminance is the V(lambda) integral of the attenuated spectrum over the disk.
    auto spectrum = preethamSunSpectralRadiance(3, relativeAirMass(radians(30)));
    double y = 0;
    for (int i = 0; i < kSunSpectrumSamples; ++i) y += spectrum[i] * cieYBar(i) * 10.0;
    EXPECT_NEAR(preethamSunNormalIlluminance(3, radians(30)), 683.0 * y * kSunDiskProjectedSolidAngle, 1e-6);
    // A low sun is reddened.
    Vec3 low = preethamSunColor(3, radians(85)), noon = preethamSunColor(3, radians(10));
    EXPECT_NEAR(luminance(low), 1.0, 1e-12);
    EXPECT_GT(low.x / low.z, noon.x / noon.z);
}

TEST(SunDisk, GeometryOfTheHalfDegreeDisk) {
    EXPECT_NEAR(degrees(2 * kSunHalfAngle), 0.533, 1e-12);
    EXPECT_NEAR(kSunSolidAngle, 6.8e-5, 1e-6);
    EXPECT_NEAR(kSunDiskProjectedSolidAngle / kSunSolidAngle, 1.0, 1e-5);
}

TEST(CieOvercastSky, LuminanceProfile) {
    CieOvercastSky sky(10000);
    EXPECT_NEAR(sky.zenithLuminance(), 9 * 10000 / (7 * kPi), 1e-9);
    EXPECT_NEAR(sky.luminance({0, 0, 1}), sky.zenithLuminance(), 1e-9);
    EXPECT_NEAR(sky.luminance({1, 0, 0}), sky.zenithLuminance() / 3, 1e-9);
    // Horizontal illuminance by quadrature in cos(theta): integral of L cos dw = E_h.
    double e = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        double z = (i + 0.5) / n;
        e += sky.luminance({std::sqrt(1 - z * z), 0, z}) * z * 2 * kPi / n;
    }
    EXPECT_NEAR(e, 10000, 1e-3);
}

TEST(CieGeneralSky, NormalizedToHorizontalIlluminance) {
    for (int type = 1; type <= 15; ++type) {
        Vec3 sun = fromAngles(radians(40), 0.3);
        CieGeneralSky sky(type, sun, 20000);
        EXPECT_NEAR(sky.relativeLuminance({0, 0, 1}), 1.0, 1e-12) << type;
        double e = 0;
        const int nz = 200, np = 200;
        for (int i = 0; i < nz; ++i)
            for (int j = 0; j < np; ++j) {
                double z = (i + 0.5) / nz;
                e += sky.luminance(fromAngles(std::acos(z), 2 * kPi * (j + 0.5) / np)) * z;
            }
        e *= 2 * kPi / (double(nz) * np);
        EXPECT_NEAR(e, 20000, 20000 * 2e-3) << type;
    }
    // Clear skies (11-15) are brighter around the sun than opposite it; type 5 is uniform.
    Vec3 sun = fromAngles(radians(40), 0);
    CieGeneralSky clear(12, sun, 20000), uniform(5, sun, 20000);
    EXPECT_GT(clear.luminance(fromAngles(radians(35), 0)), 3 * clear.luminance(fromAngles(radians(35), kPi)));
    EXPECT_NEAR(uniform.luminance(fromAngles(1.0, 2.0)), 20000 / kPi, 1e-3 * 20000 / kPi);
    EXPECT_THROW(cieGeneralSkyParameters(16), std::invalid_argument);
}

TEST(Photometry, ColourMatchingFunctionsAndConversions) {
    double sx = 0, sy = 0, sz = 0;
    for (int i = 0; i < kSpectrumSamples; ++i) {
        sx += cieXBar(i);
        sy += cieYBar(i);
        sz += cieZBar(i);
    }
    // The equal-energy spectrum is white: x = y = z = 1/3 (CIE 1931 normalization).
    EXPECT_NEAR(sx / (sx + sy + sz), 1.0 / 3, 2e-3);
    EXPECT_NEAR(sy / (sx + sy + sz), 1.0 / 3, 2e-3);
    EXPECT_NEAR(sy * 10, 106.86, 0.1);  // integral of V(lambda) in nm
    // D65 white (x 0.3127, y 0.3290) is (1, 1, 1) in linear sRGB.
    Vec3 white = xyYToRGB(0.3127, 0.3290, 1.0);
    EXPECT_NEAR(white.x, 1.0, 2e-3);
    EXPECT_NEAR(white.y, 1.0, 2e-3);
    EXPECT_NEAR(white.z, 1.0, 2e-3);
    Vec3 c = xyYToRGB(0.25, 0.27, 1234.0);
    EXPECT_NEAR(luminance(c), 1234.0, 1e-9);
    Vec3 back = rgbToXYZ(xyzToRGB({0.3, 0.5, 0.7}));
    EXPECT_NEAR(back.x, 0.3, 1e-12);
    EXPECT_NEAR(back.z, 0.7, 1e-12);
    Vec3 clamped = clampToGamut({1.5, 1.0, -0.2});
    EXPECT_GE(clamped.z, 0.0);
    EXPECT_NEAR(luminance(clamped), luminance(Vec3(1.5, 1.0, -0.2)), 1e-12);
}

}  // namespace
}  // namespace luxplan
