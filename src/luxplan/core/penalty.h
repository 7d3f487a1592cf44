// The penalty of Eq. 2 of the paper (Vitsas et al. 2020): zero inside [bMin, bMax],
// k * distance^alpha outside, with k = bRej^-alpha so that P = 1 at distance bRej.
#pragma once

#include <cmath>
#include <limits>

namespace luxplan {

// A value that is not a number (or infinite) is never on target: its penalty is
// infinite (lighting terms refuse such a value before, naming the sampler).
inline double penalty(double c, double bMin, double bMax, double bRej, double alpha) {
    if (!std::isfinite(c)) return std::numeric_limits<double>::infinity();
    double k = std::pow(bRej, -alpha);
    if (c <= bMin) return c == bMin ? 0.0 : k * std::pow(bMin - c, alpha);
    if (c >= bMax) return c == bMax ? 0.0 : k * std::pow(c - bMax, alpha);
    return 0.0;
}

}  // namespace luxplan
