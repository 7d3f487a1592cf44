// The photometric path tracer: next-event estimation to every emitter kind (area
// lights, sun disks, sky through window portals) combined with BSDF sampling by
// multiple importance sampling (power heuristic), Russian roulette instead of a
// depth cap, and thin glass panes that shadow rays and paths pass through,
// attenuated by the pane's transmittance. Results are in lx and cd/m^2.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/materials/bsdf.h>
#include <luxplan/core/spherical_rect.h>
#include <luxplan/pathtracer/emitters.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

struct PathTracerOptions {
    EmitterSelection emitterSelection = EmitterSelection::PowerDistance;
    bool portals = true;       // sample the sky through the room's openings from inside it
    int rouletteDepth = 3;     // bounces before Russian roulette starts
    int maxDepth = 256;        // a safety net only: roulette ends paths long before
};

// Rays traced, for throughput figures.
struct RayStats {
    uint64_t closest = 0, shadow = 0;
    RayStats& operator+=(const RayStats& o) { closest += o.closest, shadow += o.shadow; return *this; }
};

class PathTracer {
public:
    // `daylight` may be null (night). The scene's current layout places carried emitters.
    PathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, const PathTracerOptions& options = {});

    // Call after the EmbreeScene's layout changed (emitters carried by entities move).
    void updateLayout();

    // One-sample estimators (average many for the value):
    // illuminance (lx) at p over the hemisphere around unit n;
    double illuminanceSample(const Vec3& p, const Vec3& n, Rng& rng, RayStats& stats) const;
    // mean luminance over the whole sphere at p (cd/m^2);
    double sphericalLuminanceSample(const Vec3& p, Rng& rng, RayStats& stats) const;
    // luminance arriving at ray.origin from ray.direction (unit), in cd/m^2.
    double radianceSample(const Ray& ray, Rng& rng, RayStats& stats) const;
    // The same, also telling whether the ray's first hit is a luminaire (the value is then
    // its luminance alone: emitters end paths).
    double radianceSample(const Ray& ray, Rng& rng, RayStats& stats, bool& hitEmitterFirst) const;

    const EmbreeScene& rayTracer() const { return rt_; }
    const EmitterSet& emitters() const { return emitters_; }

private:
    enum class SensorKind { Hemisphere, Sphere, Camera };
    double trace(SensorKind sensor, const Vec3& p, const Vec3& n, Rng& rng, RayStats& stats,
                 bool* hitEmitterFirst = nullptr) const;

    // The room's openings seen from one vertex. A portal is chosen with a cheap weight
    // (area x cos / distance^2, capped at 2 pi), then a direction uniform in its
    // spherical rectangle: pdf = P(portal) / solid angle. Only the rectangles a vertex
    // samples or an escaping ray passes through are set up (four acos each); the view of
    // a sampler point, shared by all its paths, sets up all. Openings beyond kMaxPortals
    // are not sampled directly (BSDF sampling still finds them, so the estimate stays
    // unbiased).
    static constexpr int kMaxPortals = 16;
    struct PortalView {
        bool active = false;  // the vertex is inside the room: sample the portals
        int count = 0;
        Vec3 point;
        double weight[kMaxPortals] = {};
        double weightTotal = 0;
        mutable SphericalRect rects[kMaxPortals];
        mutable bool built[kMaxPortals] = {};
    };
    void viewPortals(const Vec3& p, PortalView& view) const;
    void computePortals(const Vec3& p, PortalView& view, bool buildAll) const;
    const SphericalRect& portalRect(const PortalView& view, int i) const;
    double skyPdf(const PortalView& view, const Vec3& p, const Vec3& w) const;
    EnvironmentSample sampleSky(const PortalView& view, const Vec3& p, Vec2 u) const;
    // Transmittance along p + t w up to tMax (the distance to the sampled point on
    // emitter `target`, or infinity for sun and sky): products of pane transmittances, 0
    // when anything opaque is in the way. Emitters do not block shadow rays towards
    // emitters, so that float error in Embree's intersection of the target itself (a
    // grazing ray to a small sphere) cannot shadow a light.
    double transmittance(const Vec3& p, const Vec3& w, double tMax, int target, RayStats& stats) const;

    const EmbreeScene& rt_;
    const DaylightEnvironment* daylight_;
    PathTracerOptions options_;
    std::vector<Bsdf> bsdfs_;  // per scene material
    EmitterSet emitters_;
    std::vector<Rect3> portals_;
    std::vector<Vec3> portalNormals_;  // edgeU x edgeV: the opening's normal times its area
    Bounds3 room_;
    bool hasRoom_ = false;
    uint64_t id_ = 0;  // unique per tracer, keys the per-thread portal cache
};

}  // namespace luxplan
