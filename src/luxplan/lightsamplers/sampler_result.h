// One light sampler's measurement: its value with the standard error, and the
// items (points or strata) it was made of. Its penalty is not stored: it follows
// from the value and the sampler's target (lightingPenalty, constraints/penalty.h).
#pragma once

#include <cstdint>
#include <vector>

namespace luxplan {

struct SamplerResult {
    double value = 0;              // in the type's unit (lx, cd/m2)
    double standardError = 0;      // of `value`, from the per-item sample variances
    std::vector<double> points;    // per item: the type's points or strata, in its order
    std::vector<double> pointErrors;
    uint64_t droppedNonFinite = 0; // NaN/inf path samples left out (core/estimator.h)
    int pathsPerPoint = 0;         // traced per item, the most over its items (fewer than asked when adaptive)
};

}  // namespace luxplan
