// The lighting term of Eq. 3 from Eq. 2 penalties.
#include <luxplan/constraints/penalty.h>

#include <cmath>
#include <stdexcept>

#include <luxplan/core/error.h>
#include <string>

namespace luxplan {
namespace {

// A NaN would otherwise score as on target (every comparison with it is false).
void requireFinite(const LightSamplerSpec& sampler, const std::string& jsonPath, const std::string& what, double value) {
    if (!std::isfinite(value))
        throw SceneError({{sampler.file.empty() ? std::string("scene") : sampler.file, jsonPath,
                           "sampler \"" + sampler.name + "\" measured " + what + (std::isnan(value) ? "nan" : "an infinite value") +
                               ", not a finite number: it cannot be scored"}});
}

void requireSize(const Scene& scene, size_t count) {
    if (count != scene.samplers.size())
        throw std::invalid_argument("lightingCost: " + std::to_string(count) + " values for " +
                                    std::to_string(scene.samplers.size()) + " samplers");
}

}  // namespace

double lightingPenalty(const LightSamplerSpec& sampler, double value) {
    requireFinite(sampler, sampler.jsonPath, "", value);
    return penalty(value, sampler.targetMin, sampler.targetMax, sampler.tolerance, kLightingStiffness);
}

double lightingCost(const Scene& scene, const std::vector<double>& values) {
    requireSize(scene, values.size());
    double sum = 0, weights = 0;
    for (size_t k = 0; k < values.size(); ++k) {
        if (!scene.samplers[k].statistics.empty() || scene.samplers[k].annual)
            throw std::invalid_argument("lightingCost: sampler \"" + scene.samplers[k].name +
                                        "\" has statistics or annual goals, which need its points or its year, not only its value");
        sum += scene.samplers[k].weight * lightingPenalty(scene.samplers[k], values[k]);
        weights += scene.samplers[k].weight;
    }
    return weights > 0 ? sum / weights : 0.0;
}

std::vector<LightingTerm> lightingTerms(const LightSamplerSpec& sampler, const SamplerResult& result) {
    std::vector<LightingTerm> terms;
    terms.push_back({Statistic::Mean, result.value, result.standardError, sampler.targetMin, sampler.targetMax,
                     sampler.tolerance, sampler.weight, lightingPenalty(sampler, result.value)});
    if (!sampler.statistics.empty()) {
        if (result.points.empty())
            throw std::invalid_argument("lightingTerms: sampler \"" + sampler.name +
                                        "\" has statistics goals, but its measurement holds no points");
        const PointStatistics stats = pointStatistics(result.points, result.pointErrors);
        for (const StatisticGoal& goal : sampler.statistics) {
            const StatisticEstimate& e = stats.of(goal.statistic);
            requireFinite(sampler, goal.jsonPath, std::string("its ") + statisticNames().name(goal.statistic) + " as ", e.value);
            terms.push_back({goal.statistic, e.value, e.standardError, goal.targetMin, goal.targetMax, goal.tolerance,
                             sampler.weight, penalty(e.value, goal.targetMin, goal.targetMax, goal.tolerance, kLightingStiffness)});
        }
    }
    if (sampler.annual) {
        if (!result.annualInRange)
            throw std::invalid_argument("lightingTerms: sampler \"" + sampler.name +
                                        "\" has an annual goal, but its measurement holds no year");
        const AnnualGoal& g = *sampler.annual;
        requireFinite(sampler, g.jsonPath, "its share of hours in range as ", *result.annualInRange);
        terms.push_back({Statistic::AnnualInRange, *result.annualInRange, 0.0, g.targetMin, g.targetMax, g.tolerance,
                         sampler.weight, penalty(*result.annualInRange, g.targetMin, g.targetMax, g.tolerance, kLightingStiffness)});
    }
    return terms;
}

bool allMet(const std::vector<LightingTerm>& terms) {
    for (const LightingTerm& t : terms)
        if (t.penalty > 0) return false;
    return true;
}

double marginPenalty(const LightingTerm& t, double marginZ) {
    if (!(marginZ > 0) || !(t.standardError > 0)) return t.penalty;
    // Each finite end moved inwards by z standard errors; a band narrower than that
    // shrinks to its middle.
    double lo = t.targetMin, hi = t.targetMax;
    const double shift = marginZ * t.standardError;
    if (std::isfinite(lo)) lo += shift;
    if (std::isfinite(hi)) hi -= shift;
    if (lo > hi) lo = hi = std::isfinite(t.targetMin) && std::isfinite(t.targetMax) ? (t.targetMin + t.targetMax) / 2
                                                                                   : std::isfinite(lo) ? lo : hi;
    return penalty(t.value, lo, hi, t.tolerance, kLightingStiffness);
}

double lightingCostOfResults(const Scene& scene, const std::vector<SamplerResult>& results, double marginZ) {
    requireSize(scene, results.size());
    double sum = 0, weights = 0;
    for (size_t k = 0; k < results.size(); ++k)
        for (const LightingTerm& t : lightingTerms(scene.samplers[k], results[k])) {
            sum += t.weight * marginPenalty(t, marginZ);
            weights += t.weight;
        }
    return weights > 0 ? sum / weights : 0.0;
}

namespace {

// L's denominator: every term's weight, a sampler's once per term (1 + its goals).
double totalWeight(const Scene& scene) {
    double weights = 0;
    for (const LightSamplerSpec& s : scene.samplers) weights += s.weight * double(1 + s.statistics.size() + (s.annual ? 1 : 0));
    return weights;
}

double secantError(const LightingTerm& t, double weights) {
    if (t.standardError <= 0) return 0.0;
    const double up = penalty(t.value + t.standardError, t.targetMin, t.targetMax, t.tolerance, kLightingStiffness);
    const double down = penalty(t.value - t.standardError, t.targetMin, t.targetMax, t.tolerance, kLightingStiffness);
    return t.weight / weights * std::abs(up - down) / 2;
}

// One sampler's share of L's error: its terms' secants, in quadrature.
double termError(const LightSamplerSpec& s, const SamplerResult& r, double weights) {
    if (weights <= 0) return 0.0;
    const std::vector<LightingTerm> terms = lightingTerms(s, r);
    if (terms.size() == 1) return secantError(terms[0], weights);
    double variance = 0;
    for (const LightingTerm& t : terms) variance += secantError(t, weights) * secantError(t, weights);
    return std::sqrt(variance);
}

}  // namespace

double lightingTermError(const Scene& scene, size_t k, const SamplerResult& result) {
    return termError(scene.samplers.at(k), result, totalWeight(scene));
}

double lightingCostError(const Scene& scene, const std::vector<SamplerResult>& results) {
    if (results.size() != scene.samplers.size())
        throw std::invalid_argument("lightingCostError: " + std::to_string(results.size()) + " results for " +
                                    std::to_string(scene.samplers.size()) + " samplers");
    const double weights = totalWeight(scene);
    double variance = 0;
    for (size_t k = 0; k < results.size(); ++k) {
        const double e = termError(scene.samplers[k], results[k], weights);
        variance += e * e;
    }
    return std::sqrt(variance);
}

}  // namespace luxplan
