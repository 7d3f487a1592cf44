// Student's t for intervals whose standard error comes from a few values
// (core/confidence.h), against published values.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/confidence.h>

namespace luxplan {
namespace {

TEST(Confidence, StudentCentralProbabilityMatchesClosedForms) {
    // dof 1 is Cauchy: P(|T| <= t) = 2 atan(t) / pi; dof 2: t / sqrt(2 + t^2).
    for (double t : {0.1, 1.0, 3.0, 40.0}) {
        EXPECT_NEAR(studentTCentral(t, 1), 2 * std::atan(t) / kPi, 1e-14);
        EXPECT_NEAR(studentTCentral(t, 2), t / std::sqrt(2 + t * t), 1e-14);
    }
    EXPECT_NEAR(studentTCentral(1.0, 1), 0.5, 1e-14);
    // Large dof tends to the normal: P(|Z| <= 2) = 0.9544997.
    EXPECT_NEAR(studentTCentral(2.0, 2001), 0.9544997, 2e-4);
}

TEST(Confidence, MultiplierMatchesTheTables) {
    const double z95 = 1.959963984540054;  // two-sided 95%
    // Student's two-sided 95% quantiles (any table): dof 1, 3, 7, 30.
    EXPECT_NEAR(confidenceMultiplier(z95, 1), 12.7062, 1e-4);
    EXPECT_NEAR(confidenceMultiplier(z95, 3), 3.1824, 1e-4);
    EXPECT_NEAR(confidenceMultiplier(z95, 7), 2.3646, 1e-4);
    EXPECT_NEAR(confidenceMultiplier(z95, 30), 2.0423, 1e-4);
    // The adaptive stop's z = 3 (99.73%) from eight fold values.
    EXPECT_NEAR(confidenceMultiplier(3, 7), 4.530, 1e-3);
    // Known error (dof 0) and many values: z itself.
    EXPECT_EQ(confidenceMultiplier(3, 0), 3);
    EXPECT_NEAR(confidenceMultiplier(3, 1000), 3, 0.01);
    EXPECT_EQ(confidenceMultiplier(3, 100000), 3);
    // A level that rounds to 1 still returns (for one degree of freedom, a huge multiplier).
    EXPECT_GT(confidenceMultiplier(40, 1), 1e6);
    // Fewer values, wider intervals.
    for (int dof = 1; dof < 40; ++dof) EXPECT_GT(confidenceMultiplier(3, dof), confidenceMultiplier(3, dof + 1));
}

}  // namespace
}  // namespace luxplan
