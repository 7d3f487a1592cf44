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
    // A luminaire or a sun disk (surveyed one by one), or a connected region of
    // directions brighter than the DGP threshold (sky, sunlit surfaces).
    enum class Kind { Luminaire, Sun, Region };
    Kind kind = Kind::Luminaire;
    double luminance = 0;    // L, cd/m2, mean over its visible part
    double solidAngle = 0;   // omega, sr
    double positionIndex = 1;  // P
    Vec3 direction;          // unit, from the eye (the solid-angle centroid)
    int index = -1;          // its slot (the scene's emitters in order, then the sun disks), or its region's number
};

// What a glare sampler's value is made of, for reports.
// "luminaire", "sun" or "region", as measure and the reports name a source's kind.
inline const char* glareSourceKindName(GlareSource::Kind kind) {
    return kind == GlareSource::Kind::Luminaire ? "luminaire" : kind == GlareSource::Kind::Sun ? "sun" : "region";
}

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
    std::vector<double> points;    // per item: the type's points or strata, in its order (NaN: covered)
    std::vector<double> pointErrors;
    uint64_t droppedNonFinite = 0; // NaN/inf path samples left out (core/estimator.h)
    int pathsPerPoint = 0;         // traced per item, the most over its items (fewer than asked when adaptive)
    // Paths over all its items, and of them those traced afresh, not read from the path
    // cache: under common random numbers only these can differ from the last committed
    // layout's, so they bound the noise of a difference of two estimates.
    uint64_t paths = 0, freshPaths = 0;
    std::optional<GlareSurvey> glare = std::nullopt;  // what a ugr or dgp sampler's value is made of
    // Planar samplers: the points covered by furniture (inside another entity's solid),
    // left out of the value and the statistics; their `points` entries are NaN.
    std::vector<int> covered = {};
    // A sampler with an annual goal: the share of the year's hours whose value lies in
    // its target (daylight coefficients of the same layout), and how many hours.
    std::optional<double> annualInRange = std::nullopt;
    int annualHours = 0;
};

}  // namespace luxplan
