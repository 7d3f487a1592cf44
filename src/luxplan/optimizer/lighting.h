// The optimizer's lighting hook: L(x) of the paper's Eq. 3 for a layout that
// passed the geometric test. The path-traced implementation lives with the light
// samplers; tests plug in analytic ones.
#pragma once

#include <vector>

#include <luxplan/lightsamplers/sampler_result.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// Every light sampler's measurement for a layout, in Scene::samplers order (points
// and errors when the evaluator keeps them).
struct LightingBreakdown {
    std::vector<SamplerResult> samplers;
};

class LightingEvaluator {
public:
    virtual ~LightingEvaluator() = default;
    // L(x) in [0, inf) (Eq. 3; lightingCost() of constraints/penalty.h computes it
    // from the sampler values). `world` is worldTransforms(scene, layout). Fills
    // `out`, when given, with one measurement per sampler. Called only for layouts no
    // geometric term rejects, and only when the lighting weight is above 0 (and once
    // more for the final layout's report).
    virtual double evaluate(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) = 0;
    // L(x) measured more accurately, before the chain stops because its estimate of
    // C reached 0 (a noisy estimate reaches 0 sooner than the layout does). Defaults
    // to evaluate().
    virtual double confirm(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) {
        return evaluate(layout, world, out);
    }
    // The chain accepted (commit) or refused (revert) the layout last evaluated: an
    // evaluator that keeps work between layouts (the path cache) keeps it for the
    // accepted layout only. Evaluations measure against the last committed layout.
    virtual void commit() {}
    virtual void revert() {}
};

}  // namespace luxplan
