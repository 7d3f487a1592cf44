// Thin-pane optics (ThinGlass) against a bounce-by-bounce simulation and textbook
// values, and the delta behaviour of the glass and mirror BSDFs.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/rng.h>
#include <luxplan/materials/bsdf.h>
#include <luxplan/materials/microfacet.h>
#include "support/directions.h"

namespace luxplan {
namespace {

// Follows the flux of one polarization through the pane bounce by bounce: the
// independent check of the closed-form geometric series.
PaneResponse simulatePane(double cosTheta, double ior, double tau0) {
    PaneResponse total;
    double c = std::abs(cosTheta);
    double cosT = std::sqrt(1 - (1 - c * c) / (ior * ior));
    double tau = std::pow(tau0, 1 / cosT);
    PolarizedReflectance fr = dielectricFresnel(c, ior);
    for (double r : {fr.s, fr.p}) {
        double reflected = r, transmitted = 0;
        double inside = 1 - r;  // flux just inside the first face, heading to the second
        for (int bounce = 0; bounce < 10000 && inside > 1e-300; ++bounce) {
            inside *= tau;                        // crossing the glass
            double out = inside * (1 - r);        // leaves through the face it reached
            (bounce % 2 == 0 ? transmitted : reflected) += out;
            inside *= r;                          // reflected back inside
        }
        total.reflectance += 0.5 * reflected;
        total.transmittance += 0.5 * transmitted;
    }
    return total;
}

using test::direction;

TEST(ThinGlass, NormalTransmittanceIsExactlyTheGivenOne) {
    for (double t0 : {0.0, 0.05, 0.3, 0.6, 0.8, 0.88, 0.9, 0.9183, 0.93, 0.97, 0.999, 1.0}) {
        ThinGlass pane(t0);
        EXPECT_NEAR(pane.transmittance(1.0), t0, 1e-12) << "T0 " << t0;
        EXPECT_NEAR(pane.transmittance(-1.0), t0, 1e-12) << "from the other side";
        EXPECT_NEAR(thinGlassTransmittance(1.0, t0), t0, 1e-12);
    }
    EXPECT_NEAR(thinGlassTransmittance(1.0), kDefaultGlassTransmittance, 1e-12);
}

TEST(ThinGlass, ClearPaneHasTheTextbookTransmittance) {
    // A lossless pane of index n transmits 2n / (n^2 + 1) at normal incidence (0.9183
    // for n = 1.52) and reflects the rest at every angle.
    const double n = kGlassIor, tMax = 2 * n / (n * n + 1);
    ThinGlass pane(tMax);
    EXPECT_NEAR(pane.ior(), n, 1e-9);
    EXPECT_NEAR(pane.internalTransmittance(), 1.0, 1e-9);
    for (double c = 0.0; c <= 1.0; c += 0.01) {
        PaneResponse r = pane.response(c);
        EXPECT_NEAR(r.reflectance + r.transmittance, 1.0, 1e-9) << "cos " << c;
    }
}

TEST(ThinGlass, ClearerThanGlassLowersTheIndex) {
    ThinGlass pane(0.97);
    EXPECT_LT(pane.ior(), kGlassIor);
    EXPECT_GT(pane.ior(), 1.0);
    EXPECT_EQ(pane.internalTransmittance(), 1.0);
    ThinGlass invisible(1.0);
    EXPECT_NEAR(invisible.ior(), 1.0, 1e-15);
    EXPECT_NEAR(invisible.transmittance(0.2), 1.0, 1e-12);
}

TEST(ThinGlass, ClosedFormMatchesBounceSimulation) {
    for (double t0 : {0.0, 0.2, 0.5, 0.88, 0.9183}) {
        ThinGlass pane(t0);
        for (double c : {1.0, 0.9, 0.6, 0.3, 0.1, 0.01}) {
            PaneResponse a = pane.response(c);
            PaneResponse b = simulatePane(c, pane.ior(), pane.internalTransmittance());
            EXPECT_NEAR(a.reflectance, b.reflectance, 1e-12) << "T0 " << t0 << " cos " << c;
            EXPECT_NEAR(a.transmittance, b.transmittance, 1e-12) << "T0 " << t0 << " cos " << c;
            EXPECT_NEAR(thinGlassReflectance(c, t0), a.reflectance, 1e-15);
            EXPECT_NEAR(thinGlassTransmittance(c, t0), a.transmittance, 1e-15);
        }
    }
}

TEST(ThinGlass, EnergyIsConservedAndTransmittanceFallsAtGrazingAngles) {
    for (double t0 : {0.0, 0.4, 0.88, 0.95}) {
        ThinGlass pane(t0);
        double previousT = pane.transmittance(1.0);
        for (int k = 1; k <= 900; ++k) {
            double c = std::cos(radians(0.1 * k));
            PaneResponse r = pane.response(c);
            ASSERT_GE(r.reflectance, 0);
            ASSERT_GE(r.transmittance, 0);
            ASSERT_GE(r.absorptance(), -1e-15) << "T0 " << t0 << " cos " << c;
            ASSERT_NEAR(r.reflectance + r.transmittance + r.absorptance(), 1.0, 1e-15);
            // Transmittance falls monotonically with the angle. (Reflectance need not rise near
            // normal incidence: p-polarized reflection falls towards Brewster's angle.)
            ASSERT_LE(r.transmittance, previousT + 1e-15) << "T0 " << t0 << " angle " << 0.1 * k;
            previousT = r.transmittance;
        }
        EXPECT_EQ(pane.transmittance(0.0), 0.0);
        EXPECT_EQ(pane.reflectance(0.0), 1.0);
        EXPECT_GT(pane.reflectance(std::cos(radians(70.0))), pane.reflectance(1.0));
        EXPECT_LT(pane.transmittance(std::cos(radians(85.0))), 0.5 * pane.transmittance(1.0) + 1e-15);
    }
}

TEST(ThinGlassBsdf, DeltaReflectionAndTransmissionInProportion) {
    Bsdf glass = Bsdf::thinGlass(0.88);
    EXPECT_TRUE(glass.isDelta());
    EXPECT_TRUE(glass.passesStraight());
    Rng rng(5);
    for (double theta : {0.0, 40.0, 70.0, 85.0}) {
        for (bool below : {false, true}) {
            Vec3 wo = direction(below ? 180 - theta : theta, 30);
            PaneResponse pr = glass.glass().response(wo.z);
            double pReflect = pr.reflectance / (pr.reflectance + pr.transmittance);
            const int n = 20000;
            int reflections = 0;
            for (int k = 0; k < n; ++k) {
                auto s = glass.sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()});
                ASSERT_TRUE(s);
                ASSERT_TRUE(s->isDelta);
                if (s->isTransmission) {
                    ASSERT_EQ(s->wi, -wo);
                    ASSERT_NEAR(s->pdf, 1 - pReflect, 1e-12);
                } else {
                    ++reflections;
                    ASSERT_NEAR(s->wi.x, -wo.x, 1e-15);
                    ASSERT_NEAR(s->wi.y, -wo.y, 1e-15);
                    ASSERT_NEAR(s->wi.z, wo.z, 1e-15);
                    ASSERT_NEAR(s->pdf, pReflect, 1e-12);
                }
                // Either way the throughput is R + T, and weight = f |cos| / pdf.
                double total = pr.reflectance + pr.transmittance;
                ASSERT_NEAR(s->weight.x, total, 1e-12);
                ASSERT_NEAR(s->f.y * std::abs(s->wi.z) / s->pdf, total, 1e-12);
                ASSERT_EQ(glass.eval(wo, s->wi), Vec3());
                ASSERT_EQ(glass.pdf(wo, s->wi), 0.0);
            }
            // Binomial count: 5 sigma.
            double sigma = std::sqrt(n * pReflect * (1 - pReflect));
            EXPECT_NEAR(reflections, n * pReflect, 5 * sigma + 1e-9) << "theta " << theta;
            EXPECT_NEAR(glass.straightTransmittance(wo.z), pr.transmittance, 1e-15);
            EXPECT_NEAR(glass.albedo(wo).x, pr.reflectance + pr.transmittance, 1e-15);
        }
    }
}

