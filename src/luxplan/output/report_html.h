// report.html: one self-contained page (inline CSS, the pictures embedded as data:
// URIs; no network: only its 3D view's scripts are files, copied next to it,
// report_viewer.h) that a client can be shown. Results first: the goals sentence, per
// task area (planar sampler) Em, Emin and U0, the glare samplers and the rest, each
// against its target with pass / at bound (within noise) / fail, and C, L and G in a
// sentence each; then the pictures, the room in 3D (on screen only), the daylight hour
// by hour and the scene. An appendix holds the engineer's tables: the search, samplers
// with their light budgets and why they miss, statistics and glare detail,
// constraints, overlap pairs, move statistics and timings. A print stylesheet lays it
// out on A4 (report.pdf, report_pdf.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/lightsamplers/light_budget.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/optimizer/optimizer.h>

namespace luxplan {

struct ReportTiming {
    std::string what;
    double seconds = 0;
};

// What the page shows besides the optimizer result (all optional).
struct ReportData {
    std::string title;        // empty: "luxplan: " + the scene's name
    std::string layoutLabel;  // which layout the tables describe, e.g. "optimized" or a file name
    // Sampler measurements for that layout, in Scene::samplers order; empty: the
    // optimizer result's best evaluation (if any).
    std::vector<SamplerResult> samplers;
    // Constraint terms for that layout (GeometryEvaluator::evaluate with breakdown);
    // absent: the optimizer result's bestGeometry (if any).
    std::optional<GeometryResult> geometry;
    std::vector<ReportTiming> timings;
    // Per sampler (Scene::samplers order), where its light comes from; empty: not shown.
    std::vector<SamplerBudget> budgets;
    // Why the page has no 3D view, when it has none (e.g. the viewer's files are missing).
    std::string viewerNote;
    // The daylight period hour by hour: each instant's sampler measurements (Scene::samplers
    // order) for the layout shown; empty: not shown.
    struct Hour {
        std::string at;  // ISO 8601
        std::vector<SamplerResult> samplers;
    };
    std::vector<Hour> hours;
};

// What a sampler that misses its target could do, from where its light comes from:
// "below its target; 78% of its light is daylight (sun 61%, sky 17%): nearer the
// window, or more light from a luminaire". "" when `value` is in [targetMin, targetMax].
std::string missAdvice(const Scene& scene, const LightSamplerSpec& sampler, double value, const SamplerBudget& budget);

// The pictures and files the page refers to, relative to its folder, in page order;
// the page links each one only if it exists in the folder when the page is written.
inline constexpr const char* kReportImages[] = {"plan.png", "plan_initial_vs_optimized.png", "render.png", "render_luminance.png",
                                               "convergence.png", "annual_plan.png"};
// ... and after them each sampler's temporal map of the year (output/annual_plan.h),
// temporal_map_<sampler>.png, in name order.
inline constexpr const char* kReportFiles[] = {"scene.glb", "layout.json", "report.json", "trace.csv"};

// Text with &, <, >, " and ' replaced by character references.
std::string escapeHtml(const std::string& text);

// The page's HTML for `folder` (which files exist there decides what it links).
// `result` may be null (a layout measured without optimizing).
std::string reportHtml(const std::filesystem::path& folder, const Scene& scene, const OptimizerResult* result,
                       const ReportData& data = {});

// Writes folder/report.html (write it after the pictures). Throws IoError.
void writeReportHtml(const std::filesystem::path& folder, const Scene& scene, const OptimizerResult* result,
                     const ReportData& data = {});

}  // namespace luxplan
