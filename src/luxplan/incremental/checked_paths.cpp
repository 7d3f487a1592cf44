#include <luxplan/incremental/checked_paths.h>

#include <algorithm>
#include <span>

#include <luxplan/lightsamplers/fresh_paths.h>

namespace luxplan {
namespace {

// The kept path's point where a fresh trace of it first differs.
std::optional<Vec3> wherePathsPart(std::span<const Segment> kept, const std::vector<Segment>& fresh) {
    auto point = [](const std::array<float, 3>& p) { return Vec3{p[0], p[1], p[2]}; };
    for (size_t q = 0; q < kept.size(); ++q)
        if (q >= fresh.size() || kept[q].from != fresh[q].from || kept[q].to != fresh[q].to) return point(kept[q].from);
    if (fresh.size() > kept.size()) return point(fresh[kept.size()].from);
    return std::nullopt;
}

}  // namespace

void CheckedPaths::begin(const EmbreeScene& rt, const std::vector<int>& workSampler, uint64_t streams) {
    cache_.begin(rt, workSampler, streams);
    workSampler_ = workSampler;
    firstWork_.resize(workSampler.size());
    for (size_t w = 0; w < workSampler.size(); ++w)
        firstWork_[w] = w > 0 && workSampler[w - 1] == workSampler[w] ? firstWork_[w - 1] : w;
    checked_ = 0;
    differences_.clear();
}

PathSource::Path CheckedPaths::get(size_t work, int path, RayStats& stats, FreshPaths& fresh) {
    const Path p = cache_.get(work, path, stats, fresh);
    if (!p.reused) return p;
    RayStats uncounted;  // the check's rays are not the measurement's
    const PathContributions& again = fresh.trace(work, path, uncounted, true);
    ++checked_;
    if (!again.sameAs(*p.contributions)) {
        const CacheDifference d{0,
                                workSampler_[work],
                                int(work - firstWork_[work]),
                                path,
                                p.contributions->sum(),
                                again.sum(),
                                wherePathsPart(cache_.segmentsOf(work, path), FreshPaths::footprint().segments)};
        const std::lock_guard lock(mutex_);
        differences_.emplace_back(work, d);
    }
    return p;
}

CacheCheck CheckedPaths::found() const {
    CacheCheck c;
    c.on = true;
    c.checked = checked_;
    std::vector<std::pair<size_t, CacheDifference>> sorted;
    {
        const std::lock_guard lock(mutex_);
        sorted = differences_;
    }
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return a.first != b.first ? a.first < b.first : a.second.path < b.second.path; });
    for (const auto& [work, d] : sorted) c.note(d);
    return c;
}

}  // namespace luxplan
