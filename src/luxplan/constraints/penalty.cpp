// The lighting term of Eq. 3 from Eq. 2 penalties.
#include <luxplan/constraints/penalty.h>

#include <cmath>
#include <stdexcept>

#include <luxplan/core/error.h>
#include <string>

namespace luxplan {

double lightingPenalty(const LightSamplerSpec& sampler, double value) {
    // A NaN would otherwise score as on target (every comparison with it is false).
    if (!std::isfinite(value))
        throw SceneError({{sampler.file.empty() ? std::string("scene") : sampler.file, sampler.jsonPath,
                           "sampler \"" + sampler.name + "\" measured " + (std::isnan(value) ? "nan" : "an infinite value") +
                               ", not a finite number: it cannot be scored"}});
    return penalty(value, sampler.targetMin, sampler.targetMax, sampler.tolerance, kLightingStiffness);
}

double lightingCost(const Scene& scene, const std::vector<double>& values) {
    if (values.size() != scene.samplers.size())
        throw std::invalid_argument("lightingCost: " + std::to_string(values.size()) + " values for " +
                                    std::to_string(scene.samplers.size()) + " samplers");
    double sum = 0, weights = 0;
    for (size_t k = 0; k < values.size(); ++k) {
        sum += scene.samplers[k].weight * lightingPenalty(scene.samplers[k], values[k]);
        weights += scene.samplers[k].weight;
    }
    return weights > 0 ? sum / weights : 0.0;
}

namespace {

double totalWeight(const Scene& scene) {
    double weights = 0;
    for (const LightSamplerSpec& s : scene.samplers) weights += s.weight;
    return weights;
}

double termError(const LightSamplerSpec& s, const SamplerResult& r, double weights) {
    if (weights <= 0 || r.standardError <= 0) return 0.0;
    const double up = lightingPenalty(s, r.value + r.standardError);
    const double down = lightingPenalty(s, r.value - r.standardError);
    return s.weight / weights * std::abs(up - down) / 2;
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