TEST(MirrorBsdf, DeltaReflectionScaledByReflectance) {
    Vec3 rho(0.9, 0.85, 0.8);
    Bsdf mirror = Bsdf::mirror(rho);
    EXPECT_TRUE(mirror.isDelta());
    EXPECT_FALSE(mirror.passesStraight());
    EXPECT_EQ(mirror.straightTransmittance(1.0), 0.0);
    for (double theta : {0.0, 30.0, 80.0, 100.0, 170.0}) {
        Vec3 wo = direction(theta, 200);
        auto s = mirror.sample(wo, 0.3, {0.6, 0.1});
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->isDelta);
        EXPECT_FALSE(s->isTransmission);
        EXPECT_NEAR(s->wi.x, -wo.x, 1e-15);
        EXPECT_NEAR(s->wi.y, -wo.y, 1e-15);
        EXPECT_EQ(s->wi.z, wo.z);  // the same side: two-sided
        EXPECT_EQ(s->weight, rho);
        EXPECT_EQ(s->pdf, 1.0);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c] * std::abs(s->wi.z) / s->pdf, rho[c], 1e-15);
        EXPECT_EQ(mirror.eval(wo, s->wi), Vec3());
        EXPECT_EQ(mirror.pdf(wo, s->wi), 0.0);
        EXPECT_EQ(mirror.albedo(wo), rho);
    }
    EXPECT_FALSE(mirror.sample(Vec3(1, 0, 0), 0.5, {0.5, 0.5}));  // wo in the surface
}

TEST(MakeBsdf, MapsEveryMaterialType) {
    Material m;
    m.type = MaterialType::Diffuse;
    m.reflectance = {0.2, 0.3, 0.4};
    Bsdf d = makeBsdf(m);
    EXPECT_EQ(d.type(), BsdfType::Diffuse);
    EXPECT_EQ(d.reflectance(), m.reflectance);

    m.type = MaterialType::Glossy;
    m.reflectance = {0.05, 0.05, 0.05};
    m.base = {0.02, 0.02, 0.02};
    m.roughness = 0.1;
    Bsdf g = makeBsdf(m);
    EXPECT_EQ(g.type(), BsdfType::Glossy);
    EXPECT_EQ(g.base(), m.base);
    EXPECT_EQ(g.alpha(), 0.1);
    m.roughness = 0;  // out of range: clamped to the smallest supported alpha
    EXPECT_EQ(makeBsdf(m).alpha(), kMinGgxAlpha);

    m.type = MaterialType::Glass;
    m.transmittance = 0.7;
    Bsdf gl = makeBsdf(m);
    EXPECT_EQ(gl.type(), BsdfType::ThinGlass);
    EXPECT_NEAR(gl.straightTransmittance(1.0), 0.7, 1e-12);
    EXPECT_EQ(gl.glass().ior(), kGlassIor);

    m.type = MaterialType::Mirror;
    m.reflectance = {1.5, 0.9, -1};  // out of range: clamped to [0, 1]
    Bsdf mi = makeBsdf(m);
    EXPECT_EQ(mi.type(), BsdfType::Mirror);
    EXPECT_EQ(mi.reflectance(), Vec3(1, 0.9, 0));
}

}  // namespace
}  // namespace luxplan
