// The sine and cosine of one angle together, for the samplers' angles (a few turns at
// most): the argument brought to [-pi/4, pi/4] by the nearest multiple of pi/2 (pi/2 in
// three parts, Cody and Waite 1980), then the Taylor series of both, cut where the
// next term is below an ulp. Within two ulps of libm's correctly rounded values
// (Trig.SinCosMatchesLibm), with no call and no argument checks: half the cost of
// sincos, which was 2.7% of the search's profile.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include <luxplan/core/math.h>

namespace luxplan {

struct SinCos {
    double sin, cos;
};

namespace sin_cos_detail {
// pi/2 = hi + mid + lo: hi keeps the top 33 bits of double(pi/2), so that q * hi is
// exact for |q| < 2^20; mid is the rest of double(pi/2); lo = pi/2 - double(pi/2).
inline constexpr double kHalfPiHi = std::bit_cast<double>(std::bit_cast<uint64_t>(kPi / 2) & ~uint64_t(0xfffff));
inline constexpr double kHalfPiMid = kPi / 2 - kHalfPiHi;
inline constexpr double kHalfPiLo = 6.123233995736766e-17;

// sin r and cos r for |r| <= pi/4 (+ rounding): r^17/17! < 5e-17 and r^18/18! < 3e-18.
inline double sinNear(double r) {
    const double r2 = r * r;
    const double p = -1.0 / 6 +
                     r2 * (1.0 / 120 +
                           r2 * (-1.0 / 5040 +
                                 r2 * (1.0 / 362880 +
                                       r2 * (-1.0 / 39916800 + r2 * (1.0 / 6227020800 + r2 * (-1.0 / 1307674368000))))));
    return r + r * r2 * p;
}
inline double cosNear(double r) {
    const double r2 = r * r;
    const double p = 1.0 / 24 +
                     r2 * (-1.0 / 720 +
                           r2 * (1.0 / 40320 +
                                 r2 * (-1.0 / 3628800 +
                                       r2 * (1.0 / 479001600 + r2 * (-1.0 / 87178291200 + r2 * (1.0 / 20922789888000))))));
    return 1 - 0.5 * r2 + r2 * r2 * p;
}
}  // namespace sin_cos_detail

// For |x| below about 10^6 (an exact reduction); the samplers' angles lie in a few turns.
inline SinCos sinCos(double x) {
    using namespace sin_cos_detail;
    // Rounded to the nearest integer by the addition (|x| * 2 / pi < 2^51), whose low
    // mantissa bits are then q's in two's complement: no conversion to an integer,
    // which a NaN would make undefined (a NaN in gives NaNs out).
    const double shifted = x * (2 / kPi) + 0x1.8p52;
    const double q = shifted - 0x1.8p52;
    const double r = ((x - q * kHalfPiHi) - q * kHalfPiMid) - q * kHalfPiLo;
    const double s = sinNear(r), c = cosNear(r);
    // Quadrant n: (s, c), (c, -s), (-s, -c), (-c, s); by selects and sign bits, since
    // the quadrant of a random angle is a coin the branch predictor cannot call.
    const uint64_t n = std::bit_cast<uint64_t>(shifted);
    const uint64_t sSign = (n & 2) << 62, cSign = ((n + 1) & 2) << 62;
    const bool swap = n & 1;
    return {std::bit_cast<double>(std::bit_cast<uint64_t>(swap ? c : s) ^ sSign),
            std::bit_cast<double>(std::bit_cast<uint64_t>(swap ? s : c) ^ cSign)};
}

}  // namespace luxplan
