// Statistical tests of the diffuse, glossy and translucent BSDFs: sampling against
// the pdf (chi-square), pdf normalization, reciprocity and white-furnace energy
// balance (translucent_test.cpp has the translucent model's own).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/materials/bsdf.h>
#include "support/chi2.h"
#include "support/directions.h"

namespace luxplan {
namespace {

using test::direction;

// Family-wise false-failure rate of each group of tests.
constexpr double kFamilyAlpha = 0.01;
using test::kSigmas;  // a few hundred checks below

// 6-point Gauss-Legendre on [-1, 1], to integrate the pdf over each chi-square cell.
constexpr double kGaussX[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                               0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr double kGaussW[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                               0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

struct SamplingCase {
    std::string name;
    Bsdf bsdf;
    Vec3 wo;
};

struct Histogram {
    std::vector<double> observed, expected;
    double pdfIntegral = 0;     // int pdf dw over the sphere, by quadrature
    double pdfIntegralFine = 0; // the same on cells split in four, for its error estimate
    int samples = 0;            // samples drawn
    int produced = 0;           // samples that returned a direction
};

// Directions binned over (theta, phi) cells of the whole sphere; theta bins have an edge
// at 90 degrees, where the pdf is discontinuous. Expected counts integrate the pdf per
// cell with Gauss-Legendre in (theta, phi), including the sin(theta) Jacobian.
Histogram sampleHistogram(const Bsdf& bsdf, const Vec3& wo, double pdfScale, int samples, uint64_t seed,
                          const Bsdf* pdfOf = nullptr) {
    const int thetaBins = 36, phiBins = 36;
    const Bsdf& pdfBsdf = pdfOf ? *pdfOf : bsdf;
    Histogram h;
    h.samples = samples;
    h.observed.assign(thetaBins * phiBins, 0.0);
    h.expected.assign(thetaBins * phiBins, 0.0);
    Rng rng(seed);
    for (int k = 0; k < samples; ++k) {
        auto s = bsdf.sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()});
        if (!s) continue;
        ++h.produced;
        double theta = std::acos(std::clamp(s->wi.z, -1.0, 1.0));
        double phi = std::atan2(s->wi.y, s->wi.x);
        if (phi < 0) phi += 2 * kPi;
        int i = std::clamp(int(theta / kPi * thetaBins), 0, thetaBins - 1);
        int j = std::clamp(int(phi / (2 * kPi) * phiBins), 0, phiBins - 1);
        h.observed[i * phiBins + j] += 1;
    }
    auto cellIntegral = [&](double t0, double t1, double p0, double p1) {
        double sum = 0;
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b) {
                double theta = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * kGaussX[a];
                double phi = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * kGaussX[b];
                Vec3 wi(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                sum += kGaussW[a] * kGaussW[b] * pdfBsdf.pdf(wo, wi) * std::sin(theta);
            }
        return sum * 0.25 * (t1 - t0) * (p1 - p0) * pdfScale;
    };
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j) {
            double t0 = kPi * i / thetaBins, t1 = kPi * (i + 1) / thetaBins;
            double p0 = 2 * kPi * j / phiBins, p1 = 2 * kPi * (j + 1) / phiBins;
            double coarse = cellIntegral(t0, t1, p0, p1);
            double tm = 0.5 * (t0 + t1), pm = 0.5 * (p0 + p1);
            double fine = cellIntegral(t0, tm, p0, pm) + cellIntegral(tm, t1, p0, pm) + cellIntegral(t0, tm, pm, p1) +
                          cellIntegral(tm, t1, pm, p1);
            h.expected[i * phiBins + j] = fine * samples;
            h.pdfIntegral += coarse;
            h.pdfIntegralFine += fine;
        }
    return h;
}

std::vector<SamplingCase> samplingCases() {
    std::vector<SamplingCase> cases;
    Bsdf diffuse = Bsdf::diffuse({0.8, 0.6, 0.3});
    for (double theta : {0.0, 60.0, 89.5, 135.0})
        cases.push_back({"diffuse theta " + std::to_string(theta), diffuse, direction(theta, 40)});
    for (double alpha : {0.05, 0.2, 0.5, 1.0})
        for (double theta : {0.0, 45.0, 75.0, 88.0})
            cases.push_back({"glossy alpha " + std::to_string(alpha) + " theta " + std::to_string(theta),
                             Bsdf::glossy({0.04, 0.04, 0.04}, {0.5, 0.4, 0.3}, alpha), direction(theta, 110)});
    // Coat only (a black base), a strongly coloured coat, and the back side.
    cases.push_back({"coat only alpha 0.05 theta 30", Bsdf::glossy({0.9, 0.8, 0.7}, {0, 0, 0}, 0.05), direction(30, 0)});
    cases.push_back({"coat only alpha 0.3 theta 80", Bsdf::glossy({0.9, 0.8, 0.7}, {0, 0, 0}, 0.3), direction(80, 250)});
    cases.push_back({"glossy back side alpha 0.3", Bsdf::glossy({0.05, 0.05, 0.05}, {0.6, 0.6, 0.6}, 0.3),
                     direction(120, 10)});
    // Both sides: reflection on wo's, transmission on the other.
    Bsdf shade = Bsdf::translucent({0.5, 0.45, 0.4}, {0.3, 0.35, 0.2});
    for (double theta : {0.0, 70.0, 160.0})
        cases.push_back({"translucent theta " + std::to_string(theta), shade, direction(theta, 200)});
    cases.push_back({"translucent mostly transmitting", Bsdf::translucent({0.05, 0.05, 0.05}, {0.9, 0.9, 0.9}),
                     direction(30, 0)});
    return cases;
}

// The histograms of every case, built once and shared by the chi-square and the
// normalization tests.
const std::vector<Histogram>& caseHistograms() {
    static const std::vector<Histogram> histograms = [] {
        std::vector<Histogram> out;
        uint64_t seed = 100;
        for (const SamplingCase& c : samplingCases()) out.push_back(sampleHistogram(c.bsdf, c.wo, 1.0, 100000, seed++));
        return out;
    }();
    return histograms;
}

TEST(BsdfSampling, NonDeltaModelsMatchTheirPdf) {
    std::vector<SamplingCase> cases = samplingCases();
    double alpha = test::sidakAlpha(kFamilyAlpha, int(cases.size()));
    for (size_t k = 0; k < cases.size(); ++k) {
        const Histogram& h = caseHistograms()[k];
        test::Chi2Result r = test::chi2Test(h.observed, h.expected);
        EXPECT_GT(r.pValue, alpha) << cases[k].name << " (chi2 " << r.statistic << ", dof " << r.dof << ")\n" << r.table;
    }
}

TEST(BsdfSampling, ChiSquareDetectsAWrongPdf) {
    // The test must be able to fail: samples of alpha 0.2 checked against the pdf of alpha 0.24.
    Bsdf sampled = Bsdf::glossy({0.5, 0.5, 0.5}, {0, 0, 0}, 0.2);
    Bsdf wrong = Bsdf::glossy({0.5, 0.5, 0.5}, {0, 0, 0}, 0.24);
    Histogram h = sampleHistogram(sampled, direction(30, 0), 1.0, 100000, 7, &wrong);
    EXPECT_LT(test::chi2Test(h.observed, h.expected).pValue, 1e-6);
}

TEST(BsdfPdf, IntegratesToTheFractionOfSamplesProduced) {
    // The pdf is that of the directions sample() returns; a glossy sample fails when the
    // microfacet reflects below the surface, so the pdf integrates to P(produced) <= 1
    // (exactly 1 for diffuse). Tolerance: binomial k sigma plus the quadrature's error,
    // estimated by its change when every cell is split in four.
    std::vector<SamplingCase> cases = samplingCases();
    for (size_t k = 0; k < cases.size(); ++k) {
        const Histogram& h = caseHistograms()[k];
        const SamplingCase& c = cases[k];
        double n = h.samples, p = h.produced / n;
        double quadratureError = std::abs(h.pdfIntegralFine - h.pdfIntegral);
        double tol = kSigmas * std::sqrt(std::max(p * (1 - p), 1 / n) / n) + 2 * quadratureError;
        EXPECT_NEAR(h.pdfIntegralFine, p, tol) << c.name;
        EXPECT_LE(h.pdfIntegralFine, 1 + 2 * quadratureError + 1e-12) << c.name;
        if (c.bsdf.type() == BsdfType::Diffuse || c.bsdf.type() == BsdfType::Translucent) {
            EXPECT_NEAR(h.pdfIntegralFine, 1.0, 2 * quadratureError + 1e-9) << c.name;
        }
    }
}

TEST(BsdfSampling, SampleAgreesWithEvalAndPdf) {
    Rng rng(9);
    for (const SamplingCase& c : samplingCases())
        for (int k = 0; k < 2000; ++k) {
            auto s = c.bsdf.sample(c.wo, rng.uniform(), {rng.uniform(), rng.uniform()});
            if (!s) continue;
            ASSERT_FALSE(s->isDelta);
            // Only the translucent model crosses the surface, and says so.
            ASSERT_EQ(s->isTransmission, s->wi.z * c.wo.z < 0) << c.name;
            if (c.bsdf.type() != BsdfType::Translucent) {
                ASSERT_GT(s->wi.z * c.wo.z, 0) << c.name;
            }
            ASSERT_NEAR(length(s->wi), 1.0, 1e-12);
            double pdf = c.bsdf.pdf(c.wo, s->wi);
            ASSERT_NEAR(s->pdf, pdf, 1e-12 * pdf) << c.name;
            Vec3 f = c.bsdf.eval(c.wo, s->wi);
            BsdfEval both = c.bsdf.evalPdf(c.wo, s->wi);
            ASSERT_EQ(both.f, f);
            ASSERT_NEAR(both.pdf, pdf, 1e-12 * pdf);
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_NEAR(s->f[ch], f[ch], 1e-12 * std::abs(f[ch])) << c.name;
                ASSERT_NEAR(s->weight[ch], f[ch] * std::abs(s->wi.z) / pdf, 1e-12 * std::abs(s->weight[ch]) + 1e-300);
            }
        }
}

