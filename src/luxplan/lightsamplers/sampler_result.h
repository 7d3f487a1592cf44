// One light sampler's measurement: its value with the standard error, and the
// items (points or strata) it was made of. Its penalty is not stored: it follows
// from the value and the sampler's target (lightingPenalty, constraints/penalty.h).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

// A glare sampler's sources (ugr, dgp: lightsamplers/glare_sources.h).
struct GlareSource {
    double luminance = 0;    // L, cd/m2, mean over its visible part
    double solidAngle = 0;   // omega, sr
    double positionIndex = 1;  // P
    Vec3 direction;          // unit, from the eye (the solid-angle centroid)
    int index = -1;          // its slot: the scene's emitters in order, then the sun disks
};

// What a glare sampler's value is made of, for reports.
struct GlareSurvey {
    double verticalIlluminance = 0;  // E_v at the eye over the front hemisphere, lx
    double directIlluminance = 0;    // of it, the sources' direct light
    double backgroundLuminance = 0;  // (E_v - direct) / pi
    std::vector<GlareSource> sources;
    double value = 0;
};

struct SamplerResult {
    double value = 0;              // in the type's unit (lx, cd/m2)
    double standardError = 0;      // of `value`, from the per-item sample variances
    std::vector<double> points;    // per item: the type's points or strata, in its order
    std::vector<double> pointErrors;
    uint64_t droppedNonFinite = 0; // NaN/inf path samples left out (core/estimator.h)
    int pathsPerPoint = 0;         // traced per item, the most over its items (fewer than asked when adaptive)
    std::optional<GlareSurvey> glare = std::nullopt;  // what a ugr or dgp sampler's value is made of
};

}  // namespace luxplan
