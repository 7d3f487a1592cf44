// How the constraints use the penalty P of the paper's Eq. 2 (core/penalty.h):
// geometric terms with stiffness 2, rejecting past P = 1; lighting terms (Eq. 3)
// with stiffness 1, never rejecting.
#pragma once

#include <vector>

#include <luxplan/core/penalty.h>  // penalty(c, bmin, bmax, brej, alpha): Eq. 2, infinite bounds open
#include <luxplan/lightsamplers/sampler_result.h>
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
// weights are 0. `values[k]` is the measurement of scene.samplers[k].
double lightingCost(const Scene& scene, const std::vector<double>& values);

// The standard error of sampler k's term of L: its weight share times the secant of
// its penalty over value +- standard error, halved (the delta method, with a secant
// instead of the slope so that a value near its band's edge counts the part of its
// error that crosses it; 0 well inside the band).
double lightingTermError(const Scene& scene, size_t k, const SamplerResult& result);
// The standard error of L: samplers are independent estimates, so their terms'
// errors add in quadrature. `results[k]` is the measurement of scene.samplers[k].
double lightingCostError(const Scene& scene, const std::vector<SamplerResult>& results);

}  // namespace luxplan
