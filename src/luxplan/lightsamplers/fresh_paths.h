// Paths traced afresh for the tracer's current layout: each from the random numbers
// of (seed, sampler, item, path) and, with MeasureOptions::lowDiscrepancy, the item's
// scrambled sequence (one per fold for types that compare folds).
#pragma once

#include <cstddef>

#include <luxplan/lightsamplers/measure_plan.h>

namespace luxplan {

class FreshPaths {
public:
    FreshPaths(const WorkPlan& plan, const MeasureOptions& options) : plan_(plan), options_(options) {}
    // Traces path `path` of work item `work`, its rays counted in `stats` and, with
    // `recordFootprint`, kept in footprint(). The result and the footprint are the
    // calling thread's until its next trace.
    const PathContributions& trace(size_t work, int path, RayStats& stats, bool recordFootprint);
    // The footprint of the calling thread's last path traced with recordFootprint.
    static const PathFootprint& footprint();

private:
    const WorkPlan& plan_;
    const MeasureOptions& options_;
};

}  // namespace luxplan
