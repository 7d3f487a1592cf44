// GGX distribution, Smith masking, visible-normal sampling and Fresnel terms against
// their defining identities.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/rng.h>
#include <luxplan/materials/microfacet.h>
#include "support/directions.h"

namespace luxplan {
namespace {

using test::direction;

// int over the upper hemisphere of g(h) dh, in GGX slope coordinates
// tan(theta) = alpha tan(pi v / 2) (spreads the peak evenly), midpoint rule in (v, phi).
template <class G>
double integrateOverNormals(const G& g, double alpha, int nv, int nphi) {
    double sum = 0;
    for (int i = 0; i < nv; ++i) {
        double v = (i + 0.5) / nv;
        double m = alpha * std::tan(0.5 * kPi * v);
        double cosH = 1 / std::sqrt(1 + m * m), sinH = m * cosH;
        // d(theta)/dv = alpha (pi/2) (1 + tan^2(pi v/2)) / (1 + m^2), times sin(theta).
        double t = std::tan(0.5 * kPi * v);
        double jac = alpha * 0.5 * kPi * (1 + t * t) / (1 + m * m) * sinH;
        for (int j = 0; j < nphi; ++j) {
            double phi = 2 * kPi * (j + 0.5) / nphi;
            sum += g(Vec3(sinH * std::cos(phi), sinH * std::sin(phi), cosH)) * jac;
        }
    }
    return sum * (1.0 / nv) * (2 * kPi / nphi);
}

TEST(Ggx, ProjectedAreaOfMicrofacetsIsOne) {
    // int D(h) cos(theta_h) dh = 1. Tolerance: the midpoint rule's own change when the
    // grid is doubled, which bounds its error for this smooth integrand.
    for (double alpha : {0.01, 0.1, 0.5, 1.0}) {
        auto g = [&](const Vec3& h) { return ggxD(h, alpha) * h.z; };
        double coarse = integrateOverNormals(g, alpha, 2000, 4);
        double fine = integrateOverNormals(g, alpha, 4000, 4);
        EXPECT_NEAR(fine, 1.0, 2 * std::abs(fine - coarse) + 1e-9) << "alpha " << alpha;
    }
}

TEST(Ggx, ProjectedAreaTowardsAnyDirectionMatchesSmithG1) {
    // int max(0, w.h) D(h) dh = w.z / G1(w): the visible-normal pdf integrates to 1.
    for (double alpha : {0.05, 0.3, 1.0})
        for (double theta : {0.0, 60.0, 89.0}) {
            Vec3 wo = direction(theta, 20);
            auto g = [&](const Vec3& h) { return ggxVisibleNormalPdf(wo, h, alpha); };
            double coarse = integrateOverNormals(g, alpha, 400, 256);
            double fine = integrateOverNormals(g, alpha, 800, 512);
            double tol = 2 * std::abs(fine - coarse) + 1e-6;
            ASSERT_LT(tol, 1e-3) << "the quadrature is too coarse to test anything";
            EXPECT_NEAR(fine, 1.0, tol) << "alpha " << alpha << " theta " << theta;
        }
}

TEST(Ggx, MaskingShadowingBounds) {
    Rng rng(3);
    for (int k = 0; k < 1000; ++k) {
        double alpha = 0.001 + rng.uniform();
        Vec3 a = direction(90 * rng.uniform(), 360 * rng.uniform());
        Vec3 b = direction(90 * rng.uniform(), 360 * rng.uniform());
        double g2 = ggxG2(a, b, alpha);
        EXPECT_GE(g2, 0);
        EXPECT_LE(g2, std::min(ggxG1(a, alpha), ggxG1(b, alpha)) + 1e-15);
        EXPECT_GE(g2, ggxG1(a, alpha) * ggxG1(b, alpha) - 1e-15);  // correlation never hurts
        EXPECT_EQ(g2, ggxG2(b, a, alpha));
    }
    EXPECT_EQ(ggxG1(Vec3(0, 0, 1), 0.7), 1.0);
}

TEST(Ggx, VisibleNormalsAreVisibleAndFinite) {
    Rng rng(4);
    for (double alpha : {kMinGgxAlpha, 0.05, 0.5, 1.0})
        for (double theta : {0.0, 30.0, 80.0, 89.99}) {
            Vec3 wo = direction(theta, 75);
            for (int k = 0; k < 20000; ++k) {
                Vec3 h = sampleGgxVisibleNormal(wo, alpha, {rng.uniform(), rng.uniform()});
                ASSERT_TRUE(std::isfinite(h.x) && std::isfinite(h.y) && std::isfinite(h.z));
                ASSERT_NEAR(length(h), 1.0, 1e-12);
                ASSERT_GE(dot(wo, h), -1e-12) << "alpha " << alpha << " theta " << theta;
            }
        }
}

TEST(Reflect, MirrorsAwayFromTheSurface) {
    Vec3 wo = direction(35, 80), n(0, 0, 1);
    Vec3 r = reflect(wo, n);
    EXPECT_NEAR(r.x, -wo.x, 1e-15);
    EXPECT_NEAR(r.y, -wo.y, 1e-15);
    EXPECT_NEAR(r.z, wo.z, 1e-15);
    // A ray travelling towards the surface: reflect its reverse.
    Vec3 d = -wo, bounced = reflect(-d, n);
    EXPECT_NEAR(bounced.z, -d.z, 1e-15);
    EXPECT_NEAR(bounced.x, d.x, 1e-15);
}

TEST(Fresnel, DielectricKnownValues) {
    const double n = 1.52;
    PolarizedReflectance r0 = dielectricFresnel(1.0, n);
    EXPECT_NEAR(r0.s, std::pow((n - 1) / (n + 1), 2), 1e-15);
    EXPECT_NEAR(r0.p, r0.s, 1e-15);
    // Brewster's angle: p-polarized light is not reflected where tan(theta) = n.
    PolarizedReflectance rb = dielectricFresnel(std::cos(std::atan(n)), n);
    EXPECT_NEAR(rb.p, 0.0, 1e-15);
    EXPECT_GT(rb.s, r0.s);
    PolarizedReflectance rg = dielectricFresnel(0.0, n);
    EXPECT_EQ(rg.s, 1.0);
    EXPECT_EQ(rg.p, 1.0);
    PolarizedReflectance none = dielectricFresnel(0.3, 1.0);
    EXPECT_NEAR(none.s + none.p, 0.0, 1e-15);
}

TEST(Fresnel, SchlickEndpoints) {
    Vec3 f0(0.04, 0.5, 1.0);
    EXPECT_EQ(schlickFresnel(f0, 1.0), f0);
    EXPECT_EQ(schlickFresnel(f0, 0.0), Vec3(1, 1, 1));
}

}  // namespace
}  // namespace luxplan
