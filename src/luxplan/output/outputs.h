// Everything a run leaves besides layout.json/report.json/trace.csv: the plan, the
// start-vs-result plan comparison, a path-traced view, the convergence plot,
// scene.glb, report.html and report.pdf, written into one folder.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/daylight/environment.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/output/render.h>
#include <luxplan/output/report_html.h>

namespace luxplan {

// Which outputs to write and how much light transport they may spend. The defaults
// keep the office demo's pictures to a few seconds on two cores.
struct OutputOptions {
    bool plan = true;         // plan.png: work-plane illuminance, samplers by target status
    bool comparison = true;   // plan_initial_vs_optimized.png (only when the layouts differ)
    bool render = true;       // render.png
    bool luminanceView = true;  // render_luminance.png, the same view in false colour (with render)
    bool convergence = true;  // convergence.png (only with an optimizer result)
    bool glb = true;          // scene.glb
    bool html = true;         // report.html (written last; links what exists)
    bool viewer = true;       // report.html's 3D view: three.js copied into viewer/ (report_viewer.h)
    // report.pdf: report.html printed by headless Chromium (report_pdf.h), with report.html.
    // Without a browser (said once per process through onStep) or when it fails, none.
    bool pdf = true;
    double pdfTimeoutSeconds = 180;
    int budgetPaths = 32;     // per sampler item, for report.html's light budgets; 0: none
    // report.html's daylight hour by hour: each whole hour of a daylight period (at
    // most 48), its samplers measured at hourlyPaths per point; 0: none.
    int hourlyPaths = 64;
    int renderWidth = 660, renderHeight = 440, renderSamplesPerPixel = 8;
    std::optional<Camera> camera;   // render.png's view; unset: defaultCamera(scene)
    bool renderDenoise = true;      // edge-avoiding filter on render.png (denoise.h)
    double cellSize = 0.25;         // work-plane grid cell (m)
    int cellPaths = 32;             // illuminance samples per cell
    double workPlaneHeight = 0.8;   // m above the floor
    int samplerPaths = 256;         // per sampler point, where a layout's samplers must be measured
    uint64_t seed = 1;
    PathTracerOptions tracing;      // every path traced for the outputs
    std::string title;              // report.html's title; empty: "luxplan: <scene name>"
    std::string initialLabel = "initial", finalLabel = "optimized";
    // Once true (a stop signal), the steps not yet begun are skipped.
    const std::atomic<bool>* cancel = nullptr;
    // Progress, if set: told what each long step is as it begins, and render.png's rows
    // counted as they are traced.
    std::function<void(const std::string&)> onStep;
    std::atomic<int>* renderRowsDone = nullptr;
};

struct RunOutputs {
    std::vector<std::filesystem::path> files;  // written, in order
    std::vector<ReportTiming> timings;         // per step
    bool cancelled = false;                    // OutputOptions::cancel stopped it early
    std::vector<SamplerResult> samplers;       // the final layout's sampler values shown
    std::string pdfNote;                       // why report.pdf was not written ("" when it was, or not asked for)
    double seconds = 0;
};

// Writes the outputs for `finalLayout` into `folder` (created). `initialLayout` is the
// layout the run started from (the comparison's left side). `result` may be null (a
// layout that was not optimized): the samplers are then measured with
// options.samplerPaths and the constraints evaluated here. The final layout's sampler
// values come from `result` when its lighting was evaluated. `daylight` may be null
// (night). Throws IoError when a file cannot be written.
RunOutputs writeRunOutputs(const std::filesystem::path& folder, const Scene& scene, const Layout& initialLayout,
                           const Layout& finalLayout, const OptimizerResult* result,
                           const DaylightEnvironment* daylight, const OutputOptions& options = {});

}  // namespace luxplan
