// The first part of a measurement (measureSamplers): what to trace. Every sampler
// placed for the tracer's layout, its items as work items (one per point or stratum,
// each traced with its own paths), the tracer and the light samples' roulette floor
// of each sampler, and the paths per point.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <luxplan/lightsamplers/light_samplers.h>

namespace luxplan {

// One unit of work: the paths of one item (point or stratum) of one sampler.
struct WorkItem {
    int sampler = 0;
    int item = 0;
};

struct WorkPlan {
    std::vector<std::unique_ptr<PlacedSampler>> placed;  // per sampler, in Scene::samplers order
    std::vector<WorkItem> work;                          // sampler by sampler, item by item
    std::vector<size_t> firstWork;                       // per sampler, and the end of the last
    std::vector<const PathTracer*> tracerOf;             // per sampler (glare surveys: the glare tracer)
    std::vector<double> lightFloorOf;                    // per sampler (0: every light sample traced)
    std::vector<char> sharesPaths;                       // per sampler: PlacedSampler::sharesPaths()
    int paths = 1;                                       // per point: exactly, or at most when adaptive

    size_t samplers() const { return placed.size(); }
    // The sampler of each work item (what a path source keys its paths by).
    std::vector<int> workSamplers() const;
};

// Throws std::logic_error when options.lightFloors is neither empty nor one per sampler.
WorkPlan planWork(const PathTracer& tracer, const MeasureOptions& options, const PathTracer* glareTracer);

}  // namespace luxplan
