// `optimize` as a library call: the search, report.json's and layout.json's content and
// the run's files, for the CLI and the Python module alike, so that both give the same
// layout and report for the same seed. The CLI keeps its progress line, its summary on
// stdout and its signals, which plug in through OptimizeHooks.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <luxplan/daylight/daylight.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include <luxplan/output/outputs.h>
#include <luxplan/scene/settings.h>

namespace luxplan::api {

struct OptimizeRequest {
    int iterations = -1;     // -1: optimizer.iterations
    int paths = 0;           // the search's per point; 0: optimizer.paths_per_point
    int suggestions = 0;     // 0: optimizer.suggestions
    std::optional<uint64_t> seed;
    std::string startFile;                  // a layout to start from instead of a uniform draw
    std::optional<std::string> startText;   // ... or its text (named "start" in errors)
};

// The settings the run uses: the scene's (--set over them), then the request's, the
// report's and the selection's counts not below the search's, and the optional ones at
// optimize's defaults (report.json's "settings").
OptimizerSettings runSettings(const OptimizeRequest& request, const OptimizerSettings& scene);

// Fails now, not after the search, when the output folder cannot take files.
void checkOutputFolder(const std::filesystem::path& folder);

// Where a run tells what it does; each may be empty.
struct OptimizeHooks {
    std::function<void(const std::string&)> warning;  // a line for stderr, without its newline
    std::function<void(const std::string&)> note;     // a line for stderr that a quiet run leaves out
    std::function<DaylightEnvironment(const DaylightParams&, const Site&)> bake;  // default: buildDaylight
    std::function<void(int drawn, int most)> drawing;  // the start's draws while none passes the rules
    std::function<void(int looked, int plans, double lowestC)> planning;  // the planned start's plans (StartProgress)
    std::function<void(const Optimizer&)> started;     // the start drawn, before the first iteration
    ProgressCallback progress;
    const std::atomic<bool>* cancel = nullptr;  // once true, the search stops with its best so far
};

// A run and what its outputs need.
struct OptimizeRun {
    Scene original;                      // as loaded
    OptimizerSettings settings;          // runSettings'
    std::optional<FlatScene> flattened;  // a flat run's scene
    std::optional<DaylightEnvironment> daylight;
    std::unique_ptr<PathTracedLighting> lighting;  // null without samplers
    Layout start;                        // the start layout (the comparison's left side)
    OptimizerResult result;
    const Scene& scene() const { return flattened ? flattened->scene : original; }  // the one searched
};

// The search (the start drawn or given, the chain, the candidates' re-measures and the
// report's measurement). Throws SceneError, IoError or std::runtime_error.
std::unique_ptr<OptimizeRun> optimize(Scene original, const OptimizeRequest& request, const OptimizeHooks& hooks = {});

std::string reportText(const OptimizeRun& run);  // report.json's content
std::string layoutText(const OptimizeRun& run);  // layout.json's: in the scene file's hierarchy

// layout.json, report.json, trace.csv and, as the run asks, layout_flat.json,
// snapshots.json and suggestions/ in `folder`, each atomically.
void writeOutputs(const OptimizeRun& run, const std::filesystem::path& folder);

// The pictures, scene.glb, report.html and report.pdf of the result (writeRunOutputs):
// `spp` samples per pixel (0: the default), `pdf` whether to print report.pdf; `watch`,
// if given, is called with the options before they are made and what it returns lives
// while they are (a progress display).
RunOutputs writePictures(const OptimizeRun& run, const std::filesystem::path& folder, int spp, bool pdf,
                         const std::atomic<bool>* cancel,
                         const std::function<std::shared_ptr<void>(OutputOptions&)>& watch = {});

}  // namespace luxplan::api
