// Whether a sampler's target can be met: the range of values it took over every layout
// the search measured, and a verdict on the result's miss in words a designer reads
// ("at most 180 lx over the 2400 layouts measured, below the target's 300 lx").
#pragma once

#include <cstdint>
#include <string>

#include <luxplan/core/math.h>
#include <luxplan/scene/sampler_result.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// The lowest and highest estimates of one sampler over the layouts measured, each with
// its standard error, and how many of them were inside the target.
struct SamplerRange {
    double lowest = kInf, highest = -kInf;
    double lowestError = 0, highestError = 0;
    int64_t layouts = 0, met = 0;
    void add(const LightSamplerSpec& sampler, double value, double standardError);
};

enum class Reach {
    Met,         // the result meets the target and every statistics goal
    WithinNoise, // the result is outside the band (or a statistics goal's) by less than its standard error
    GoalMissed,  // the result's value meets its target, a statistics goal (u0, min, max) does not
    Reached,     // the result misses it, but some measured layout met it (a trade-off)
    NeverMet,    // no measured layout met it, though some came within two standard errors
    OutOfReach,  // every measured layout missed it by more than two standard errors, on one side
    NotMeasured, // the search measured no layout (lighting weight 0, nothing feasible)
};
const char* reachName(Reach reach);

struct ReachVerdict {
    Reach reach = Reach::NotMeasured;
    std::string reason;  // empty when met
};

// `value`: the result's measurement of the sampler, `standardError` its error. The
// range and this verdict are about the value (the mean of a planar sampler) against
// its target: a value past a bound by no more than its standard error is at the bound
// within noise (WithinNoise), not missed.
ReachVerdict reachVerdict(const LightSamplerSpec& sampler, const SamplerRange& range, double value,
                          double standardError = 0);
// The same, then, when the value meets its target, the sampler's statistics goals
// (lightingTerms, constraints/penalty.h) on the result's points.
ReachVerdict reachVerdict(const LightSamplerSpec& sampler, const SamplerRange& range, const SamplerResult& result);

}  // namespace luxplan
