// A sampler's light budget: the shares of what it measures that come straight from
// the sun, from the sky (and the ground outside), from each luminaire, and from light
// that scattered off the room's surfaces first (interreflection), so that a report can
// say what lights a desk and what would change it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

struct SamplerBudget {
    // Shares in [0, 1] that sum to 1 (all 0 when the sampler sees no light).
    double sun = 0, sky = 0, interreflected = 0;
    std::vector<double> emitters;  // per Scene::emitters index
    uint64_t paths = 0;            // traced for it
};

// Traces `pathsPerItem` paths per item of each sampler (seeded from (seed, tag,
// sampler, item, path), so the result does not depend on the thread count) and sums
// every contribution of each path by its source (pathtracer's LightBudget). The
// shares are over all of a sampler's items: for a planar sampler its points' mean,
// for a directional one all its strata, not only the brightest.
std::vector<SamplerBudget> measureLightBudgets(const PathTracer& tracer, int pathsPerItem = 64, uint64_t seed = 1);

// The budget in words, largest share first, shares under 0.5 % left out:
// "sun 61%, sky 22%, interreflection 14%, panel1 3%".
std::string describeBudget(const Scene& scene, const SamplerBudget& budget);

}  // namespace luxplan
