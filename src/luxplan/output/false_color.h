// A Radiance-falsecolor-like colour scale for illuminance and luminance maps (linear
// or logarithmic; its maximum a round number above a high percentile, or centred on a
// target band) and the legend that explains it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/output/image.h>

namespace luxplan {

enum class ColorScale { Linear, Log };

struct FalseColor {
    ColorScale scale = ColorScale::Linear;
    double maxValue = 1000;  // the top of the scale (values above saturate)
    double decades = 3;      // log scale: from maxValue / 10^decades to maxValue
    // The target band [lo, hi] the legend marks (targetFalseColor), if any.
    std::optional<std::array<double, 2>> band;

    double minValue() const;  // linear: 0
    // Position of v on the scale, clamped to [0, 1].
    double fraction(double v) const;
    Rgb color(double v) const;
};

// The palette: dark blue through blue, cyan, green, yellow and orange to red (the hue
// order of Radiance's falsecolor), t in [0, 1] clamped.
Rgb falseColorRamp(double t);

// The smallest of 1, 2, 2.5, 5 x 10^k that is >= x (x > 0; returns 1 for x <= 0).
double niceCeil(double x);

// A scale whose maximum is niceCeil of the `percentile` quantile of the finite values,
// capped at 5 x their median (so hot spots, e.g. sun patches, saturate instead of washing
// out the rest); 1 if all are <= 0.
FalseColor autoFalseColor(const std::vector<double>& values, ColorScale scale = ColorScale::Linear,
                          double percentile = 0.95);

// A logarithmic scale centred on the target band [targetMin, targetMax] (in log
// terms: the band's geometric mean is the middle colour), one decade beyond each end,
// so a room that meets a 300-500 lx target shows the ramp's middle hues, a dark
// corner blue and a sun patch red. An open band (targetMax at least 100 x targetMin,
// e.g. "at least 500") spans targetMin / 10 to 100 x targetMin; one with no lower end
// (targetMin <= 0) hi / 100 to 10 x hi. The band is marked in the legend.
FalseColor targetFalseColor(double targetMin, double targetMax);

// The legend's tick values: linear, `ticks` + 1 evenly spaced from 0; log, the 1-2-5
// values of each decade between minValue() and maxValue (both ends included).
std::vector<double> legendTicks(const FalseColor& scale, int ticks = 5);

// A vertical colour bar at (x, y) of size width x height (top = maxValue), with
// labelled ticks (legendTicks) on its right and `unit` above; a target band is
// bracketed on the left and labelled "target". Returns the width in pixels taken
// including the labels.
int drawLegend(Image& image, const FalseColor& scale, int x, int y, int width, int height,
               const std::string& unit = "lx", int ticks = 5);

}  // namespace luxplan
