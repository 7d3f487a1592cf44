#include <luxplan/lightsamplers/light_samplers.h>

#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>

namespace luxplan {
namespace {

// One unit of work: one item (point or stratum) of one sampler.
struct WorkItem {
    int sampler = 0;
    int item = 0;
};

}  // namespace

Estimate PlacedSampler::combine(const std::vector<double>& means, const std::vector<double>& errors) const {
    Estimate e;
    if (means.empty()) return e;
    double sum = 0, var = 0;
    for (size_t i = 0; i < means.size(); ++i) sum += means[i], var += errors[i] * errors[i];
    e.value = sum / means.size();
    e.standardError = std::sqrt(var) / means.size();
    return e;
}

std::unique_ptr<PlacedSampler> placeSampler(const LightSamplerSpec& s, const EmbreeScene& rt) {
    return s.type->place(s.entity >= 0 ? rt.worldFromEntity(s.entity) : Transform());
}

MeasureResult measureSamplers(const PathTracer& tracer, const MeasureOptions& options) {
    const EmbreeScene& rt = tracer.rayTracer();
    const Scene& scene = rt.scene();
    MeasureResult result;
    std::vector<std::unique_ptr<PlacedSampler>> placed;
    std::vector<WorkItem> items;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        placed.push_back(placeSampler(scene.samplers[k], rt));
        for (int i = 0; i < placed.back()->items(); ++i) items.push_back({int(k), i});
    }
    std::vector<double> mean(items.size()), error(items.size());
    std::vector<uint64_t> dropped(items.size());
    std::vector<RayStats> stats(items.size());
    const int paths = std::max(1, options.pathsPerPoint);

    parallelFor(items.size(), [&](size_t index) {
        const WorkItem& w = items[index];
        const PlacedSampler& sampler = *placed[size_t(w.sampler)];
        MeanEstimator estimate;
        for (int path = 0; path < paths; ++path) {
            Rng rng(hashValues({options.seed, uint64_t(w.sampler), uint64_t(w.item), uint64_t(path)}));
            estimate.add(sampler.sample(tracer, w.item, rng, stats[index]));
        }
        mean[index] = estimate.mean();
        error[index] = estimate.standardError();
        dropped[index] = estimate.dropped();
    });

    // Reduce per sampler, in a fixed order.
    result.samplers.resize(scene.samplers.size());
    for (size_t i = 0; i < items.size(); ++i) {
        SamplerResult& r = result.samplers[size_t(items[i].sampler)];
        r.points.push_back(mean[i]);
        r.pointErrors.push_back(error[i]);
        r.droppedNonFinite += dropped[i];
        result.droppedNonFinite += dropped[i];
        result.rays += stats[i];
    }
    result.paths = uint64_t(items.size()) * paths;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        SamplerResult& r = result.samplers[k];
        if (r.points.empty()) continue;
        Estimate e = placed[k]->combine(r.points, r.pointErrors);
        r.value = e.value;
        r.standardError = e.standardError;
    }
    return result;
}

}  // namespace luxplan
