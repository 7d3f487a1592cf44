// Chi-square tests of the direction warps against their pdfs.
#include <gtest/gtest.h>

#include <functional>

#include <luxplan/core/rng.h>
#include <luxplan/core/warp.h>
#include "support/chi2.h"

namespace luxplan {
namespace {

// Bins directions over (cos theta, phi) cells of equal parameter size and compares
// counts with the pdf integrated over each cell (midpoint rule on a fine subgrid).
test::Chi2Result directionChi2(const std::function<Vec3(Vec2)>& sample, const std::function<double(const Vec3&)>& pdf,
                               int samples, int thetaBins = 16, int phiBins = 32) {
    Rng rng(7);
    std::vector<double> observed(thetaBins * phiBins, 0.0), expected(thetaBins * phiBins, 0.0);
    auto cellOf = [&](const Vec3& w) {
        int i = std::clamp(int((w.z + 1) * 0.5 * thetaBins), 0, thetaBins - 1);
        double phi = std::atan2(w.y, w.x);
        if (phi < 0) phi += 2 * kPi;
        int j = std::clamp(int(phi / (2 * kPi) * phiBins), 0, phiBins - 1);
        return i * phiBins + j;
    };
    for (int k = 0; k < samples; ++k) observed[cellOf(sample({rng.uniform(), rng.uniform()}))] += 1;
    const int sub = 8;
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j) {
            double sum = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    double z = -1 + 2.0 * (i + (a + 0.5) / sub) / thetaBins;
                    double phi = 2 * kPi * (j + (b + 0.5) / sub) / phiBins;
                    double r = std::sqrt(std::max(0.0, 1 - z * z));
                    sum += pdf({r * std::cos(phi), r * std::sin(phi), z});
                }
            // Solid angle of a cell in (z, phi) is dz * dphi.
            expected[i * phiBins + j] = sum / (sub * sub) * (2.0 / thetaBins) * (2 * kPi / phiBins) * samples;
        }
    return test::chi2Test(observed, expected);
}

TEST(Warp, CosineHemisphereMatchesPdf) {
    auto r = directionChi2(sampleCosineHemisphere, [](const Vec3& w) { return cosineHemispherePdf(w.z); }, 200000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(Warp, UniformSphereMatchesPdf) {
    auto r = directionChi2(sampleUniformSphere, [](const Vec3&) { return uniformSpherePdf(); }, 200000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(Warp, EqualAreaHemisphereMatchesPdf) {
    auto r = directionChi2(equalAreaHemisphere, [](const Vec3& w) { return w.z >= 0 ? uniformHemispherePdf() : 0.0; }, 200000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(Warp, EqualAreaHemisphereKeepsTheMidlinesOnGreatCircles) {
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.8, 1.0}) {
        EXPECT_NEAR(equalAreaHemisphere({t, 0.5}).y, 0.0, 1e-12);
        EXPECT_NEAR(equalAreaHemisphere({0.5, t}).x, 0.0, 1e-12);
    }
    EXPECT_NEAR(equalAreaHemisphere({1.0, 0.5}).z, 0.0, 1e-12);  // the square's edge is the horizon
    EXPECT_NEAR(equalAreaHemisphere({0.5, 0.5}).z, 1.0, 1e-12);
}

TEST(Warp, UniformConeMatchesPdf) {
    double cosMax = 0.8125;  // on a bin edge, so the pdf is smooth within every cell
    auto r = directionChi2([&](Vec2 u) { return sampleUniformCone(u, cosMax); },
                           [&](const Vec3& w) { return w.z >= cosMax ? uniformConePdf(cosMax) : 0.0; }, 200000, 64, 16);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(Warp, ChiSquareDetectsAWrongPdf) {
    // The test must be able to fail: a uniform hemisphere checked against the cosine pdf.
    auto r = directionChi2(sampleUniformHemisphere, [](const Vec3& w) { return cosineHemispherePdf(w.z); }, 50000);
    EXPECT_LT(r.pValue, 1e-6);
}

TEST(Chi2, SurvivalFunctionKnownValues) {
    // Tabulated: P(chi2_1 > 3.841) = 0.05, P(chi2_10 > 23.209) = 0.01.
    EXPECT_NEAR(test::chi2Survival(3.841459, 1), 0.05, 1e-5);
    EXPECT_NEAR(test::chi2Survival(23.209251, 10), 0.01, 1e-5);
}

}  // namespace
}  // namespace luxplan
