// How the constraints use the penalty P of the paper's Eq. 2 (core/penalty.h):
// geometric terms with stiffness 2, rejecting past P = 1; lighting terms (Eq. 3)
// with stiffness 1, never rejecting.
#pragma once

#include <string>
#include <vector>

#include <luxplan/core/penalty.h>  // penalty(c, bmin, bmax, brej, alpha): Eq. 2, infinite bounds open
#include <luxplan/scene/sampler_result.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// Stiffness factors alpha: quadratic for geometric rules (Eqs. 4-8), linear for
// light samplers (Eq. 3).
inline constexpr double kGeometricStiffness = 2.0;
inline constexpr double kLightingStiffness = 1.0;

// A geometric term rejects its layout when its penalty exceeds 1 (Section 3).
inline bool rejects(double geometricPenalty) { return geometricPenalty > 1.0; }

// Eq. 3 for one sampler: P(value, target min, target max, tolerance, 1). Never rejects.
// A non-finite value throws SceneError naming the sampler (FILE: /json/path).
double lightingPenalty(const LightSamplerSpec& sampler, double value);

// Eq. 3: L = sum_k w_k P_k / sum_k w_k, i.e. the paper's (1/N_S) sum_k w_k P_k with
// the weights normalized to a mean of 1; 0 when there are no samplers or all
// weights are 0. `values[k]` is the measurement of scene.samplers[k]. A scene with
// statistics goals needs the points: it throws std::invalid_argument (use
// lightingCostOfResults).
double lightingCost(const Scene& scene, const std::vector<double>& values);

// One term of Eq. 3: a sampler's value against its target (statistic Mean: the
// value whatever the type, e.g. a directional sampler's brightest stratum), or one of
// its statistics goals, with the statistic measured over its points.
struct LightingTerm {
    Statistic statistic = Statistic::Mean;
    double value = 0, standardError = 0;
    double targetMin = 0, targetMax = kInf, tolerance = 1;
    double weight = 1;  // the sampler's
    double penalty = 0;  // P(value, targetMin, targetMax, tolerance, 1)
};

// A sampler's terms: its value's first, then one per statistics goal in the order of
// LightSamplerSpec::statistics, then its annual goal's (the share of hours in range,
// SamplerResult::annualInRange, error 0: the coefficients' noise is not estimated). A non-finite value throws SceneError naming the
// sampler (its goal's path for a statistic); goals without points to measure them
// over throw std::invalid_argument.
std::vector<LightingTerm> lightingTerms(const LightSamplerSpec& sampler, const SamplerResult& result);

// Whether every term is on target (penalty 0): the sampler meets its goals.
bool allMet(const std::vector<LightingTerm>& terms);

// Eq. 3 over every term of every sampler: L = sum_t w_t P_t / sum_t w_t, each
// statistics goal a term of its own with its sampler's weight, in the denominator
// too, so that L stays a weighted mean of penalties. Without statistics goals, the
// same number as lightingCost(scene, values). (Another name, not an overload: a
// braced list such as {} or {500} would fit both.)
// With `marginZ` > 0 (the search's margin, OptimizerOptions::marginZ), each term's
// band is first narrowed by marginZ of its standard errors at each finite end
// (marginPenalty): an estimate at 0 then lies that far inside every band, so that an
// independent measurement finds it inside too.
double lightingCostOfResults(const Scene& scene, const std::vector<SamplerResult>& results, double marginZ = 0);
// A term's penalty against its band narrowed by marginZ standard errors at each finite
// end (to its middle when narrower than that); the plain penalty when marginZ or the
// error is 0.
double marginPenalty(const LightingTerm& t, double marginZ);

// The standard error of sampler k's share of L: each of its terms (lightingTerms)
// contributes its weight share of L's denominator times the secant of its penalty
// over value +- standard error, halved (the delta method, with a secant instead of
// the slope so that a value near its band's edge counts the part of its error that
// crosses it; 0 well inside the band), and the terms add in quadrature (its goals'
// statistics come from the same points as its value: an approximation).
double lightingTermError(const Scene& scene, size_t k, const SamplerResult& result);
// The standard error of L: samplers are independent estimates, so their shares'
// errors add in quadrature. `results[k]` is the measurement of scene.samplers[k].
double lightingCostError(const Scene& scene, const std::vector<SamplerResult>& results);

}  // namespace luxplan
