// The translucent (diffuse-transmitting) BSDF: its two Lambertian lobes, energy
// balance (white furnace), the split of the flux between the sides, reciprocity
// and its inputs. Sampling against the pdf is in bsdf_test.cpp's chi-square cases.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/rng.h>
#include <luxplan/materials/bsdf.h>
#include "support/directions.h"

namespace luxplan {
namespace {

using test::direction;

using test::kSigmas;

TEST(Translucent, TwoLambertianLobes) {
    Bsdf b = Bsdf::translucent({0.5, 0.4, 0.3}, {0.2, 0.3, 0.4});
    EXPECT_EQ(b.type(), BsdfType::Translucent);
    EXPECT_FALSE(b.isDelta());
    EXPECT_FALSE(b.passesStraight());
    EXPECT_TRUE(b.hasDiffuseTransmission());
    EXPECT_EQ(b.straightTransmittance(1.0), 0.0);  // it scatters: shadow rays stop at it
    for (double thetaO : {10.0, 80.0, 120.0})
        for (double thetaI : {5.0, 60.0, 100.0, 170.0}) {
            Vec3 wo = direction(thetaO, 30), wi = direction(thetaI, 250);
            bool same = wo.z * wi.z > 0;
            Vec3 expected = (same ? Vec3(0.5, 0.4, 0.3) : Vec3(0.2, 0.3, 0.4)) * kInvPi;
            Vec3 f = b.eval(wo, wi);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], expected[c], 1e-15);
            // Reciprocal, and the same seen from the other side.
            EXPECT_EQ(b.eval(wi, wo), f);
            EXPECT_EQ(b.eval(-wo, -wi), f);
            double pR = luminance(Vec3(0.5, 0.4, 0.3)) / (luminance(Vec3(0.5, 0.4, 0.3)) + luminance(Vec3(0.2, 0.3, 0.4)));
            EXPECT_NEAR(b.pdf(wo, wi), (same ? pR : 1 - pR) * std::abs(wi.z) / kPi, 1e-15);
        }
    EXPECT_EQ(b.albedo(direction(40, 0)), Vec3(0.5, 0.4, 0.3) + Vec3(0.2, 0.3, 0.4));
    EXPECT_EQ(b.eval(Vec3(1, 0, 0), Vec3(0, 0, 1)), Vec3());  // grazing: nothing
    EXPECT_EQ(b.pdf(Vec3(0, 0, 1), Vec3(0, 1, 0)), 0.0);
    EXPECT_FALSE(b.sample(Vec3(1, 0, 0), 0.5, {0.5, 0.5}));
}

TEST(Translucent, WhiteFurnaceEveryLumenLeavesOnOneSideOrTheOther) {
    // A lossless grey sheet (rho + tau = 1): every sample carries weight 1.
    Rng rng(71);
    for (double rho : {0.0, 0.3, 0.7, 1.0}) {
        Bsdf b = Bsdf::translucent({rho, rho, rho}, {1 - rho, 1 - rho, 1 - rho});
        for (double theta : {0.0, 50.0, 89.0, 140.0})
            for (int k = 0; k < 2000; ++k) {
                auto s = b.sample(direction(theta, 10), rng.uniform(), {rng.uniform(), rng.uniform()});
                ASSERT_TRUE(s);
                for (int c = 0; c < 3; ++c) ASSERT_NEAR(s->weight[c], 1.0, 1e-12) << "rho " << rho;
            }
    }
}

TEST(Translucent, TheFluxSplitsAsReflectanceAndTransmittance) {
    // Monte Carlo: the mean weight of the samples on wo's side is rho, on the other tau,
    // per channel, within 5 sigma; the energy lost is 1 - rho - tau.
    const Vec3 rho(0.45, 0.3, 0.1), tau(0.25, 0.5, 0.6);
    Bsdf b = Bsdf::translucent(rho, tau);
    const int n = 40000;
    for (double theta : {20.0, 130.0}) {
        Vec3 wo = direction(theta, 75);
        Rng rng(hashValues({72, uint64_t(theta)}));
        Vec3 sum[2], sumSq[2];
        for (int k = 0; k < n; ++k) {
            auto s = b.sample(wo, rng.uniform(), {rng.uniform(), rng.uniform()});
            ASSERT_TRUE(s);
            int side = s->isTransmission ? 1 : 0;
            ASSERT_EQ(s->isTransmission, s->wi.z * wo.z < 0);
            sum[side] += s->weight, sumSq[side] += s->weight * s->weight;
            // (a sample adds 0 to the other side's mean)
        }
        for (int side = 0; side < 2; ++side) {
            Vec3 truth = side ? tau : rho;
            for (int c = 0; c < 3; ++c) {
                double mean = sum[side][c] / n, var = sumSq[side][c] / n - mean * mean;
                EXPECT_NEAR(mean, truth[c], kSigmas * std::sqrt(var / n) + 1e-12) << "side " << side << " channel " << c;
            }
        }
    }
}

TEST(Translucent, InputsAreClampedAndNeverCreateLight) {
    Bsdf b = Bsdf::translucent({0.8, -0.2, 0.5}, {0.6, 1.5, 0.5});
    // Red: 0.8 + 0.6 scaled to sum 1; green: 0 and 1; blue as given.
    EXPECT_NEAR(b.reflectance().x, 0.8 / 1.4, 1e-15);
    EXPECT_NEAR(b.transmittance().x, 0.6 / 1.4, 1e-15);
    EXPECT_EQ(b.reflectance().y, 0.0);
    EXPECT_EQ(b.transmittance().y, 1.0);
    EXPECT_EQ(b.reflectance().z, 0.5);
    EXPECT_EQ(b.transmittance().z, 0.5);
    // A black sheet scatters nothing, on either side.
    Bsdf black = Bsdf::translucent({0, 0, 0}, {0, 0, 0});
    auto s = black.sample(direction(30, 0), 0.7, {0.3, 0.6});
    ASSERT_TRUE(s);
    EXPECT_EQ(s->weight, Vec3());
    // makeBsdf reads the material's two colours.
    Material m;
    m.type = MaterialType::Translucent;
    m.reflectance = Vec3(0.4, 0.4, 0.4);
    m.diffuseTransmittance = Vec3(0.3, 0.2, 0.1);
    Bsdf made = makeBsdf(m);
    EXPECT_EQ(made.type(), BsdfType::Translucent);
    EXPECT_EQ(made.transmittance(), Vec3(0.3, 0.2, 0.1));
}

}  // namespace
}  // namespace luxplan
