#include <luxplan/lightsamplers/daylight_factor.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include <luxplan/daylight/daylight.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {
namespace {

bool daylightFactorSamples(const LightSamplerSpec& s) { return std::string_view(s.type->name()) == "planar"; }

}  // namespace

DaylightParams daylightFactorSky(const Scene& scene) {
    DaylightParams sky;
    sky.model = SkyModelType::CieOvercast;
    sky.horizontalIlluminanceLx = kDaylightFactorSkyLx;
    sky.sun = false;
    if (scene.daylight) sky.groundReflectance = scene.daylight->groundReflectance;
    return sky;
}

std::string daylightFactorRefusal(const Scene& scene) {
    if (std::none_of(scene.samplers.begin(), scene.samplers.end(), daylightFactorSamples))
        return "the scene has no planar sampler: the daylight factor is measured at a planar sampler's points "
               "(a work plane)";
    bool rooms = false, openings = false;
    for (const StaticItem& item : scene.geometry)
        if (item.room && !item.invisible) rooms = true, openings |= !item.room->openings.empty();
    if (rooms && !openings)
        return "the room has no openings (windows or rooflights): no daylight enters it, so every daylight factor "
               "would be 0";
    return "";
}

DaylightFactorScene daylightFactorScene(const Scene& scene) {
    DaylightFactorScene out{scene, {}};
    Scene& s = out.scene;
    s.daylight = daylightFactorSky(scene);
    for (Emitter& e : s.emitters) e.fluxLm = 0;  // off: nothing chooses them, nothing sees them shine
    // The planar samplers alone, renumbered; the entities' lists follow.
    std::vector<int> renumbered(scene.samplers.size(), -1);
    s.samplers.clear();
    for (size_t k = 0; k < scene.samplers.size(); ++k)
        if (daylightFactorSamples(scene.samplers[k])) {
            renumbered[k] = int(s.samplers.size());
            s.samplers.push_back(scene.samplers[k]);
            out.samplers.push_back(k);
        }
    for (Entity& e : s.entities) {
        std::vector<int> kept;
        for (int k : e.samplers)
            if (renumbered[size_t(k)] >= 0) kept.push_back(renumbered[size_t(k)]);
        e.samplers = std::move(kept);
    }
    return out;
}

DaylightFactorResult measureDaylightFactors(const Scene& scene, const Layout& layout, const MeasureOptions& options,
                                            const PathTracerOptions& tracing) {
    if (std::string why = daylightFactorRefusal(scene); !why.empty()) throw std::runtime_error(why);
    const DaylightFactorScene df = daylightFactorScene(scene);
    const DaylightEnvironment sky = buildDaylight(*df.scene.daylight, df.scene.site);
    const EmbreeScene rt(df.scene, layout);
    const PathTracer tracer(rt, &sky, tracing);
    MeasureOptions o = options;
    o.lightFloors.clear();
    DaylightFactorResult r;
    // The illuminance the map itself gives the open horizontal plane (exact for the
    // piecewise-constant map), so that open ground reads 100% without the bake's error.
    r.outdoorLx = sky.skyHorizontalIlluminance();
    r.samplers = df.samplers;
    r.measured = measureSamplers(tracer, o);
    const double percent = 100 / r.outdoorLx;
    for (const SamplerResult& m : r.measured.samplers) {
        DaylightFactor f;
        f.percent = percent * m.value;
        f.stdError = percent * m.standardError;
        f.min = kInf;
        for (double p : m.points) {
            f.points.push_back(percent * p);
            if (!std::isnan(p)) f.min = std::min(f.min, percent * p);
        }
        if (!std::isfinite(f.min)) f.min = 0;  // every point covered
        r.factors.push_back(std::move(f));
    }
    return r;
}

}  // namespace luxplan
