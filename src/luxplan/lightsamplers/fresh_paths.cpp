#include <luxplan/lightsamplers/fresh_paths.h>

#include <vector>

#include <luxplan/core/rng.h>

namespace luxplan {
namespace {

constexpr uint64_t kSequenceTag = 0x5350'0bb1'5eedULL;  // keys the low-discrepancy sequences

// Each thread's buffers keep their memory from one path to the next: a measurement
// traces millions of paths, and their allocations showed in the search's profile.
struct Scratch {
    PathContributions traced{0};
    PathFootprint footprint;
    // The sequences of the item traced last (made at its first path traced afresh:
    // about half a search's work items read every path back from the cache).
    std::vector<PathSamples::Sequence> sequences;
    uint64_t seed = 0;
    int sampler = -1, item = -1;
    bool folds = false;
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

}  // namespace

const PathFootprint& FreshPaths::footprint() { return scratch().footprint; }

const PathContributions& FreshPaths::trace(size_t work, int path, RayStats& stats, bool recordFootprint) {
    constexpr int kFolds = ItemEstimates::kFolds;
    const WorkItem& w = plan_.work[work];
    const PlacedSampler& sampler = *plan_.placed[size_t(w.sampler)];
    Scratch& s = scratch();
    const uint64_t seed = options_.seed;
    // The item's low-discrepancy sequence (one per fold for types that compare folds).
    const bool folds = sampler.independentFolds();
    Rng rng(hashValues({seed, uint64_t(w.sampler), uint64_t(w.item), uint64_t(path)}));
    auto samplesOf = [&]() {
        if (!options_.lowDiscrepancy) return PathSamples(rng);
        if (s.sequences.empty() || s.seed != seed || s.sampler != w.sampler || s.item != w.item || s.folds != folds) {
            s.sequences.clear();
            for (int g = 0; g < (folds ? kFolds : 1); ++g)
                s.sequences.emplace_back(
                    hashValues({seed, kSequenceTag, uint64_t(w.sampler), uint64_t(w.item), folds ? uint64_t(g) : uint64_t(kFolds)}));
            s.seed = seed, s.sampler = w.sampler, s.item = w.item, s.folds = folds;
        }
        return PathSamples(rng, s.sequences[folds ? size_t(path % kFolds) : 0], uint32_t(folds ? path / kFolds : path));
    };
    PathSamples samples = samplesOf();
    PathParams params;
    params.lightFloor = plan_.lightFloorOf[size_t(w.sampler)];
    s.traced = PathContributions(w.item);
    if (recordFootprint) {
        s.footprint.clear();
        params.footprint = &s.footprint;
    }
    sampler.sample(*plan_.tracerOf[size_t(w.sampler)], w.item, samples, stats, params, s.traced);
    return s.traced;
}

}  // namespace luxplan
