// What a year of hourly light says per sampler: its mean, the share of hours in its
// target band, and for planar samplers the climate-based metrics designers report
// (IES LM-83-12's sDA300/50% and ASE1000,250; Mardaljevic & Nabil's UDI), with the
// JSON of `measure --annual --json` and its table. docs/daylight.md, "Annual results".
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <luxplan/annual/annual_series.h>

namespace luxplan {

// IES LM-83-12 (Approved Method: IES Spatial Daylight Autonomy (sDA) and Annual Sunlight
// Exposure (ASE), 2012), sections 2.1-2.2 (sDA) and 3 (ASE): sDA300/50% is the share of
// analysis points that "meet or exceed" 300 lx for "at least 50%" of the analysis hours;
// ASE1000,250 the share of points that "exceed" 1000 lx of direct sunlight for "more
// than 250 hours". Honeybee counts the same way (value >= 300, share >= 50%; value >
// 1000, hours > 250). No blinds are modelled: LM-83's sDA (2.2.6) closes them in hours
// when more than 2% of the points get more than 1000 lx of direct sun.
inline constexpr double kSdaIlluminance = 300;   // lx, inclusive (>=)
inline constexpr double kSdaTimeShare = 0.5;     // of the hours, inclusive (>=)
inline constexpr double kAseIlluminance = 1000;  // lx of direct sun, exclusive (>)
inline constexpr int kAseHours = 250;            // hours, exclusive (>): an absolute count, not a share

// Useful daylight illuminance (Nabil & Mardaljevic, Lighting Res. Technol. 37(1), 2005,
// 41-59; the 3000 lx upper bound of Mardaljevic, Heschong & Lee, LR&T 41(3), 2009): a
// point-hour is "fell short" below 100 lx, "useful" in [100, 3000] lx (both bounds
// inclusive) and "exceeded" above 3000 lx, as Honeybee's UDI (v < min, v > max, else useful).
inline constexpr double kUdiLow = 100;    // lx: below it (exclusive) falls short
inline constexpr double kUdiHigh = 3000;  // lx: above it (exclusive) is exceeded

struct AnnualMetrics {
    int hours = 0;           // hours measured
    double mean = 0;         // of the sampler's values over the hours (NaN without hours)
    double inRange = 0;      // share of hours whose value lies in [targetMin, targetMax] (NaN without hours)
    // Planar samplers only (NaN otherwise, and without hours or uncovered points).
    bool planar = false;
    int points = 0;          // uncovered points: the metrics' analysis points
    double sda = 0;          // share of those points with >= 300 lx for >= 50% of the hours
    double ase = 0;          // share of those points with > 1000 lx of direct sun for > 250 hours
                             // (NaN when the series has no direct-sun values)
    std::array<double, 3> udi{};  // shares of point-hours < 100 lx, in [100, 3000] lx, > 3000 lx
    // Per point (the sampler's order; NaN for a covered point): the share of its hours
    // in [targetMin, targetMax], what the annual plan shows.
    std::vector<double> pointsInRange;
};

// A non-finite value (which the series should not hold) counts as no hour in range,
// below no threshold and above none, and makes the mean NaN.
AnnualMetrics annualMetrics(const AnnualSampler& sampler, size_t hours);
inline AnnualMetrics annualMetrics(const AnnualSampler& sampler, const AnnualSeries& series) {
    return annualMetrics(sampler, series.hours.size());
}

// Adds the annual results to measure --json's object: top-level "hours" (ISO local
// times, DateTime::str()) and, in each sampler object whose "name" is a series
// sampler's, "annual": {"hours", "mean", "in_range", "values"}; a planar sampler's
// "annual" also holds "sda", "ase", "udi" and "points_in_range", and "sda", "ase" and
// "udi" are repeated at the sampler object's top level. Non-finite numbers are null.
// A series sampler with no object of its name in measureJson["samplers"] gets one
// ({"name", "type", "annual", ...}) so that nothing measured is dropped.
void addAnnualJson(nlohmann::json& measureJson, const AnnualSeries& series);

// The annual table for people: per sampler its hours, mean, share in range and, for
// planar samplers, sDA, ASE and the UDI shares, in percent.
std::string annualText(const AnnualSeries& series);

}  // namespace luxplan
