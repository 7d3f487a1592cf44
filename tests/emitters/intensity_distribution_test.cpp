// The intensity distribution of a photometric file: every C symmetry expanded to the
// full circle, bilinear interpolation, the flux integral against closed forms, and
// the sampling of directions against the intensity itself (chi-square).
#include <gtest/gtest.h>

#include <luxplan/core/rng.h>
#include <luxplan/emitters/intensity_distribution.h>
#include "support/chi2.h"

namespace luxplan::test {
namespace {

constexpr double kDeg = kPi / 180;

double at(const IntensityDistribution& d, double cDeg, double gammaDeg) {
    return d.intensity(PhotometricAngles{cDeg * kDeg, gammaDeg * kDeg});
}

// Planes `c` (degrees) over gammas {0, 30, 60, 90}; plane i's value at gamma j is
// 100 (gamma 0, the same direction for every plane) or 10 * (i + 1) * (4 - j).
PhotometricTable planes(std::vector<double> c, CSymmetry symmetry) {
    PhotometricTable t;
    t.cDeg = std::move(c);
    t.gammaDeg = {0, 30, 60, 90};
    t.symmetry = symmetry;
    for (size_t i = 0; i < t.cDeg.size(); ++i)
        for (int j = 0; j < 4; ++j) t.candela.push_back(j == 0 ? 100 : 10.0 * double(i + 1) * (4 - j));
    return t;
}

TEST(IntensityDistribution, RotationalIsTheSameInEveryPlane) {
    IntensityDistribution d(planes({0}, CSymmetry::Rotational));
    for (double c : {0.0, 37.0, 90.0, 181.0, 359.0}) EXPECT_DOUBLE_EQ(at(d, c, 30), 30) << c;
    EXPECT_DOUBLE_EQ(at(d, 10, 45), 25);  // halfway between 30 and 20
}

TEST(IntensityDistribution, EverySymmetryMirrorsItsPlanes) {
    // Quadrants (IES 0-90, LDT Isym 4): planes 0, 45, 90.
    IntensityDistribution q(planes({0, 45, 90}, CSymmetry::Quadrants));
    for (double c : {45.0, 135.0, 225.0, 315.0}) EXPECT_DOUBLE_EQ(at(q, c, 30), 60) << c;
    for (double c : {90.0, 270.0}) EXPECT_DOUBLE_EQ(at(q, c, 30), 90) << c;
    for (double c : {0.0, 180.0, 360.0}) EXPECT_DOUBLE_EQ(at(q, c, 30), 30) << c;
    EXPECT_DOUBLE_EQ(at(q, 100, 30), at(q, 80, 30));
    // About the C0-C180 plane (IES 0-180, LDT Isym 2): planes 0, 90, 180.
    IntensityDistribution b(planes({0, 90, 180}, CSymmetry::AboutC0C180));
    EXPECT_DOUBLE_EQ(at(b, 270, 30), 60);
    EXPECT_DOUBLE_EQ(at(b, 200, 60), at(b, 160, 60));
    EXPECT_DOUBLE_EQ(at(b, 180, 30), 90);
    // About the C90-C270 plane (IES 90-270, LDT Isym 3): planes 90, 180, 270.
    IntensityDistribution m(planes({90, 180, 270}, CSymmetry::AboutC90C270));
    EXPECT_DOUBLE_EQ(at(m, 0, 30), 60);  // the image of C 180
    EXPECT_DOUBLE_EQ(at(m, 45, 60), at(m, 135, 60));
    EXPECT_DOUBLE_EQ(at(m, 300, 60), at(m, 240, 60));
    EXPECT_DOUBLE_EQ(at(m, 90, 30), 30);
    EXPECT_DOUBLE_EQ(at(m, 270, 30), 90);
    // None (IES 0-360, LDT Isym 0) without a 360 plane: the last interval wraps to C 0.
    IntensityDistribution n(planes({0, 90, 180, 270}, CSymmetry::None));
    EXPECT_DOUBLE_EQ(at(n, 270, 30), 120);
    EXPECT_DOUBLE_EQ(at(n, 315, 30), 75);  // halfway between 120 (C 270) and 30 (C 0)
    EXPECT_DOUBLE_EQ(at(n, 360, 30), 30);
    // ... and with one: the same.
    IntensityDistribution full(planes({0, 90, 180, 270, 360}, CSymmetry::None));
    EXPECT_DOUBLE_EQ(at(full, 315, 30), 75);
}

TEST(IntensityDistribution, InterpolatesBilinearlyAndIsZeroOutsideItsGammas) {
    IntensityDistribution d(planes({0, 90, 180, 270}, CSymmetry::None));
    // C 45 (between planes 1 and 2), gamma 45 (between 30 and 60).
    double expected = 0.5 * (0.5 * 30 + 0.5 * 20) + 0.5 * (0.5 * 60 + 0.5 * 40);
    EXPECT_NEAR(at(d, 45, 45), expected, 1e-12);
    EXPECT_EQ(at(d, 45, 120), 0.0);
    EXPECT_FALSE(d.emitsBeyond90());
    // A direction of the luminaire's frame: x along C 0, y along C 90, z along gamma 0.
    EXPECT_NEAR(d.intensity(Vec3(0, std::sin(30 * kDeg), std::cos(30 * kDeg))), 60, 1e-9);
    EXPECT_NEAR(d.intensity(Vec3(-std::sin(60 * kDeg), 0, std::cos(60 * kDeg))), 60, 1e-9);
}

TEST(IntensityDistribution, FluxAgainstClosedForms) {
    // 100 cd everywhere: 400 pi lm.
    PhotometricTable uniform;
    uniform.cDeg = {0};
    uniform.gammaDeg = {0, 90, 180};
    uniform.candela = {100, 100, 100};
    uniform.symmetry = CSymmetry::Rotational;
    IntensityDistribution u(uniform);
    EXPECT_NEAR(u.flux(), 400 * kPi, 1e-9);
    EXPECT_TRUE(u.emitsBeyond90());
    // Lambertian I0 cos(gamma), tabulated every 5 degrees: pi I0, less the chords'
    // shortfall (about 0.1%).
    PhotometricTable lambert;
    lambert.cDeg = {0, 90};
    lambert.symmetry = CSymmetry::Quadrants;
    for (int g = 0; g <= 90; g += 5) lambert.gammaDeg.push_back(g);
    for (int c = 0; c < 2; ++c)
        for (double g : lambert.gammaDeg) lambert.candela.push_back(1000 * std::cos(g * kDeg));
    IntensityDistribution l(lambert);
    EXPECT_NEAR(l.flux(), 1000 * kPi, 0.002 * 1000 * kPi);
    EXPECT_LT(l.flux(), 1000 * kPi);
    // The asymmetric table: the flux is the quadrature of its intensity.
    IntensityDistribution a(planes({0, 90, 180, 270}, CSymmetry::None));
    double sum = 0;
    const int n = 720;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n / 4; ++j) {
            double c = (i + 0.5) * 2 * kPi / n, g = (j + 0.5) * (kPi / 2) / (n / 4);
            sum += a.intensity(PhotometricAngles{c, g}) * std::sin(g) * (2 * kPi / n) * (kPi / 2 / (n / 4));
        }
    EXPECT_NEAR(a.flux(), sum, 1e-4 * sum);
}

TEST(IntensityDistribution, RefusesABrokenTable) {
    PhotometricTable t = planes({0, 90, 180}, CSymmetry::Quadrants);  // 180 is outside 0-90
    EXPECT_THROW(IntensityDistribution{t}, std::invalid_argument);
    t = planes({0, 90}, CSymmetry::Quadrants);
    t.candela.pop_back();
    EXPECT_THROW(IntensityDistribution{t}, std::invalid_argument);
}

// Directions drawn by sample() binned by (C, gamma) cells: 12 sectors of 30 degrees
// by the file's gamma intervals, against the intensity's own flux in each cell, by a
// quadrature of intensity() (not of the sampler's tables).
TEST(IntensityDistribution, SamplingFollowsTheIntensity) {
    PhotometricTable t;
    t.cDeg = {0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330};
    t.gammaDeg = {0, 15, 30, 45, 60, 75, 90, 120, 150, 180};
    t.symmetry = CSymmetry::None;
    for (size_t i = 0; i < t.cDeg.size(); ++i)
        for (double g : t.gammaDeg) {
            // A lopsided beam towards C 60, some uplight, nothing straight up.
            double beam = 500 * std::exp(-std::pow((g - 40) / 20, 2)) * (1.2 + std::cos((t.cDeg[i] - 60) * kDeg));
            t.candela.push_back(g == 180 ? 0 : beam + (g > 90 ? 30 : 0));
        }
    IntensityDistribution d(t);
    const int nc = 12, ng = int(t.gammaDeg.size()) - 1, samples = 400000;
    std::vector<double> observed(size_t(nc * ng), 0.0), expected(size_t(nc * ng), 0.0);
    Rng rng(11);
    for (int k = 0; k < samples; ++k) {
        auto s = d.sample({rng.uniform(), rng.uniform()});
        ASSERT_GT(s.pdf, 0);
        ASSERT_NEAR(s.pdf, d.pdf(s.local), 1e-9 * s.pdf);
        double c = std::atan2(s.local.y, s.local.x) / kDeg, g = std::acos(std::clamp(s.local.z, -1.0, 1.0)) / kDeg;
        if (c < 0) c += 360;
        int ic = std::clamp(int(c / 30), 0, nc - 1);
        int ig = int(std::upper_bound(t.gammaDeg.begin(), t.gammaDeg.end(), g) - t.gammaDeg.begin()) - 1;
        observed[size_t(std::clamp(ig, 0, ng - 1) * nc + ic)] += 1;
    }
    const int sub = 24;
    double total = 0;
    for (int ig = 0; ig < ng; ++ig)
        for (int ic = 0; ic < nc; ++ic) {
            double g0 = t.gammaDeg[size_t(ig)] * kDeg, g1 = t.gammaDeg[size_t(ig) + 1] * kDeg, sum = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    double c = (ic * 30 + 30 * (a + 0.5) / sub) * kDeg, g = g0 + (g1 - g0) * (b + 0.5) / sub;
                    sum += d.intensity(PhotometricAngles{c, g}) * std::sin(g) * (30 * kDeg / sub) * ((g1 - g0) / sub);
                }
            expected[size_t(ig * nc + ic)] = sum;
            total += sum;
        }
    EXPECT_NEAR(total, d.flux(), 2e-3 * d.flux());  // midpoint quadrature
    for (double& e : expected) e *= samples / total;
    auto r = chi2Test(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(IntensityDistribution, PdfIntegratesToOne) {
    IntensityDistribution d(planes({0, 45, 90}, CSymmetry::Quadrants));
    const int n = 400;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double c = (i + 0.5) * 2 * kPi / n, z = 1 - 2 * (j + 0.5) / n, s = std::sqrt(1 - z * z);
            sum += d.pdf(Vec3(s * std::cos(c), s * std::sin(c), z)) * (4 * kPi / (double(n) * n));
        }
    EXPECT_NEAR(sum, 1.0, 5e-3);
}

}  // namespace
}  // namespace luxplan::test
