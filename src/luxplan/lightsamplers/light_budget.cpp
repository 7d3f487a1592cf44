// Light budgets: each sampler's paths traced with a LightBudget in their RayStats,
// in parallel over (sampler, item), then normalized to shares.
#include <luxplan/lightsamplers/light_budget.h>

#include <algorithm>
#include <cstdio>

#include <luxplan/core/parallel.h>
#include <luxplan/lightsamplers/light_samplers.h>

namespace luxplan {
namespace {

constexpr uint64_t kBudgetTag = 0x627564676574ULL;  // "budget"

}  // namespace

std::vector<SamplerBudget> measureLightBudgets(const PathTracer& tracer, int pathsPerItem, uint64_t seed) {
    const EmbreeScene& rt = tracer.rayTracer();
    const Scene& scene = rt.scene();
    pathsPerItem = std::max(1, pathsPerItem);
    std::vector<std::unique_ptr<PlacedSampler>> placed;
    struct Work {
        size_t sampler;
        int item;
    };
    std::vector<Work> work;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        placed.push_back(placeSampler(scene.samplers[k], tracer));
        for (int i = 0; i < placed.back()->items(); ++i) work.push_back({k, i});
    }
    std::vector<LightBudget> sums(work.size());
    parallelFor(work.size(), [&](size_t w) {
        const Work& job = work[w];
        RayStats stats;
        LightBudget path;
        PathParams params;
        params.budget = &path;
        for (int p = 0; p < pathsPerItem; ++p) {
            path = LightBudget();
            Rng rng(hashValues({seed, kBudgetTag, uint64_t(job.sampler), uint64_t(job.item), uint64_t(p)}));
            PathSamples samples(rng);
            PathContributions out(job.item);
            placed[job.sampler]->sample(tracer, job.item, samples, stats, params, out);
            if (!out.finite() || !std::isfinite(path.total())) continue;  // dropped, as the estimator drops it
            LightBudget& sum = sums[w];
            sum.sun += path.sun, sum.sky += path.sky, sum.interreflected += path.interreflected;
            if (sum.emitters.size() < path.emitters.size()) sum.emitters.resize(path.emitters.size(), 0.0);
            for (size_t e = 0; e < path.emitters.size(); ++e) sum.emitters[e] += path.emitters[e];
        }
    });

    std::vector<SamplerBudget> out(scene.samplers.size());
    LightBudget total;
    for (size_t k = 0, w = 0; k < scene.samplers.size(); ++k) {
        total = LightBudget();
        total.emitters.assign(scene.emitters.size(), 0.0);
        for (; w < work.size() && work[w].sampler == k; ++w) {
            total.sun += sums[w].sun, total.sky += sums[w].sky, total.interreflected += sums[w].interreflected;
            for (size_t e = 0; e < sums[w].emitters.size() && e < total.emitters.size(); ++e) total.emitters[e] += sums[w].emitters[e];
            out[k].paths += uint64_t(pathsPerItem);
        }
        SamplerBudget& b = out[k];
        b.emitters.assign(scene.emitters.size(), 0.0);
        const double sum = total.total();
        if (!(sum > 0)) continue;
        b.sun = total.sun / sum, b.sky = total.sky / sum, b.interreflected = total.interreflected / sum;
        for (size_t e = 0; e < total.emitters.size(); ++e) b.emitters[e] = total.emitters[e] / sum;
    }
    return out;
}

std::string describeBudget(const Scene& scene, const SamplerBudget& budget) {
    std::vector<std::pair<double, std::string>> parts{
        {budget.sun, "sun"}, {budget.sky, "sky"}, {budget.interreflected, "interreflection"}};
    for (size_t e = 0; e < budget.emitters.size() && e < scene.emitters.size(); ++e)
        parts.push_back({budget.emitters[e], scene.emitters[e].name});
    std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string text;
    for (const auto& [share, name] : parts) {
        if (share < 0.005) continue;
        char pct[16];
        std::snprintf(pct, sizeof pct, " %.0f%%", 100 * share);
        if (!text.empty()) text += ", ";
        text += name;
        text += pct;
    }
    return text.empty() ? "no light" : text;
}

}  // namespace luxplan
