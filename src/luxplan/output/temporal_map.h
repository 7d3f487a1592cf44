// The temporal map of a sampler's annual values, as Ladybug's hourly plot draws it:
// day of the year across, hour of the day up, each measured hour a false-colour cell,
// hours not measured grey, with month ticks and a colour legend.
#pragma once

#include <optional>
#include <string>

#include <luxplan/annual/annual_series.h>
#include <luxplan/output/false_color.h>
#include <luxplan/output/image.h>

namespace luxplan {

inline constexpr Rgb kUnmeasuredColor{205, 205, 205};  // hours not in the series

struct TemporalMapOptions {
    int dayWidth = 2;      // pixels per day
    int hourHeight = 8;    // pixels per hour
    std::string title;     // default: the sampler's name and its number of hours
    std::string unit;      // above the legend (e.g. "lx")
    std::optional<FalseColor> colors;  // default: temporalMapColors(sampler)
};

// Where the cells are: the plot's top-left pixel and size, for tests and overlays.
struct TemporalMapFrame {
    int left = 0, top = 0, dayWidth = 2, hourHeight = 8;
    int days = 365;  // 366 when a hour of the series falls in a leap year
    // The centre pixel of day-of-year `day` (1-based) and hour-of-day `hour` (0..23).
    int cellX(int day) const { return left + (day - 1) * dayWidth + dayWidth / 2; }
    int cellY(int hour) const { return top + (23 - hour) * hourHeight + hourHeight / 2; }
};

// Day of the year, 1-based (1 January = 1; 31 December = 365, or 366 in a leap year).
int dayOfYear(const DateTime& t);

// The scale: targetFalseColor of the sampler's band when it has one (a lower end above
// 0 or a finite upper end), else a logarithmic autoFalseColor of its values.
FalseColor temporalMapColors(const AnnualSampler& sampler);

// The map of `sampler`'s values over `hours` (AnnualSeries::hours; values[i] is at
// hours[i]). An hour is drawn in the row of its hour of the day (the hour reported
// at 12:30 fills the 12-13 row), hour 0 at the bottom; a non-finite value is drawn as
// not measured.
Image renderTemporalMap(const AnnualSampler& sampler, const std::vector<DateTime>& hours,
                        const TemporalMapOptions& options = {}, TemporalMapFrame* frame = nullptr);

}  // namespace luxplan
