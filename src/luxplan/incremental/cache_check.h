// Checking the path cache against fresh traces (checked_paths.h): every path
// the cache reads back is traced again from scratch for the same layout and the two are
// compared bit for bit. They agree but where a path meets two entities' faces of
// different materials flush in one plane before any see-through surface (path_cache.h);
// a difference names the path and where it parts, so a user can find the faces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

// A path the cache read back that, traced again, added something else.
struct CacheDifference {
    int64_t evaluation = 0;  // which measurement of the run (1 = the first; 0 where not counted)
    int sampler = 0;         // Scene::samplers index
    int item = 0;            // the point or stratum it was traced for
    int path = 0;            // its index among that item's paths
    double cached = 0, fresh = 0;  // what it added, summed over the items it reached
    // Where the two paths part: the kept path's point at the start of the first ray
    // that differs (a ray that met coincident faces continues from it); none when every
    // ray is the same.
    std::optional<Vec3> where;
};

// What the check found, over one measurement or a whole search.
struct CacheCheck {
    static constexpr size_t kKept = 16;  // differences kept: the first ones, in order
    bool on = false;
    uint64_t checked = 0;    // paths read from the cache and traced again
    uint64_t differing = 0;  // ... of which differed
    std::vector<CacheDifference> first;

    void note(const CacheDifference& d) {
        ++differing;
        if (first.size() < kKept) first.push_back(d);
    }
    void add(const CacheCheck& o) {
        on = on || o.on;
        checked += o.checked;
        differing += o.differing;
        for (size_t k = 0; k < o.first.size() && first.size() < kKept; ++k) first.push_back(o.first[k]);
    }
};

}  // namespace luxplan
