// Eq. 2 of the paper and its use for the lighting term (Eq. 3).
#include <luxplan/constraints/penalty.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace luxplan {

double penalty(double c, double bmin, double bmax, double brej, double alpha) {
    if (!(brej > 0)) throw std::invalid_argument("penalty: elastic limit b_rej must be > 0, got " + std::to_string(brej));
    double k = std::pow(brej, -alpha);
    if (c <= bmin) return k * std::pow(bmin - c, alpha);
    if (c >= bmax) return k * std::pow(c - bmax, alpha);
    return 0.0;
}

double lightingPenalty(const LightSamplerSpec& sampler, double value) {
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

}  // namespace luxplan
