// A scene with everything needed to measure it: the daylight, the Embree scene and
// the path tracer, for a scene built in C++ (support/scene_builder.h).
#pragma once

#include <memory>
#include <optional>

#include <luxplan/daylight/daylight.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/scene/layout.h>

namespace luxplan::test {

struct SceneLab {
    Scene scene;
    std::optional<DaylightEnvironment> daylight;
    std::unique_ptr<EmbreeScene> rt;
    std::unique_ptr<PathTracer> tracer;

    explicit SceneLab(Scene s, const PathTracerOptions& options = {}) : scene(std::move(s)) {
        if (scene.daylight) daylight = buildDaylight(*scene.daylight, scene.site);
        rt = std::make_unique<EmbreeScene>(scene, initialLayout(scene));
        tracer = std::make_unique<PathTracer>(*rt, daylight ? &*daylight : nullptr, options);
    }
    MeasureResult measure(int paths, uint64_t seed = 1) const {
        MeasureOptions o;
        o.pathsPerPoint = paths, o.seed = seed;
        return measure(o);
    }
    MeasureResult measure(const MeasureOptions& options) const { return measureSamplers(*tracer, options); }
};

}  // namespace luxplan::test
