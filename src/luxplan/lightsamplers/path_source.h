// The second part of a measurement (measureSamplers): where each path comes from.
// Every path is traced afresh by FreshPaths (fresh_paths.h) unless a path source in
// front of it gives the path from what an earlier measurement kept (the path cache,
// incremental/path_cache.h); a source may wrap another (the cache check,
// incremental/checked_paths.h). The numbers are the same whichever gives a path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_footprint.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {

class EmbreeScene;
class FreshPaths;

class PathSource {
public:
    // One path as a source gives it.
    struct Path {
        const PathContributions* contributions = nullptr;  // what it added (valid until the thread's next path)
        bool reused = false;      // read back, not traced for this layout
        bool askedAgain = false;  // reused because its shadow queries, asked again, answered as before
    };

    virtual ~PathSource() = default;
    // Before a measurement of `rt`'s current layout with one work item per sampler item,
    // whose samplers are `workSampler`; `streams` keys what a path's numbers are (the
    // seed and the sampling options).
    virtual void begin(const EmbreeScene& rt, const std::vector<int>& workSampler, uint64_t streams) = 0;
    // Path `path` of work item `work`: given by the source, or traced by `fresh` (rays
    // counted in `stats`). Threads may ask for paths of one work item at once.
    virtual Path get(size_t work, int path, RayStats& stats, FreshPaths& fresh) = 0;
    // What the measurement did with path `path` of work item `work`, for paths 0, 1, ...
    // in order per work item (from one thread per work item at a time); `footprint` is
    // a path traced afresh's.
    virtual void used(size_t work, int path, const Path& p, const FootprintView& footprint) = 0;
    // Paths the measurement in progress, or else the last one, read back.
    virtual uint64_t reused() const = 0;
};

}  // namespace luxplan
