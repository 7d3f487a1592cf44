// A scene built from JSON text with everything needed to measure it: the
// daylight, the Embree scene and the path tracer.
#pragma once

#include <memory>
#include <optional>

#include <luxplan/daylight/daylight.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include "support/temp_files.h"

namespace luxplan::test {

struct Lab {
    TempDir dir;
    Scene scene;
    std::optional<DaylightEnvironment> daylight;
    std::unique_ptr<EmbreeScene> rt;
    std::unique_ptr<PathTracer> tracer;

    explicit Lab(const std::string& json, const PathTracerOptions& options = {}) {
        scene = io::loadScene(dir.write("scene.json", json));
        if (scene.daylight) daylight = buildDaylight(*scene.daylight, scene.site);
        rt = std::make_unique<EmbreeScene>(scene, initialLayout(scene));
        tracer = std::make_unique<PathTracer>(*rt, daylight ? &*daylight : nullptr, options);
    }
    MeasureResult measure(int paths, uint64_t seed = 1) const {
        MeasureOptions o;
        o.pathsPerPoint = paths, o.seed = seed;
        return measureSamplers(*tracer, o);
    }
};

}  // namespace luxplan::test