TEST(Bsdf, Reciprocity) {
    Rng rng(10);
    std::vector<Bsdf> bsdfs = {Bsdf::diffuse({0.3, 0.6, 0.9}), Bsdf::glossy({0.04, 0.04, 0.04}, {0.5, 0.2, 0.1}, 0.1),
                               Bsdf::glossy({0.9, 0.5, 0.1}, {0.3, 0.3, 0.3}, 0.7),
                               Bsdf::glossy({0.2, 0.2, 0.2}, {1, 1, 1}, kMinGgxAlpha)};
    for (const Bsdf& b : bsdfs)
        for (int k = 0; k < 5000; ++k) {
            bool lower = k % 3 == 0;
            Vec3 wo = direction(lower ? 90 + 90 * rng.uniform() : 90 * rng.uniform(), 360 * rng.uniform());
            Vec3 wi = direction(lower ? 90 + 90 * rng.uniform() : 90 * rng.uniform(), 360 * rng.uniform());
            Vec3 a = b.eval(wo, wi), c = b.eval(wi, wo);
            for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(a[ch], c[ch], 1e-12 * std::abs(a[ch]));
            // Opposite sides never scatter for an opaque surface.
            ASSERT_EQ(b.eval(wo, Vec3(wi.x, wi.y, -wi.z)), Vec3());
            ASSERT_EQ(b.pdf(wo, Vec3(wi.x, wi.y, -wi.z)), 0.0);
        }
}

