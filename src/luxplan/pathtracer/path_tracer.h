// The photometric path tracer: paths start at a sensor (sensor.h: what a light
// sampler or a camera pixel responds to) and take next-event estimation to every
// light (area emitters of emitters.h, the sun disks, the sky through window portals
// of sky_light.h, the sun's light off surfaces outside seen through those portals,
// and at surfaces the sunlit patches of sun_patches.h) combined with
// BSDF sampling by multiple importance sampling (power heuristic), Russian roulette instead of a depth cap, and thin glass panes that
// shadow rays and paths pass through, attenuated by the pane's transmittance (the
// windows' panes analytically for shadow rays, panes.h). Translucent surfaces are
// vertices like opaque ones (they block shadow rays) whose light sampling and BSDF
// sampling reach both sides.
// Results are in lx and cd/m^2.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/materials/bsdf.h>
#include <luxplan/pathtracer/emitters.h>
#include <luxplan/pathtracer/open_sun_disks.h>
#include <luxplan/pathtracer/panes.h>
#include <luxplan/pathtracer/sealed_boxes.h>
#include <luxplan/pathtracer/path_footprint.h>
#include <luxplan/pathtracer/path_samples.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/pathtracer/sky_light.h>
#include <luxplan/pathtracer/sun_patches.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

struct Path;
struct LightSample;

struct PathTracerOptions {
    EmitterSelection emitterSelection = EmitterSelection::PowerDistance;
    bool portals = true;       // sample the sky through the room's openings from inside it
    bool sunPatches = true;    // sample the room's sunlit patches at surface vertices
    // Follow the sky's portal samples that meet a surface outside the room (a facade
    // across the street) and take the sun's light there.
    bool exteriorSun = true;
    // Choose each sun sample's disk among those the room's shell may let through from
    // the vertex (open_sun_disks.h); false: among all of the period's disks.
    bool openSunDisks = true;
    int rouletteDepth = 3;     // bounces before Russian roulette starts
    // The roulette lets a path go on with probability min(0.95, throughput / (level x
    // the first surface's)), so a survivor carries level x that throughput (or more).
    // A third: at 1 (as before 2026-12-04) the few deep survivors carried a first
    // vertex's whole weight, and one that met a sunlit patch or a bright window
    // dominated its point (docs/performance.md, "Russian roulette at a third").
    double rouletteLevel = 1.0 / 3.0;
    int maxDepth = 256;        // a safety net only: roulette ends paths long before
};

// Where the light of the paths came from (a sampler's light budget, for reports):
// every contribution's luminance, summed by its source. Light that reaches the
// sensor straight from a source (the sensor's own light samples and the rays it
// sends that meet the source) counts as that source's; light that scattered off a
// surface first counts as interreflected, whatever its source.
struct LightBudget {
    double sun = 0, sky = 0;        // direct; the sky includes the ground outside
    std::vector<double> emitters;   // direct, per Scene::emitters index (grown as needed)
    double interreflected = 0;
    // The same light by kind (kSunKind, kSkyKind, kLuminaireKind) and by the surfaces it
    // scattered off before the sensor (0: direct; the last entry holds that many and more).
    static constexpr int kSunKind = 0, kSkyKind = 1, kLuminaireKind = 2, kKinds = 3, kBounces = 8;
    std::array<std::array<double, kBounces>, kKinds> byBounce{};
    static constexpr int kSun = -1, kSky = -2;  // sources that are not emitters
    void credit(int source, int depth, double value) {
        if (!(value == value)) return;  // NaN: the estimator drops the path too
        const int kind = source == kSun ? kSunKind : source == kSky ? kSkyKind : kLuminaireKind;
        byBounce[size_t(kind)][size_t(std::min(depth, kBounces - 1))] += value;
        if (depth > 0) interreflected += value;
        else if (source == kSun) sun += value;
        else if (source == kSky) sky += value;
        else if (source >= 0) {
            if (emitters.size() <= size_t(source)) emitters.resize(size_t(source) + 1, 0.0);
            emitters[size_t(source)] += value;
        }
    }
    double total() const {
        double t = sun + sky + interreflected;
        for (double e : emitters) t += e;
        return t;
    }
};

