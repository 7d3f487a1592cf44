// Isolines (isolux contours) of a field sampled on a regular grid, by marching squares.
#pragma once

#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

struct ContourSegment {
    Vec2 a, b;  // in grid coordinates: sample (i, j) is at (i, j)
};

// The segments where the field crosses `level`, linearly interpolated along the edges
// of each square of four neighbouring samples; `values` row-major, x fastest (nx x ny).
// A square with a sample where `valid` is 0 (e.g. inside furniture) gives no segment;
// empty `valid`: all valid. A saddle square (opposite corners on the same side) is
// resolved by the mean of its four samples, as is usual for marching squares.
std::vector<ContourSegment> isolines(const std::vector<double>& values, int nx, int ny, double level,
                                     const std::vector<char>& valid = {});

}  // namespace luxplan
