// The path tracer's lights behind one interface (pbrt-v4's Light and light sampler):
// each way of drawing light at a path's vertex is a LightStrategy with sample() (next-
// event estimation at the path's current vertex: draw the strategy's numbers, connect,
// add what it finds) and pdf() (the density with which it would have drawn light the
// path found another way). The strategies, in the order they draw their numbers at a
// vertex (light_strategies.h): the area emitters, the sun disks, the sky through the
// portals (with the sun and sky off surfaces outside the room), the sunlit patches.
// `Path` is one path's state as the strategies and the integrator share it; misWeight()
// is the one power heuristic over the strategies that could make a light path.
// Internal to pathtracer/.
#pragma once

#include <optional>

#include <luxplan/core/math.h>
#include <luxplan/core/warp.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/materials/bsdf.h>
#include <luxplan/pathtracer/path_samples.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/pathtracer/sky_light.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

inline constexpr double kRayEpsilon = 1e-4;  // metres; scenes are rooms, not microns

inline Vec3 offsetAlong(const Vec3& p, const Vec3& n, const Vec3& w) {
    return p + n * (dot(w, n) >= 0 ? kRayEpsilon : -kRayEpsilon);
}

// Where the path currently scatters: the sensor itself or a surface.
struct Vertex {
    Vec3 p;
    Vec3 ng;  // geometric normal on the side the path arrived from (surfaces)
    Frame shading;
    Vec3 wo;  // local shading coordinates
    const Bsdf* bsdf = nullptr;  // null at the sensor

    bool isSurface() const { return bsdf != nullptr; }
};

// The vertex at a surface hit, seen from direction wo (unit, away from the surface).
Vertex surfaceVertex(const Hit& hit, const Bsdf& bsdf, const Vec3& wo);

// A surface vertex where the sunlit patches were sampled, as the MIS weights of the
// paths it continues need it: the strategy skips the beams whose far end (SunPatches::
// beamEnd) lies behind an opaque vertex's surface, without tracing them.
struct PatchOrigin {
    Vec3 p, ng;
    bool translucent = false;
    bool valid = false;  // the path arrived from a vertex where the patches were sampled
    bool faces(const Vec3& beamEnd) const { return translucent || dot(ng, beamEnd - p) > 0; }
};

// The densities of the strategies that could make one path to a light whose last
// scattering vertex is y, for the power heuristic:
//  - the light's own sampling at y (`light`, per solid angle) and BSDF sampling at y
//    (`bsdf`), the two ways of every light;
//  - for the sun's and the sky's light at a surface y reached by a BSDF sample from a
//    vertex x, a two-bounce strategy drawn at x (a sunlit patch, a surface outside the
//    room seen through a portal): its area density at y (`twoBounce`, 0: none competes)
//    and its light's density (`twoBounceLight`); the other two ways then take the area
//    density of x's BSDF sample at y (`arrival`) as their first factor.
struct StrategyDensities {
    double light = 0, bsdf = 0;
    double arrival = 0, twoBounce = 0, twoBounceLight = 0;
};
enum class Strategy { Light, Bsdf, TwoBounce };

// The power heuristic's weight of the path that strategy `own` made. With a two-bounce
// strategy, over three products of densities in one order (light, two-bounce, BSDF).
inline double misWeight(Strategy own, const StrategyDensities& d) {
    if (d.twoBounce > 0) {
        const double a = d.arrival;
        const double mine = own == Strategy::Light ? a * d.light : own == Strategy::Bsdf ? a * d.bsdf : d.twoBounce * d.twoBounceLight;
        const double sum = (a * d.light) * (a * d.light) + (d.twoBounce * d.twoBounceLight) * (d.twoBounce * d.twoBounceLight) +
                           (a * d.bsdf) * (a * d.bsdf);
        return sum > 0 ? mine * mine / sum : 0;
    }
    return own == Strategy::Light ? powerHeuristic(1, d.light, 1, d.bsdf) : powerHeuristic(1, d.bsdf, 1, d.light);
}

