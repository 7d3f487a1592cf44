// The shared estimator's formulas and NaN/inf policy, and the shared parallel loop.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>
#include "support/threads.h"

namespace luxplan {
namespace {

TEST(MeanEstimator, MeanVarianceAndStandardError) {
    MeanEstimator e;
    for (double x : {1.0, 2.0, 4.0, 7.0}) e.add(x);
    EXPECT_EQ(e.count(), 4u);
    EXPECT_EQ(e.dropped(), 0u);
    EXPECT_DOUBLE_EQ(e.mean(), 3.5);
    EXPECT_DOUBLE_EQ(e.variance(), 7.0);  // sum of squared deviations 21, over n - 1 = 3
    EXPECT_DOUBLE_EQ(e.standardError(), std::sqrt(7.0 / 4));
    EXPECT_DOUBLE_EQ(e.varianceOfMean(), 7.0 / 4);
}

TEST(MeanEstimator, NonFiniteSamplesAreDroppedAndCounted) {
    MeanEstimator clean, dirty;
    for (double x : {0.5, 1.5, 3.0}) clean.add(x);
    dirty.add(std::numeric_limits<double>::quiet_NaN());
    for (double x : {0.5, 1.5}) dirty.add(x);
    dirty.add(std::numeric_limits<double>::infinity());
    dirty.add(3.0);
    dirty.add(-std::numeric_limits<double>::infinity());
    EXPECT_EQ(dirty.count(), 3u);
    EXPECT_EQ(dirty.dropped(), 3u);
    EXPECT_EQ(dirty.mean(), clean.mean());
    EXPECT_EQ(dirty.standardError(), clean.standardError());
}

TEST(MeanEstimator, FewSamples) {
    MeanEstimator none;
    none.add(std::nan(""));
    EXPECT_EQ(none.mean(), 0);
    EXPECT_EQ(none.standardError(), 0);
    MeanEstimator one;
    one.add(5);
    EXPECT_EQ(one.mean(), 5);
    EXPECT_EQ(one.variance(), 0);
    EXPECT_EQ(one.varianceOfMean(), 0);
}

TEST(ParallelFor, EveryIndexOnceWhateverTheThreadCount) {
    auto run = [] {
        std::vector<double> out(1000, -1);
        parallelFor(out.size(), [&](size_t i) { out[i] = std::sqrt(double(i)); });
        return out;
    };
    std::vector<double> one = test::withThreads(1, run), four = test::withThreads(4, run);
    EXPECT_EQ(one, four);
    for (size_t i = 0; i < one.size(); ++i) EXPECT_EQ(one[i], std::sqrt(double(i)));
    parallelFor(0, [](size_t) { FAIL(); });
}

}  // namespace
}  // namespace luxplan
