// The daylight factor (CIE; BS 8206-2, EN 17037): the illuminance at a point indoors as a
// share of the illuminance that the same sky gives an unobstructed horizontal plane
// outdoors, DF = 100 E_in / E_out %, under the CIE standard overcast sky (CIE standard
// general sky type 1, Moon & Spencer), which has no sun and the same luminance in every
// azimuth: DF then depends on the room and its surroundings alone, not on the time, the
// site or the sky's brightness. `measure --daylight-factor` measures each planar
// sampler's mean daylight factor with the luminaires off (docs/scene-format.md).
#pragma once

#include <string>
#include <vector>

#include <luxplan/daylight/daylight_params.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// E_out, the overcast sky's illuminance on the open horizontal plane (the sky alone, lx).
// The daylight factor does not depend on it.
inline constexpr double kDaylightFactorSkyLx = 10000;

// The sky of the daylight factor: CIE standard overcast giving kDaylightFactorSkyLx on
// the open horizontal plane, no sun, and the scene's ground (its daylight's
// ground_reflectance; 0.2 for a scene without daylight).
DaylightParams daylightFactorSky(const Scene& scene);

// Why the scene has no daylight factor to measure, as a sentence; "" when it has one: it
// has no planar sampler, or it has rooms and none of them an opening (no daylight
// enters: every daylight factor would be 0). A scene without a room is open ground.
std::string daylightFactorRefusal(const Scene& scene);

// The scene the daylight factor is measured in: its planar samplers only, every
// luminaire and carried emitter off (no flux), and the overcast sky instead of its own
// daylight. Its entities are the scene's, so the scene's layouts place it.
struct DaylightFactorScene {
    Scene scene;
    std::vector<size_t> samplers;  // for each of its samplers, its index in the original scene
};
DaylightFactorScene daylightFactorScene(const Scene& scene);

// One planar sampler's daylight factor, in percent of E_out.
struct DaylightFactor {
    double percent = 0;   // the mean over its points (covered points left out), as the sampler's value
    double stdError = 0;  // of `percent`
    double min = 0;       // the least point's
    std::vector<double> points;  // each point's (NaN: covered by furniture)
};

struct DaylightFactorResult {
    double outdoorLx = 0;          // E_out of the baked sky (the map's own, exact for it)
    std::vector<size_t> samplers;  // the scene's planar samplers, in its order
    std::vector<DaylightFactor> factors;  // one per entry of `samplers`
    MeasureResult measured;        // the illuminances (lx) under the overcast sky, per entry of `samplers`
};

// Measures the daylight factor of every planar sampler of `scene` under `layout`, with the
// options' paths and seed (`tracing` as for any measurement; options.lightFloors is
// ignored). Throws std::runtime_error with daylightFactorRefusal()'s sentence where there
// is none to measure.
DaylightFactorResult measureDaylightFactors(const Scene& scene, const Layout& layout, const MeasureOptions& options,
                                            const PathTracerOptions& tracing = {});

}  // namespace luxplan