// One light sample to connect to the current vertex by a shadow ray (PathTracer::
// connect): a direction, what arrives along it, its density per solid angle.
struct LightSample {
    Vec3 wi;
    Vec3 Le;
    double pdf = 0;
    double maxT = kInf;  // the sampled point's distance (emitters)
    int target = -1;     // the emitter sampled (it does not shadow itself), else -1
    int source = LightBudget::kSky;  // LightBudget's source: an emitter's index, kSun or kSky
    // The direction must leave through an opening (the sun's: a direction that leaves
    // the box through an opaque wall is blocked whatever the layout), tested once the
    // surface is known to face it.
    bool throughShell = false;
    // The sky's radiance, positive wherever it points (DaylightEnvironment::
    // radiancePositive), is looked up only once the shadow ray has found the way open
    // (most are blocked, by furniture).
    bool skyLater = false;
};

// One path's state, as the integrator and the strategies share it.
struct Path {
    Path(const PathTracer& tracer, const Sensor& sensor, PathSamples& samples, RayStats& stats, const PathParams& params,
         SensorLight* sensorLight)
        : tracer(tracer), sensor(sensor), samples(samples), stats(stats), params(params), sensorLight(sensorLight),
          lightFloor(params.lightFloor) {}

    const PathTracer& tracer;
    const Sensor& sensor;
    PathSamples& samples;
    RayStats& stats;
    const PathParams& params;
    SensorLight* sensorLight;
    const double lightFloor;

    Vec3 L, throughput{1, 1, 1};
    Vertex v;  // the current vertex (the sensor's at depth 0)
    int depth = 0;
    double firstWeight = 0;  // the first vertex's throughput (the roulette's scale)
    // A light sample the sensor cannot see adds nothing: none is drawn (a glare frustum
    // facing away from the sun and the windows).
    bool sensorSeesSun = false, sensorSeesEmitters = false;
    // Once through a see-through surface, a path may run inside parts whose faces
    // coincide with another material's (a glass top resting on a wooden leg, and so
    // into the leg): its rays' ties then go by a fixed order, so that it is the same
    // path after any move (EmbreeScene::intersect; a second query per ray, which paths
    // that never meet glass or a translucent surface do not pay).
    bool seeThrough = false;

    // ---- the last non-delta vertex, as BSDF sampling left it (MIS) ----
    bool lastDelta = false;
    double lastPdf = 0;
    // The share of the sun's disks open from this vertex and the last non-delta one
    // (OpenSunDisks; 1 where no sun sample was asked for: no sun light can come there).
    double sunOpen = 1, lastSunOpen = 1;
    Vec3 lastPoint;
    bool lastAtSensor = true;  // lastPoint is the sensor's (its emitter view applies)
    bool lastPatched = false;  // the patches were sampled there
    bool lastOutside = false;  // its portal sample went on to surfaces outside
    PatchOrigin lastOrigin;

    // ---- how BSDF sampling reached the current vertex (the two-bounce strategies) ----
    // The area density at the current vertex of the BSDF sample that reached it from a
    // surface vertex where the sunlit patches were sampled (0 otherwise): the patch
    // strategy could have made the same path, and the sun's MIS weights count it.
    double arrivalDensity = 0;
    PatchOrigin arrivalFrom;
    // The same for the sunlit surfaces outside: at a vertex outside the room reached
    // through an opening, the area density with which the last vertex's portal sample
    // could have reached it (0 otherwise; never non-zero where a patch's is, which
    // lies in the room).
    double outsideDensity = 0;

    // ---- the sky's portals seen from this vertex and from the last non-delta one ----
    // A View is large (16 spherical rectangles): a path neither zeroes nor copies one.
    // The sensor's is its thread's cached view, a surface's is set up in this thread's
    // scratch (views[current ^ 1] is the last non-delta vertex's).
    const SkyLight::View* views[2] = {nullptr, nullptr};
    SkyLight::View* scratch = nullptr;  // two, per thread
    int current = 0;

