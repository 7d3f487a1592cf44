// A year (or the scene's period) of hourly light at each sampler: what `measure
// --annual` computes with daylight coefficients (annual/daylight_coefficients.h) and
// what the annual metrics (annual/annual_metrics.h), goals and pictures read.
// docs/daylight.md, "Annual results".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <luxplan/daylight/datetime.h>

namespace luxplan {

// One sampler's hours. Values are in the sampler's unit (lx for planar samplers).
struct AnnualSampler {
    std::string name;               // as measure --json names it (dotted for entity samplers)
    std::string type;               // the scene file's type ("planar", ...)
    double targetMin = 0, targetMax = 0;  // the sampler's target band (in_range counts hours inside it)
    std::vector<double> values;     // the sampler's value per hour (hours of AnnualSeries)
    // Planar samplers: per point (row-major as the sampler's points; a point covered by
    // furniture has an empty row) the value per hour, and the direct sun's share alone
    // (the sun straight at the point, no interreflection: ASE's quantity).
    bool planar = false;
    std::vector<std::vector<double>> points;     // [point][hour]
    std::vector<std::vector<double>> directSun;  // [point][hour]
};

struct AnnualSeries {
    std::vector<DateTime> hours;  // local times of the hours measured, in order
    std::vector<AnnualSampler> samplers;
};

}  // namespace luxplan
