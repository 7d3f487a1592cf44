// The statistics over a sampler's points (core/point_statistics.h): EN 12464-1's
// Em, Emin, Emax and U0 = Emin / Em, and their standard errors against the spread
// of simulated measurements.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/core/point_statistics.h>
#include <luxplan/core/rng.h>

namespace luxplan {
namespace {

const std::vector<double> kValues{400, 300, 500, 450, 350}, kErrors{8, 6, 10, 9, 7};

TEST(PointStatistics, MeanMinMaxAndUniformity) {
    const PointStatistics s = pointStatistics(kValues, kErrors);
    EXPECT_DOUBLE_EQ(s.mean.value, 400);
    EXPECT_DOUBLE_EQ(s.mean.standardError, std::sqrt(64.0 + 36 + 100 + 81 + 49) / 5);
    EXPECT_EQ(s.min.value, 300);
    EXPECT_EQ(s.min.standardError, 6);  // the error of the point that is the min
    EXPECT_EQ(s.max.value, 500);
    EXPECT_EQ(s.max.standardError, 10);
    EXPECT_DOUBLE_EQ(s.u0.value, 0.75);
    // Delta method with Cov(min, mean) = 6^2 / 5: (36 (1 - 2 * 0.75 / 5) + 0.75^2 * 330 / 25) / 400^2.
    EXPECT_NEAR(s.u0.standardError, std::sqrt((36 * 0.7 + 0.5625 * 13.2) / 160000), 1e-15);
    EXPECT_EQ(&s.of(Statistic::U0), &s.u0);
    EXPECT_EQ(&s.of(Statistic::Min), &s.min);
}

TEST(PointStatistics, ErrorsMatchTheSpreadOfSimulatedMeasurements) {
    // Each point measured as its value plus normal noise of its error, 100000 times:
    // the standard deviations of the min, the mean and U0 over the draws are what the
    // errors claim (the min point is 50 lx, seven errors, clear of the next, so it
    // is always the same point). Without the covariance term U0's error would be 15%
    // too large.
    Rng rng(7);
    auto normal = [&rng] { return std::sqrt(-2 * std::log(1 - rng.uniform())) * std::cos(2 * kPi * rng.uniform()); };
    const int draws = 100000;
    double sums[3] = {}, squares[3] = {};
    std::vector<double> v(kValues.size());
    for (int d = 0; d < draws; ++d) {
        for (size_t i = 0; i < v.size(); ++i) v[i] = kValues[i] + kErrors[i] * normal();
        const PointStatistics s = pointStatistics(v, kErrors);
        const double x[3] = {s.min.value, s.mean.value, s.u0.value};
        for (int k = 0; k < 3; ++k) sums[k] += x[k], squares[k] += x[k] * x[k];
    }
    const PointStatistics s = pointStatistics(kValues, kErrors);
    const double claimed[3] = {s.min.standardError, s.mean.standardError, s.u0.standardError};
    for (int k = 0; k < 3; ++k) {
        const double mean = sums[k] / draws, sd = std::sqrt(squares[k] / draws - mean * mean);
        // The sample deviation of 10^5 draws is good to 0.2%; the delta method to about sigma / mean.
        EXPECT_NEAR(sd / claimed[k], 1, 0.02) << "statistic " << k;
    }
}

TEST(PointStatistics, OnePointIsUniformAndDarknessIsNot) {
    const PointStatistics one = pointStatistics({250}, {5});
    EXPECT_EQ(one.u0.value, 1);
    EXPECT_EQ(one.u0.standardError, 0);  // min and mean are the same number
    EXPECT_EQ(one.min.value, one.mean.value);
    const PointStatistics dark = pointStatistics({0, 0, 0}, {0, 0, 0});
    EXPECT_EQ(dark.u0.value, 0);
    EXPECT_EQ(dark.u0.standardError, 0);
    const PointStatistics none = pointStatistics({}, {});
    EXPECT_EQ(none.mean.value, 0);
    EXPECT_EQ(none.u0.value, 0);
}

TEST(PointStatistics, NamesParseAndPrint) {
    EXPECT_EQ(statisticNames().parse("u0"), Statistic::U0);
    EXPECT_EQ(statisticNames().parse("mean"), Statistic::Mean);
    EXPECT_FALSE(statisticNames().parse("U0"));
    EXPECT_STREQ(statisticNames().name(Statistic::Max), "max");
}

}  // namespace
}  // namespace luxplan
