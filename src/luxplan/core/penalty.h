// The penalty of Eq. 2 of the paper (Vitsas et al. 2020): zero inside [bMin, bMax],
// k * distance^alpha outside, with k = bRej^-alpha so that P = 1 at distance bRej.
#pragma once

#include <cmath>

namespace luxplan {

inline double penalty(double c, double bMin, double bMax, double bRej, double alpha) {
    double k = std::pow(bRej, -alpha);
    if (c <= bMin) return c == bMin ? 0.0 : k * std::pow(bMin - c, alpha);
    if (c >= bMax) return c == bMax ? 0.0 : k * std::pow(c - bMax, alpha);
    return 0.0;
}

}  // namespace luxplan
