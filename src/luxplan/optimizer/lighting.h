// The optimizer's lighting hook: L(x) of the paper's Eq. 3 for a layout that
// passed the geometric test. The path-traced implementation lives with the light
// samplers; tests plug in analytic ones.
#pragma once

#include <vector>

#include <luxplan/scene/layout.h>

namespace luxplan {

// One light sampler's measurement for a layout.
struct SamplerMeasurement {
    int sampler = -1;            // index into Scene::samplers
    double value = 0;            // lx (planar) or cd/m2 (directional, volume)
    double penalty = 0;          // P(value, target min, target max, tolerance, 1) (lightingPenalty)
    std::vector<double> points;  // per point or per stratum, when the evaluator keeps them
};

struct LightingBreakdown {
    std::vector<SamplerMeasurement> samplers;
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
};

}  // namespace luxplan