// The sun's and the sky's light of a path by the direction it left them in, credited
// as LightBudget is: what daylight coefficients (annual/daylight_coefficients.h) bin by
// sky patch and sun position.
class DaylightTally {
public:
    virtual ~DaylightTally() = default;
    // `source`: LightBudget::kSun or kSky; `towards`: unit, from the scene towards the
    // sun disk or the sky (or the ground below the horizon); `depth`: the surfaces the
    // light scattered off before the sensor; `value`: luminance, as LightBudget's.
    virtual void add(int source, const Vec3& towards, int depth, double value) = 0;
};

// Rays traced, for throughput figures.
struct RayStats {
    uint64_t closest = 0, shadow = 0;
    RayStats& operator+=(const RayStats& o) { closest += o.closest, shadow += o.shadow; return *this; }
};

// What one path is traced with besides its random numbers, and where it records what
// it did (PathTracer::sample).
struct PathParams {
    // Russian roulette on the light samples at surface vertices: a sample whose
    // contribution before its shadow ray (throughput x BSDF x Le / pdf, luminance in the
    // sensor's unit) is c < lightFloor is traced with probability c / lightFloor and
    // counts lightFloor / c times, so that a path spends its shadow rays where its light
    // is. Unbiased; each such sample adds at most c x lightFloor to the variance. 0:
    // every sample traced.
    double lightFloor = 0;
    // Where its rays went, if set: every ray of the path is added to it (incremental
    // re-evaluation, incremental/path_cache.h).
    PathFootprint* footprint = nullptr;
    LightBudget* budget = nullptr;  // credited with every contribution, if set
    // Credited with every contribution of the sun and the sky, if set. Not with the
    // exterior sun (PathTracerOptions::exteriorSun), whose samples mix both.
    DaylightTally* daylight = nullptr;
};

// The light a path's next-event estimation found at the sensor itself, reported apart
// from the path's value with its direction: a sensor made of cells (the directional
// sampler's strata) counts each sample in the cell its direction falls in.
struct SensorLight {
    // One sample per light kind: emitters, sun, sky (or the sun off a surface outside).
    static constexpr int kCapacity = 3;
    int count = 0;
    Vec3 wi[kCapacity];
    double value[kCapacity] = {};  // response * Le * T * MIS weight / pdf, luminance
};

