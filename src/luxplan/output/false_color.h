// A Radiance-falsecolor-like colour scale for illuminance maps (linear or
// logarithmic, maximum chosen as a round number above a high percentile) and the
// legend that explains it.
#pragma once

#include <string>
#include <vector>

#include <luxplan/output/image.h>

namespace luxplan {

enum class ColorScale { Linear, Log };

struct FalseColor {
    ColorScale scale = ColorScale::Linear;
    double maxValue = 1000;  // the top of the scale (values above saturate)
    int decades = 3;         // log scale: from maxValue / 10^decades to maxValue

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

// A vertical colour bar at (x, y) of size width x height (top = maxValue), with
// `ticks` + 1 labelled ticks on its right (log scale: one per decade) and `unit` above.
// Returns the width in pixels taken including the labels.
int drawLegend(Image& image, const FalseColor& scale, int x, int y, int width, int height,
               const std::string& unit = "lx", int ticks = 5);

// A compact number label: "0", "12.5", "250", "2270", "25k" (no decimals from 100 up).
std::string formatValue(double v);

}  // namespace luxplan
