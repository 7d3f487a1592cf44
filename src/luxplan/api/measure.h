// `measure` as a library call: what `luxplan measure SCENE --json` prints, for the CLI
// and the Python module alike (python/bindings.cpp), so that both give the same keys
// and numbers. The CLI keeps its text table and its progress on stderr, which plug in
// through MeasureHooks.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include <luxplan/annual/annual_series.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/scene/scene.h>

namespace luxplan::api {

struct MeasureRequest {
    std::string layoutFile;               // a layout.json to measure instead of the scene's placement
    std::optional<std::string> layoutText;  // ... or its text (named "layout" in errors); not with layoutFile
    int paths = 0;                        // per point; 0: optimizer.report_paths_per_point
    std::optional<uint64_t> seed;         // unset: optimizer.seed
    std::string at;                       // ISO 8601: one instant of the daylight instead of its period
    bool annual = false;                  // also every occupied hour of the period, by daylight coefficients
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();  // "seconds" counts from here
};

// Where a long measurement tells what it does; each may be empty (quiet).
struct MeasureHooks {
    std::function<void(const std::string&)> warning;  // a line for stderr, without its newline
    // The daylight's bake (default: buildDaylight, silent).
    std::function<DaylightEnvironment(const DaylightParams&, const Site&)> bake;
    // Called before the samplers are traced, with their options and the paths in all; what
    // it returns lives while they are traced (a progress watcher that reads
    // MeasureOptions::pathsDone).
    std::function<std::shared_ptr<void>(MeasureOptions&, unsigned long long totalPaths)> watchSamplers;
    // The year's points as they finish (what: "--annual" or "annual goals").
    std::function<void(const std::string& what, size_t done, size_t total, size_t hours)> yearProgress;
};

// Everything `measure` found: what its JSON and its table say.
struct MeasureOutcome {
    Scene scene;  // as measured (flattened with the setting flat)
    MeasureRequest request;
    std::string atReported;  // --at as reported: a weather file's hour at its middle
    MeasureOptions options;
    std::string sampling;    // "sobol" or "random"
    bool sunPatches = false, exteriorSun = false;
    double lightRoulette = 0;
    MeasureResult result;
    std::optional<AnnualSeries> year;  // with `annual`, every sampler's; else the annual goals'
    double yearSeconds = 0, samplersSeconds = 0, seconds = 0;
    double lighting = 0, lightingError = 0, cost = 0;
    GeometryResult geometry;
};

// Measures the scene's samplers (at its placement or the request's layout). Throws
// SceneError, IoError or std::runtime_error (the CLI names the scene file for the last).
MeasureOutcome measure(Scene scene, const MeasureRequest& request, const MeasureHooks& hooks = {});

// `luxplan measure --json`'s object.
nlohmann::json measureJson(const MeasureOutcome& outcome);

// The daylight at one instant (ISO 8601) instead of the period's average: a weather
// file's hour that contains it. Throws std::runtime_error ("--at ...").
DaylightParams daylightAt(const Scene& scene, const std::string& at);

// The warnings `measure` and `optimize` say before they trace (a line each; empty: none).
// Fewer than 2 paths per point (from --paths if `fromOption`, else setting `key`:
// report_paths_per_point for measure, paths_per_point for optimize's search, named as
// --set gave it or at its JSON path in the scene file) leave the samplers without a
// standard error.
std::string fewPathsWarning(const Scene& scene, int paths, bool fromOption, const std::string& key);
// A large measurement (optimizer/progress_line.h's largeMeasurementWarning), naming the scene file.
std::string largeMeasurementNote(const Scene& scene, int pathsPerPoint, const std::string& what);
// The points of the scene's samplers, all of them (a covered point counts too).
long long samplerPoints(const Scene& scene);

}  // namespace luxplan::api