class PathTracer {
public:
    // `daylight` may be null (night). The scene's current layout places carried emitters.
    PathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, const PathTracerOptions& options = {});

    // Call after the EmbreeScene's layout changed (emitters carried by entities move).
    void updateLayout();

    // One path's estimate of what `sensor` measures (average many for the value).
    // `hitEmitterFirst`, when given, tells whether the first ray from a delta sensor
    // hit a luminaire (the value is then its luminance alone: emitters end paths).
    // `sensorLight`, when given, receives the light sampled at the sensor instead of
    // the returned value (which then holds the rest of the path's).
    // `params`: the path's roulette floor and recorders (PathParams).
    double sample(const Sensor& sensor, PathSamples& samples, RayStats& stats, const PathParams& params,
                  bool* hitEmitterFirst = nullptr, SensorLight* sensorLight = nullptr) const;
    // The same with every light sample traced and nothing recorded.
    double sample(const Sensor& sensor, PathSamples& samples, RayStats& stats, bool* hitEmitterFirst = nullptr,
                  SensorLight* sensorLight = nullptr) const {
        return sample(sensor, samples, stats, PathParams{}, hitEmitterFirst, sensorLight);
    }
    // The same with pseudo-random numbers only.
    double sample(const Sensor& sensor, Rng& rng, RayStats& stats, bool* hitEmitterFirst = nullptr,
                  SensorLight* sensorLight = nullptr) const {
        PathSamples samples(rng);
        return sample(sensor, samples, stats, hitEmitterFirst, sensorLight);
    }
    // The same for the usual sensors: illuminance (lx) at p over the hemisphere around
    // unit n, and the luminance arriving along a ray (cd/m^2).
    double illuminanceSample(const Vec3& p, const Vec3& n, Rng& rng, RayStats& stats) const {
        return sample(CosineSensor(p, n), rng, stats);
    }
    double radianceSample(const Ray& ray, Rng& rng, RayStats& stats, bool& hitEmitterFirst) const {
        hitEmitterFirst = false;
        return sample(RaySensor(ray), rng, stats, &hitEmitterFirst);
    }

    const EmbreeScene& rayTracer() const { return rt_; }
    const EmitterSet& emitters() const { return emitters_; }
    // Whether no light reaches p: inside a closed opaque box (sealed_boxes.h). A path
    // from there is 0 and traces no ray. `exit`: where the way out leaves the box.
    bool sealedAt(const Vec3& p, Vec3* exit = nullptr) const;
    const DaylightEnvironment* daylight() const { return daylight_; }  // null at night
    // Whether paths sample the sunlit patches (asked for, and the scene has a sun, a room
    // with an opening it shines through, and no glass furniture).
    bool samplesSunPatches() const { return patches_.active(); }
    // Whether the sky's portal samples that meet a surface outside the room take the
    // sun's light there (asked for, and the scene has a sun, a sky, a room, visible
    // static surfaces outside it and no glass furniture).
    bool samplesExteriorSun() const { return exteriorSun_; }

    // Transmittance along p + t w up to tMax (the distance to the sampled point on
    // emitter `target`, or infinity for sun and sky): products of pane transmittances, 0
    // when anything opaque or another luminaire is in the way (the target itself never
    // shadows itself). Public for the glare samplers' direct views of their sources.
    double transmittance(const Vec3& p, const Vec3& w, double tMax, int target, RayStats& stats,
                         PathFootprint* footprint = nullptr) const;

    // The light a sun of unit normal illuminance (1 lx) along unit `towardsSun` sends
    // straight to the sensor, nothing scattered: its response there times what lets the
    // sun through (panes; 0 behind anything opaque), along the disk's centre. The direct
    // sun of daylight coefficients, per hour without noise. `footprint`, if given, gets
    // the ray from the sensor towards the sun.
    double directSun(const Sensor& sensor, const Vec3& towardsSun, RayStats& stats, PathFootprint* footprint = nullptr) const;

private:
    // The lights are strategies (light_strategy.h) that read the tracer's parts.
    friend class EmitterStrategy;
    friend class SunStrategy;
    friend class SkyStrategy;
    friend class SunPatchStrategy;

    // Next-event estimation at the path's current vertex: each strategy in turn.
    void estimateDirect(Path& path) const;
    // A light sample joined to the current vertex by a shadow ray, weighed by MIS.
    void connect(Path& path, const LightSample& s) const;
    // BSDF sampling at the current vertex (its direction into d) and Russian roulette;
    // false ends the path.
    bool scatter(Path& path, Vec3& d) const;
    // The ray along d through the panes it crosses to the next scattering vertex (true),
    // or to the light it escapes to or meets (false: the path ends).
    bool follow(Path& path, Vec3 d, bool* hitEmitterFirst) const;
    void addEscaped(Path& path, const Vec3& d) const;
    void addEmitterHit(Path& path, const Hit& hit, const Vec3& d) const;
    // The density at the current vertex of the two-bounce ways to its sun light (a
    // sunlit patch, a surface outside), 0: BSDF sampling and the sun's own sampling only.
    double otherSunDensity(const Path& path, const Vec3& ws) const;

    const EmbreeScene& rt_;
    const DaylightEnvironment* daylight_;
    PathTracerOptions options_;
    std::vector<Bsdf> bsdfs_;  // per scene material
    EmitterSet emitters_;
    SkyLight sky_;
    SunPatches patches_;
    OpenSunDisks sunDisks_;
    OpeningPanes panes_;
    SealedBoxes sealed_;
    uint64_t layoutStamp_ = 0;  // unique to each updateLayout() of any tracer
    bool exteriorSun_ = false;
};

}  // namespace luxplan
