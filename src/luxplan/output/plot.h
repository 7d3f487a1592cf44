// The optimizer's convergence plot: the current cost (thin grey) and the best cost
// so far (thick blue) against the iteration, with labelled axes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <luxplan/optimizer/optimizer.h>
#include <luxplan/output/image.h>

namespace luxplan {

struct PlotOptions {
    int width = 800, height = 450;
    std::string title = "Convergence";
    // Log y when the finite positive costs span more than two decades, unless forced.
    std::optional<bool> logY;
};

// Infeasible points (TracePoint::feasible false) are left out of the current-cost line
// (it breaks there); the best line starts at the first finite best. Zero costs on a log
// axis are drawn at its bottom. An empty trace draws the axes and "no data".
Image plotConvergence(const std::vector<TracePoint>& trace, const PlotOptions& options = {});

}  // namespace luxplan
