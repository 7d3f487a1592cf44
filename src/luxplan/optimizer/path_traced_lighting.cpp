#include <luxplan/optimizer/path_traced_lighting.h>

#include <luxplan/constraints/penalty.h>

namespace luxplan {

PathTracedLighting::PathTracedLighting(const Scene& scene, const DaylightEnvironment* daylight, const MeasureOptions& options)
    : scene_(scene), rt_(scene, initialLayout(scene)), tracer_(rt_, daylight), options_(options), cache_(scene) {}

double PathTracedLighting::evaluate(const Layout& /*layout*/, const std::vector<Transform>& world, LightingBreakdown* out) {
    // Only instance transforms change: the top level is re-committed, nothing rebuilt.
    for (size_t i = 0; i < world.size(); ++i) rt_.setEntityTransform(int(i), world[i]);
    rt_.commit();
    tracer_.updateLayout();
    last_ = measureSamplers(tracer_, options_, incremental_ ? &cache_ : nullptr);
    ++evaluations_;
    rays_ += last_.rays;
    reusedPaths_ += last_.reusedPaths;
    tracedPaths_ += last_.paths - last_.reusedPaths;
    if (out) out->samplers = last_.samplers;
    return scene_.samplers.empty() ? 0.0 : lightingCostOfResults(scene_, last_.samplers);
}

double PathTracedLighting::confirm(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) {
    const MeasureOptions search = options_;
    if (confirmPaths_ > 0) options_.pathsPerPoint = confirmPaths_;
    options_.adaptive = false;
    double cost = evaluate(layout, world, out);
    options_ = search;
    return cost;
}

}  // namespace luxplan
