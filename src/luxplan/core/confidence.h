// Confidence intervals for a mean: how many standard errors a two-sided interval at
// the level of z normal standard errors spans when the standard error itself is
// estimated from only dof + 1 values (Student's t). A sampler whose error comes from
// the spread of eight fold values (the directional sampler's cross-fitted max) has 7
// degrees of freedom: at z = 3 its interval must span 4.53 errors, not 3, to be as sure.
#pragma once

#include <cmath>

#include <luxplan/core/math.h>

namespace luxplan {

// P(|T| <= t) for Student's t with an integer number of degrees of freedom, by the
// finite sums of Abramowitz & Stegun 26.7.3-4 (exact; dof terms).
inline double studentTCentral(double t, int dof) {
    const double theta = std::atan(std::abs(t) / std::sqrt(double(dof)));
    const double s = std::sin(theta), c2 = std::cos(theta) * std::cos(theta);
    if (dof % 2 == 1) {
        double term = std::sqrt(c2), sum = dof > 1 ? term : 0;  // cos, then (2/3) cos^3, ...
        for (int k = 3; k <= dof - 2; k += 2) sum += (term *= c2 * double(k - 1) / double(k));
        return 2 / kPi * (theta + s * sum);
    }
    double term = 1, sum = 1;
    for (int k = 2; k <= dof - 2; k += 2) sum += (term *= c2 * double(k - 1) / double(k));
    return s * sum;
}

// The multiplier of an estimated standard error that gives the two-sided confidence of
// z normal standard errors: z itself when dof <= 0 (the error is known well: many
// samples), Student's quantile otherwise. Above z ~ 8 the level rounds to 1 and the
// multiplier stops growing with z.
inline double confidenceMultiplier(double z, int dof) {
    if (dof <= 0 || dof > 1000) return z;  // within 0.3% of z above 1000 (the sums cost dof terms)
    const double level = std::erf(z / std::sqrt(2.0));  // P(|Z| <= z)
    double lo = z, hi = z;
    for (int i = 0; i < 64 && studentTCentral(hi, dof) < level; ++i) hi *= 2;  // bounded where level rounds to 1
    for (int i = 0; i < 100 && hi - lo > 1e-9 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (studentTCentral(mid, dof) < level ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace luxplan
