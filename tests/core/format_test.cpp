// The number formats of core/format.h, against printf's.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/format.h>
#include <luxplan/core/math.h>

namespace luxplan {
namespace {

TEST(Format, FixedDigits) {
    EXPECT_EQ(fixedDigits(2.345, 2), "2.35");  // 2.345 is 2.34500000000000019984
    EXPECT_EQ(fixedDigits(-0.04, 1), "-0.0");
    EXPECT_EQ(fixedDigits(519.25, 0), "519");
    EXPECT_EQ(fixedDigits(1e300, 0).size(), 301u);  // every digit, none cut off
    EXPECT_EQ(fixedDigits(kInf, 3), "inf");
}

TEST(Format, SignificantDigits) {
    EXPECT_EQ(significantDigits(0.000123456, 3), "0.000123");
    EXPECT_EQ(significantDigits(1e7, 6), "1e+07");
    EXPECT_EQ(significantDigits(19, 6), "19");
    EXPECT_EQ(formatNumber(0.1), "0.1");
    EXPECT_EQ(formatNumber(1.0 / 3), "0.3333333333");
    EXPECT_EQ(formatNumber(-kInf), "-inf");
}

TEST(Format, CompactNumber) {
    EXPECT_EQ(compactNumber(0), "0");
    EXPECT_EQ(compactNumber(12.5), "12.5");
    EXPECT_EQ(compactNumber(250.4), "250");
    EXPECT_EQ(compactNumber(2270), "2270");
    EXPECT_EQ(compactNumber(25000), "25k");
    EXPECT_EQ(compactNumber(-0.125), "-0.125");
}

}  // namespace
}  // namespace luxplan
