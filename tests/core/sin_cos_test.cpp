#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/rng.h>
#include <luxplan/core/sin_cos.h>

namespace luxplan {
namespace {

// Units in the last place of libm's value; near a zero of the function, where an ulp
// vanishes, an absolute bound of two ulps of 1/4 (the reduction's own rounding: the
// argument is known to about an ulp of pi/2).
double errorInUlps(double got, double want) {
    const double scale = std::max(std::abs(want), 0.25);
    return std::abs(got - want) / (std::nextafter(scale, kInf) - scale);
}

void expectMatchesLibm(double x) {
    const SinCos t = sinCos(x);
    EXPECT_LE(errorInUlps(t.sin, std::sin(x)), 2.0) << "sin(" << x << ")";
    EXPECT_LE(errorInUlps(t.cos, std::cos(x)), 2.0) << "cos(" << x << ")";
}

TEST(Trig, SinCosMatchesLibm) {
    Rng rng(7);
    for (int i = 0; i < 1000000; ++i) expectMatchesLibm((rng.uniform() - 0.25) * 8 * kPi);  // [-2 pi, 6 pi)
    // The quadrants' edges, either side; the series' ends; tiny and zero arguments.
    for (int k = -8; k <= 16; ++k)
        for (double x0 : {k * kPi / 4, k * kPi / 2})
            for (double x : {x0, std::nextafter(x0, -kInf), std::nextafter(x0, kInf), x0 - 1e-9, x0 + 1e-9}) expectMatchesLibm(x);
    for (double x : {0.0, -0.0, 1e-300, -1e-300, 1e-8, -1e-8, 1e3, -1e3, 12345.678}) expectMatchesLibm(x);
    EXPECT_EQ(sinCos(0.0).sin, 0.0);
    EXPECT_EQ(sinCos(0.0).cos, 1.0);
    // Not a number in, not a number out (as libm's), for NaN and the infinities.
    for (double x : {std::nan(""), kInf, -kInf}) {
        EXPECT_TRUE(std::isnan(sinCos(x).sin)) << x;
        EXPECT_TRUE(std::isnan(sinCos(x).cos)) << x;
    }
}

TEST(Trig, SinCosQuadrantsAndSigns) {
    // Exact quadrant values, up to the rounding of pi/2 itself.
    const double eps = 1e-15;
    for (int k = -8; k <= 8; ++k) {
        const SinCos t = sinCos(k * kPi / 2);
        const int q = ((k % 4) + 4) % 4;
        EXPECT_NEAR(t.sin, q == 1 ? 1 : q == 3 ? -1 : 0, eps) << k;
        EXPECT_NEAR(t.cos, q == 0 ? 1 : q == 2 ? -1 : 0, eps) << k;
    }
}

}  // namespace
}  // namespace luxplan