// Monte Carlo directional albedo: the mean sample weight (failed samples count as 0),
// with the standard deviation of one weight, per channel.
struct AlbedoEstimate {
    Vec3 mean, stddev;
    int n = 0;
    Vec3 tolerance() const { return stddev * (kSigmas / std::sqrt(double(n))); }
};

AlbedoEstimate estimateAlbedo(const Bsdf& bsdf, const Vec3& wo, int n, uint64_t seed) {
    Rng rng(seed);
    Vec3 sum, sumSq;
    for (int k = 0; k < n; ++k) {
        auto s = bsdf.sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()});
        if (!s) continue;
        sum += s->weight;
        sumSq += s->weight * s->weight;
    }
    AlbedoEstimate e;
    e.n = n;
    e.mean = sum / n;
    for (int c = 0; c < 3; ++c) e.stddev[c] = std::sqrt(std::max(0.0, sumSq[c] / n - e.mean[c] * e.mean[c]));
    return e;
}

TEST(WhiteFurnace, WhiteDiffuseReflectsEverything) {
    Bsdf white = Bsdf::diffuse({1, 1, 1});
    for (double theta : {0.0, 45.0, 89.0, 150.0}) {
        AlbedoEstimate e = estimateAlbedo(white, direction(theta, 0), 20000, 21);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], 1.0, e.tolerance()[c] + 1e-12) << "theta " << theta;
    }
}

TEST(WhiteFurnace, GlossyAlbedoIsAtMostOneAndMatchesTheModel) {
    // The model's albedo is E(wo) + base (1 - E(wo)): a white base under any coat returns
    // all the light, up to the table's error in E. The estimate must agree with albedo()
    // within k sigma plus that error, and never exceed 1 by more.
    struct Coat {
        Vec3 f0, base;
    };
    std::vector<Coat> coats = {{{1, 1, 1}, {1, 1, 1}}, {{0.04, 0.04, 0.04}, {1, 1, 1}}, {{0.5, 0.2, 0.9}, {0.7, 1, 0.2}}};
    uint64_t seed = 400;
    for (const Coat& coat : coats)
        for (double alpha : {0.01, 0.1, 0.4, 1.0})
            for (double theta : {0.0, 45.0, 80.0, 87.0}) {
                Bsdf b = Bsdf::glossy(coat.f0, coat.base, alpha);
                Vec3 wo = direction(theta, 33);
                AlbedoEstimate e = estimateAlbedo(b, wo, 20000, seed++);
                Vec3 model = b.albedo(wo);
                for (int c = 0; c < 3; ++c) {
                    double tol = e.tolerance()[c] + kGgxAlbedoTableError;
                    EXPECT_LE(e.mean[c], 1 + tol) << "alpha " << alpha << " theta " << theta << " channel " << c;
                    EXPECT_NEAR(e.mean[c], model[c], tol) << "alpha " << alpha << " theta " << theta << " channel " << c;
                    EXPECT_LE(model[c], 1.0);
                    if (coat.base[c] == 1) {
                        EXPECT_NEAR(model[c], 1.0, 1e-12);
                    }
                }
            }
}