    // ---- this vertex's light samples (set by PathTracer::estimateDirect) ----
    const SkyLight::View* view = nullptr;  // null without a sky
    bool skyHere = false, sunHere = false;
    bool outside = false;         // the sky's sample lights a surface outside with the sun's
    EnvironmentSample sunAtZ;     // that sun sample: the period's own, from the vertex's numbers

    // The sunlit patch point drawn once per path (SunPatchStrategy).
    struct PatchLight {
        bool drawn = false, traced = false, lit = false;
        EnvironmentSample sun;
        Vec3 entry, beamEnd;
        std::optional<Hit> hit;
        double density = 0, toSun = -1;  // toSun < 0: not asked yet
        double openAtY = 0;  // the open disks' share at y (OpenSunDisks), once asked
    } patch;

    // f * |cos| and the sampling pdf of vertex x for a world direction.
    Vec3 evalCos(const Vertex& x, const Vec3& wi) const {
        if (!x.isSurface()) {
            double r = sensor.response(wi);
            return Vec3(r, r, r);
        }
        // Light must arrive on the side the path is on (no leaks through surfaces), or
        // from the other side of a translucent one; on the same side of the geometric
        // and the shading normal (wo is on the upper side of both).
        const double side = dot(wi, x.ng);
        if (side == 0 || (side < 0 && !x.bsdf->hasDiffuseTransmission())) return Vec3();
        Vec3 local = x.shading.toLocal(wi);
        if ((side > 0) != (local.z > 0)) return Vec3();
        return x.bsdf->eval(x.wo, local) * std::abs(local.z);
    }
    double pdfOf(const Vertex& x, const Vec3& wi) const {
        if (!x.isSurface()) return sensor.pdf(wi);
        return x.bsdf->pdf(x.wo, x.shading.toLocal(wi));
    }
    // Rays leave a surface offset along its normal, and a sensor 0.1 mm along the ray,
    // so that a sampler point lying on a surface (a micron off it, after the transforms
    // of a rotated entity) sees past that surface.
    Vec3 spawn(const Vertex& x, const Vec3& wi) const { return x.isSurface() ? offsetAlong(x.p, x.ng, wi) : x.p + wi * kRayEpsilon; }

    // A light sample's contribution, credited to `source` at `creditDepth` bounces:
    // at the sensor (depth 0) into sensorLight when given, else into L. `towards`: where
    // the sun's or sky's light left them, when that is not along wi (a sunlit patch's sun).
    void add(const Vec3& wi, const Vec3& contribution, int source, int creditDepth, const Vec3* towards = nullptr) {
        if (params.budget) params.budget->credit(source, creditDepth, luminance(contribution));
        if (params.daylight && (source == LightBudget::kSun || source == LightBudget::kSky))
            params.daylight->add(source, towards ? *towards : wi, creditDepth, luminance(contribution));
        if (depth == 0 && sensorLight) {
            sensorLight->wi[sensorLight->count] = wi;
            sensorLight->value[sensorLight->count++] = luminance(contribution);
        } else {
            L += contribution;
        }
    }
};

class LightStrategy {
public:
    virtual ~LightStrategy() = default;
    // Next-event estimation at the path's current vertex (not a delta one): draws this
    // strategy's numbers (also where it then finds nothing, so that every later number
    // stays where it is) and adds the light its samples find.
    virtual void sample(Path& path) const = 0;
    // The density with which this strategy would have drawn the light a BSDF sample of
    // the path found along unit `wi` (`hit`: the emitter it met; null: it escaped):
    // per solid angle from the last non-delta vertex for the one-vertex strategies
    // (emitters, sun, sky); per unit area at the current vertex for the sunlit
    // patches (the sun's light there, `wi` towards the sun). 0: it cannot.
    virtual double pdf(const Path& path, const Vec3& wi, const Hit* hit) const = 0;
};

}  // namespace luxplan
