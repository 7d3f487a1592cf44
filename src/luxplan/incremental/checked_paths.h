// The path cache's check as a decorator of it (optimize --set check_cache=true): every
// path the cache gives is traced again from scratch for the same layout and the two are
// compared bit for bit (cache_check.h). The numbers stay the cache's; a measurement
// costs what one without the cache does, and more.
#pragma once

#include <atomic>
#include <mutex>
#include <vector>

#include <luxplan/incremental/cache_check.h>
#include <luxplan/incremental/path_cache.h>

namespace luxplan {

class CheckedPaths final : public PathSource {
public:
    explicit CheckedPaths(PathCache& cache) : cache_(cache) {}

    void begin(const EmbreeScene& rt, const std::vector<int>& workSampler, uint64_t streams) override;
    Path get(size_t work, int path, RayStats& stats, FreshPaths& fresh) override;
    void used(size_t work, int path, const Path& p, const FootprintView& footprint) override {
        cache_.used(work, path, p, footprint);
    }
    uint64_t reused() const override { return cache_.reused(); }

    // What the check found since begin(): the first differences in work order (sampler,
    // item, path), `evaluation` 0.
    CacheCheck found() const;

private:
    PathCache& cache_;
    std::vector<int> workSampler_;
    std::vector<size_t> firstWork_;  // per work item: its sampler's first
    std::atomic<uint64_t> checked_{0};
    mutable std::mutex mutex_;  // differences are rare: one lock each
    std::vector<std::pair<size_t, CacheDifference>> differences_;  // with their work item, in any order
};

}  // namespace luxplan
