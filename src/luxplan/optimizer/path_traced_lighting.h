// The optimizer's lighting term measured by the path tracer: L(x) of Eq. 3 from every
// light sampler, for the layout the chain proposes.
#pragma once

#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/optimizer/lighting.h>

namespace luxplan {

class PathTracedLighting : public LightingEvaluator {
public:
    // `daylight` may be null (night). Every evaluation uses the same seed: common random
    // numbers, so that the difference between two layouts' costs carries less noise
    // than either cost (the paths differ only where the geometry does).
    PathTracedLighting(const Scene& scene, const DaylightEnvironment* daylight, const MeasureOptions& options);

    double evaluate(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) override;
    // evaluate() with `confirmPathsPerPoint` paths per point (set by setConfirmPaths;
    // by default the same as the search's).
    double confirm(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) override;
    void setConfirmPaths(int pathsPerPoint) { confirmPaths_ = pathsPerPoint; }

    // The full measurement of the last evaluated layout (per-point values, errors).
    const MeasureResult& lastMeasurement() const { return last_; }
    uint64_t evaluations() const { return evaluations_; }
    RayStats rays() const { return rays_; }
    void setOptions(const MeasureOptions& options) { options_ = options; }

private:
    const Scene& scene_;
    EmbreeScene rt_;
    PathTracer tracer_;
    MeasureOptions options_;
    int confirmPaths_ = 0;  // 0: options_.pathsPerPoint
    MeasureResult last_;
    uint64_t evaluations_ = 0;
    RayStats rays_;
};

}  // namespace luxplan
