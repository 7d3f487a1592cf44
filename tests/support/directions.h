// Directions and tolerances the BSDF tests share.
#pragma once

#include <cmath>

#include <luxplan/core/math.h>

namespace luxplan::test {

// The unit direction at polar angle thetaDeg from +z and azimuth phiDeg from +x.
inline Vec3 direction(double thetaDeg, double phiDeg) {
    const double t = radians(thetaDeg), p = radians(phiDeg);
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// For mean-value checks: |estimate - truth| <= kSigmas * stddev / sqrt(n). P(|z| > 5) is
// 5.7e-7 per check, so a few hundred checks fail spuriously with p < 1e-3.
inline constexpr double kSigmas = 5;

}  // namespace luxplan::test