TEST(WhiteFurnace, RandomGlossyMaterialsConserveEnergy) {
    Rng rng(13);
    for (int k = 0; k < 40; ++k) {
        Vec3 f0(rng.uniform(), rng.uniform(), rng.uniform()), base(rng.uniform(), rng.uniform(), rng.uniform());
        double alpha = std::pow(10.0, -3 * rng.uniform());
        Bsdf b = Bsdf::glossy(f0, base, alpha);
        Vec3 wo = direction(89.5 * rng.uniform(), 360 * rng.uniform());
        AlbedoEstimate e = estimateAlbedo(b, wo, 10000, 500 + k);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(e.mean[c], 0);
            EXPECT_LE(e.mean[c], 1 + e.tolerance()[c] + kGgxAlbedoTableError) << "alpha " << alpha << " wo.z " << wo.z;
        }
    }
}

TEST(GlossyCoat, SmoothCoatOverBlackReflectsF0AtNormalIncidence) {
    // At alpha 0.01 masking and the spread of microfacet normals change the coat's albedo by
    // O(alpha^2) = 1e-4 relative, so it is F0 to 1e-3 relative.
    for (double f0 : {0.02, 0.04, 0.1}) {
        Bsdf screen = Bsdf::glossy({f0, f0, f0}, {0, 0, 0}, 0.01);
        AlbedoEstimate e = estimateAlbedo(screen, Vec3(0, 0, 1), 20000, 31);
        EXPECT_NEAR(e.mean.x, f0, e.tolerance().x + 1e-3 * f0);
    }
}

TEST(GlossyCoat, AlbedoMatchesIndependentQuadrature) {
    // Sampling and eval of the coat against the nested quadrature of ggxAlbedoQuadrature,
    // which shares only the GGX terms with them (F0 = 1: the analytic 1 - ln 2 case included).
    uint64_t seed = 600;
    for (double alpha : {0.1, 0.3, 1.0})
        for (double theta : {0.0, 50.0, 80.0})
            for (double f0 : {0.04, 1.0}) {
                Bsdf coat = Bsdf::glossy({f0, f0, f0}, {0, 0, 0}, alpha);
                Vec3 wo = direction(theta, 0);
                AlbedoEstimate e = estimateAlbedo(coat, wo, 40000, seed++);
                double reference = ggxAlbedoQuadrature(wo.z, alpha, 1e-7).with(f0);
                EXPECT_NEAR(e.mean.x, reference, e.tolerance().x + 2e-7)
                    << "alpha " << alpha << " theta " << theta << " f0 " << f0;
            }
    AlbedoEstimate e = estimateAlbedo(Bsdf::glossy({1, 1, 1}, {0, 0, 0}, 1.0), Vec3(0, 0, 1), 40000, 700);
    EXPECT_NEAR(e.mean.x, 1 - std::log(2.0), e.tolerance().x);
}

TEST(GlossyCoat, BaseShowsThroughAtNormalIncidenceAndCoatDominatesAtGrazing) {
    // A screen (docs/scene-format.md, "glossy"): F0 0.05, roughness 0.1, base 0.02.
    Bsdf screen = Bsdf::glossy({0.05, 0.05, 0.05}, {0.02, 0.02, 0.02}, 0.1);
    double normal = screen.albedo(Vec3(0, 0, 1)).x, grazing = screen.albedo(direction(85, 0)).x;
    EXPECT_GT(normal, 0.05);
    EXPECT_LT(normal, 0.05 + 0.02);
    EXPECT_GT(grazing, 0.3);  // Fresnel: most light is reflected at grazing angles
}

TEST(Bsdf, DegenerateDirectionsScatterNothing) {
    for (const Bsdf& b : {Bsdf::diffuse({0.5, 0.5, 0.5}), Bsdf::glossy({0.04, 0.04, 0.04}, {0.5, 0.5, 0.5}, 0.3)}) {
        EXPECT_FALSE(b.sample(Vec3(1, 0, 0), 0.5, {0.5, 0.5}));
        EXPECT_EQ(b.eval(Vec3(1, 0, 0), Vec3(0, 0, 1)), Vec3());
        EXPECT_EQ(b.pdf(Vec3(0, 0, 1), Vec3(0, 1, 0)), 0.0);
    }
}

}  // namespace
}  // namespace luxplan
