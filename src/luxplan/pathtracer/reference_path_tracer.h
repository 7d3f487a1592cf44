// A deliberately simple twin of PathTracer (pbrt-v4's SimplePathIntegrator), to test the
// fast one against: at every non-delta vertex one light sample of each kind (an emitter
// chosen uniformly and a point on it, the sun from all of the period's disks, the sky
// map by its own importance sampling), BSDF sampling to the next vertex, and the power
// heuristic over the two; thin panes crossed one hit at a time. None of the fast
// tracer's strategies: no portals, no sunlit patches, no open sun disks, no exterior
// sun, no sealed boxes, no roulette (a fixed depth instead), no per-thread caches.
// Slow; tests only (tests/reference/).
#pragma once

#include <luxplan/core/rng.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/materials/bsdf.h>
#include <luxplan/pathtracer/emitters.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

class ReferencePathTracer {
public:
    // `daylight` may be null (night). A path ends after `maxDepth` surfaces: with
    // reflectances up to 0.8 what it leaves out is below 0.8^maxDepth of the light.
    ReferencePathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, int maxDepth = 24);

    // One path's estimate of what `sensor` measures (lx or cd/m^2).
    double sample(const Sensor& sensor, Rng& rng) const;

private:
    // Along p + t w for t < tMax: the product of the straight transmittances of the
    // glass met, 0 when anything else is met first (but emitter `target` itself).
    double visibility(const Vec3& p, const Vec3& w, double tMax, int target) const;

    const EmbreeScene& rt_;
    const DaylightEnvironment* daylight_;
    int maxDepth_;
    std::vector<Bsdf> bsdfs_;
    EmitterSet emitters_;
};

}  // namespace luxplan
