// The optimizer's lighting hook: L(x) of the paper's Eq. 3 for a layout that
// passed the geometric test. The optimizer sees an evaluator of the light, not how it
// measures: the path-traced one (path_traced_lighting.h) keeps its path cache to itself;
// tests plug in analytic ones.
#pragma once

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include <luxplan/scene/sampler_result.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// Every light sampler's measurement for a layout, in Scene::samplers order (points
// and errors when the evaluator keeps them).
struct LightingBreakdown {
    std::vector<SamplerResult> samplers;
};

// What an evaluator says of its own in report.json (its settings and checks), as
// fields in the order written: each sampler's after its measurement, and the run's
// after the search's statistics.
struct LightingNotes {
    std::vector<nlohmann::ordered_json> samplers;  // per sampler (Scene::samplers order), an object each; empty: none
    nlohmann::ordered_json run = nlohmann::ordered_json::object();
};

// What an independent measurement (LightingEvaluator::measureIndependently) is for: it
// sets the measurement's paths (optimizer.selection_paths_per_point, report_paths_per_point).
enum class IndependentUse {
    Selection,  // a zero cost's confirmation, a candidate's re-measure: dozens in a run
    Report,     // the result's reported value (and each suggestion's): `measure` repeats it
};

class LightingEvaluator {
public:
    virtual ~LightingEvaluator() = default;
    // L(x) in [0, inf) (Eq. 3; lightingCostOfResults() of constraints/penalty.h
    // computes it from the measurements, goals included). `world` is worldTransforms(scene, layout). Fills
    // `out`, when given, with one measurement per sampler. Called only for layouts no
    // geometric term rejects, and only when the lighting weight is above 0 (and once
    // more for the final layout's report).
    virtual double evaluate(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) = 0;
    // L(x) measured again from `seed` instead of the search's, at the accuracy `use`
    // asks (the selection's or the report's): the optimizer draws these seeds apart from
    // the search's (one confirms a zero cost and selects among the best candidates,
    // another measures the one selected for the report), so that neither the search's
    // nor the selection's luck reaches the reported value. Commits nothing: the next
    // evaluate() measures against the last committed layout as before. Defaults to
    // evaluate() (an exact evaluator has nothing to draw again).
    virtual double measureIndependently(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out,
                                        uint64_t seed, IndependentUse use) {
        (void)seed, (void)use;
        return evaluate(layout, world, out);
    }
    // Whether two evaluations of one layout draw independent noise. The path tracer's
    // do not (every evaluation uses the same seed: common random numbers, so its
    // estimates are a fixed function of the layout). If they do, the chain measures
    // its current layout again before each test, as the penalty method needs.
    virtual bool drawsAnew() const { return false; }
    // Paths traced so far over every evaluation and measurement (not those a cache
    // reused); 0 for an evaluator that traces none.
    virtual uint64_t tracedPaths() const { return 0; }
    // Its own fields of report.json, for the run so far (LightingNotes).
    virtual LightingNotes notes() const { return {}; }
    // The search's margin (OptimizerOptions::marginZ): evaluate() narrows every band by
    // this many standard errors of the term at each end (constraints/penalty.h,
    // marginPenalty); measureIndependently() never does. An evaluator without errors
    // ignores it.
    virtual void setSearchMargin(double z) { (void)z; }
    // Horizontal illuminance (lx, facing up) at `points` in the room without its movable
    // furniture (and the luminaires it carries), `paths` paths each from `seed`: the light
    // surrogate's fields (light_surrogate.h). Commits nothing. Empty: this evaluator
    // cannot tell, and the chain starts where it was drawn.
    virtual std::vector<double> emptyRoomIlluminance(const std::vector<Vec3>& points, int paths, uint64_t seed) {
        (void)points, (void)paths, (void)seed;
        return {};
    }
    // The values of `samplers` (Scene::samplers indices, carried by `entity` or its
    // members) with `entity` at each of `placements`, in the room without its other
    // movable furniture, `paths` paths per point from `seed` (the same at every
    // placement): the light surrogate's pose tables. Per placement, one value per
    // sampler. Commits nothing. Empty: this evaluator cannot tell.
    virtual std::vector<std::vector<double>> aloneInEmptyRoom(int entity, const std::vector<Placement>& placements,
                                                              const std::vector<int>& samplers, int paths, uint64_t seed) {
        (void)entity, (void)placements, (void)samplers, (void)paths, (void)seed;
        return {};
    }
    // The chain accepted (commit) or refused (revert) the layout last evaluated: an
    // evaluator that keeps work between layouts (the path cache) keeps it for the
    // accepted layout only. Evaluations measure against the last committed layout.
    virtual void commit() {}
    virtual void revert() {}
};

}  // namespace luxplan
