#include <luxplan/lightsamplers/light_samplers.h>

#include <array>
#include <stdexcept>

#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>

namespace luxplan {
namespace {

// One unit of work: the paths of one item (point or stratum) of one sampler.
struct WorkItem {
    int sampler = 0;
    int item = 0;
};

constexpr int kFolds = ItemEstimates::kFolds;

// What one work item's paths added: per fold an estimator for each item they reach
// (the own item only, or all of a sampler that shares paths).
struct WorkResult {
    std::array<std::vector<MeanEstimator>, kFolds> folds;
    uint64_t dropped = 0;
    RayStats stats;
};

}  // namespace

ItemEstimates::ItemEstimates(int items, int sources)
    : items_(items), sources_(sources), cells_(size_t(items) * sources * kFolds) {}

Estimate ItemEstimates::of(int item, unsigned folds) const {
    double sum = 0, varianceOfSum = 0;
    uint64_t n = 0;
    for (int source = 0; source < sources_; ++source) {
        MeanEstimator m;
        for (int g = 0; g < kFolds; ++g)
            if (folds & (1u << g)) m.merge(cells_[index(item, source, g)]);
        sum += m.mean() * double(m.count());
        varianceOfSum += m.variance() * double(m.count());
        n += m.count();
    }
    if (n == 0) return {};
    return {sum / double(n), std::sqrt(varianceOfSum) / double(n)};
}

uint64_t ItemEstimates::paths(int item, unsigned folds) const {
    uint64_t n = 0;
    for (int source = 0; source < sources_; ++source)
        for (int g = 0; g < kFolds; ++g)
            if (folds & (1u << g)) n += cells_[index(item, source, g)].count();
    return n;
}

Estimate PlacedSampler::combine(const ItemEstimates& items) const {
    Estimate e;
    if (items.items() == 0) return e;
    double sum = 0, var = 0;
    for (int i = 0; i < items.items(); ++i) {
        Estimate x = items.of(i);
        sum += x.value, var += x.standardError * x.standardError;
    }
    e.value = sum / items.items();
    e.standardError = std::sqrt(var) / items.items();
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
    std::vector<WorkItem> work;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        placed.push_back(placeSampler(scene.samplers[k], rt));
        for (int i = 0; i < placed.back()->items(); ++i) work.push_back({int(k), i});
    }
    std::vector<WorkResult> done(work.size());
    const int paths = std::max(1, options.pathsPerPoint);

    parallelFor(work.size(), [&](size_t index) {
        const WorkItem& w = work[index];
        const PlacedSampler& sampler = *placed[size_t(w.sampler)];
        const bool shares = sampler.sharesPaths();
        WorkResult& r = done[index];
        for (auto& f : r.folds) f.resize(shares ? size_t(sampler.items()) : 1);
        uint64_t finite[kFolds] = {};
        for (int path = 0; path < paths; ++path) {
            Rng rng(hashValues({options.seed, uint64_t(w.sampler), uint64_t(w.item), uint64_t(path)}));
            PathContributions c(w.item);
            sampler.sample(tracer, w.item, rng, r.stats, c);
            if (!c.finite()) {  // the path is dropped whole (core/estimator.h's policy)
                ++r.dropped;
                continue;
            }
            auto& fold = r.folds[size_t(path % kFolds)];
            ++finite[path % kFolds];
            for (int k = 0; k < c.size(); ++k) {
                if (!shares && c.itemAt(k) != w.item)
                    throw std::logic_error("a light sampler that does not share paths added to another item");
                fold[shares ? size_t(c.itemAt(k)) : 0].add(c.valueAt(k));
            }
        }
        // Paths that added nothing to an item count as zeros there.
        for (int g = 0; g < kFolds; ++g)
            for (MeanEstimator& e : r.folds[g]) e.addZeros(finite[g] - e.count());
    });

    // Reduce per sampler, in a fixed order.
    result.samplers.resize(scene.samplers.size());
    size_t next = 0;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const PlacedSampler& sampler = *placed[k];
        const size_t n = size_t(sampler.items());
        const bool shares = sampler.sharesPaths();
        ItemEstimates e(int(n), shares ? int(n) : 1);
        SamplerResult& r = result.samplers[k];
        for (size_t source = 0; source < n; ++source, ++next) {
            const WorkResult& w = done[next];
            for (int g = 0; g < kFolds; ++g) {
                if (shares)
                    for (size_t i = 0; i < n; ++i) e.cell(int(i), int(source), g) = w.folds[g][i];
                else
                    e.cell(int(source), 0, g) = w.folds[g][0];
            }
            r.droppedNonFinite += w.dropped;
            result.droppedNonFinite += w.dropped;
            result.rays += w.stats;
        }
        for (size_t i = 0; i < n; ++i) {
            Estimate x = e.of(int(i));
            r.points.push_back(x.value);
            r.pointErrors.push_back(x.standardError);
        }
        if (n == 0) continue;
        Estimate value = sampler.combine(e);
        r.value = value.value;
        r.standardError = value.standardError;
    }
    result.paths = uint64_t(work.size()) * paths;
    return result;
}

}  // namespace luxplan
