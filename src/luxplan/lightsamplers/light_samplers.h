// Measuring the scene's light samplers with the path tracer. Each sampler type
// (sampler_type.h: planar, directional, volume) says where it measures and what one
// path contributes; this runs the paths in parallel and combines them (measurement.cpp:
// the work plan, the path source, the adaptive rounds and the reducer). Samplers on
// entities follow the layout.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include <luxplan/lightsamplers/path_source.h>
#include <luxplan/scene/sampler_result.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {

// A sampler placed for the current layout of the tracer's scene, told its luminaires
// and sun disks.
std::unique_ptr<PlacedSampler> placeSampler(const LightSamplerSpec& sampler, const PathTracer& tracer);

struct MeasureOptions {
    int pathsPerPoint = 1000;  // exactly, or at most when adaptive
    uint64_t seed = 1;
    // Adaptive: a sampler looks at its paths from time to time and stops once value +-
    // confidenceZ standard errors lies inside one linear piece of its penalty (below,
    // inside or above its target band), and so does each statistics goal's statistic:
    // more paths would then only refine penalties that are linear in the values. A
    // stopped sampler reads exactly as a fixed run of the paths it traced.
    // The first look comes after minPaths paths per point: an interval from fewer paths
    // is not to be trusted where rare paths carry much of the light (a sunlit patch seen
    // after a bounce or two: in the office's glare samplers 1% of the paths carry 30-50%
    // of the value, and 16 paths that missed them read 10x low with a small error;
    // docs/light-transport.md). A value whose error comes from a few fold values
    // (Estimate::degreesOfFreedom) is settled on Student's interval at the same level,
    // and below a bound only when the sampler's upper end is too (PlacedSampler::upperEnd:
    // for the directional type, every stratum's).
    // Each later look comes where the interval, narrowing as 1 / sqrt(paths), would
    // clear the band's nearest bound: at least batchPaths and at most about a quarter
    // more paths per point on. With pathsPerPoint <= minPaths there is no look: the run
    // is a fixed one.
    bool adaptive = false;
    int batchPaths = 16;
    int minPaths = 64;
    double confidenceZ = 3;
    // Low-discrepancy numbers for the first vertices of every path
    // (pathtracer/path_samples.h): the paths of one point are consecutive points of a
    // scrambled sequence (one per fold for types that compare folds,
    // PlacedSampler::independentFolds). Off: PCG only.
    bool lowDiscrepancy = true;
    // A value that chooses among its items (the directional sampler's brightest stratum)
    // reports an error that includes how the choice varies (PlacedSampler::reportedError:
    // a bootstrap of the estimate, about 0.25 ms a sampler of 16 strata). The search's own
    // measurements leave it out: their stops read every item's interval, not the
    // value's error, and it would make the search 1.17 times slower.
    bool choiceError = true;
    // A look at fewer than four items (a glare sampler's focused stratum) traces each
    // item's paths in chunks of this many, any thread taking any chunk, and adds them
    // up in path order: the same numbers as one thread in order (0: never split).
    int chunkPaths = 32;
    // Russian roulette on the light samples at surface vertices
    // (PathParams::lightFloor): sampler k's paths take lightFloors[k] (in the
    // tracer's unit for its paths; lightSampleFloors). Empty: every sample traced.
    std::vector<double> lightFloors;
    // Where a watcher reads the progress (measure's stderr line): the paths traced or
    // read back from the cache so far, added up as each point's round ends. Null: none.
    std::atomic<uint64_t>* pathsDone = nullptr;
};

// The light samples' roulette floors (MeasureOptions::lightFloors) for the tracer's
// current layout, one per sampler: `share` times the variance of one of its paths over
// their mean, from `pilotPaths` paths per item (PCG, keyed by `seed`; within-item
// variances and means, averaged over the items). A light sample worth c < F then adds
// at most c F to its path's variance, so all of them at most F times the mean, `share`
// times the variance per path where the pilot measured it. 0 for a sampler whose
// pilot saw no light and for the glare surveys (their paths measure their sources).
std::vector<double> lightSampleFloors(const PathTracer& tracer, double share, uint64_t seed, int pilotPaths = 64);

struct MeasureResult {
    std::vector<SamplerResult> samplers;  // in Scene::samplers order
    RayStats rays;
    uint64_t paths = 0;             // traced, over all samplers
    uint64_t droppedNonFinite = 0;  // over all samplers
    uint64_t reusedPaths = 0;       // read back from the path source instead of traced (in `paths`)
};

// Measures every sampler of the scene for the path tracer's current layout. Each path is
// seeded from (seed, sampler, point, path), so results do not depend on the thread count
// (set once by the caller, see core/parallel.h). With a path source (the path cache,
// incremental/path_cache.h), the paths it gives are read back instead of traced (the result is the
// same), and it is told of every path the measurement traced (path_source.h).
// `glareTracer`, when given (on the same scene), traces the glare surveys (the "ugr" and
// "dgp" samplers) instead of `tracer`: the search gives them the sunlit patches and the
// others not (a survey's vertical illuminance misses the light off sunlit surfaces in
// a third of its first looks, with an error that does not show it: docs/light-transport.md).
MeasureResult measureSamplers(const PathTracer& tracer, const MeasureOptions& options, PathSource* source = nullptr,
                              const PathTracer* glareTracer = nullptr);

}  // namespace luxplan
