// A run's pictures, scene.glb and report.html: one ray-tracing scene, measured for
// the final layout first, then (for the comparison) for the initial one.
#include <luxplan/output/outputs.h>

#include <chrono>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/lightsamplers/light_budget.h>
#include <luxplan/core/error.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/output/gltf_export.h>
#include <luxplan/output/plan.h>
#include <luxplan/output/plot.h>
#include <luxplan/output/report_pdf.h>
#include <luxplan/output/render.h>
#include <luxplan/output/report_viewer.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {
namespace {

using Clock = std::chrono::steady_clock;

bool sameLayout(const Layout& a, const Layout& b) {
    if (a.placements.size() != b.placements.size()) return false;
    for (size_t i = 0; i < a.placements.size(); ++i) {
        const Placement &p = a.placements[i], &q = b.placements[i];
        if (p.region != q.region || p.position != q.position || p.rotationDeg != q.rotationDeg) return false;
    }
    return true;
}

}  // namespace

RunOutputs writeRunOutputs(const std::filesystem::path& folder, const Scene& scene, const Layout& initialLayout,
                           const Layout& finalLayout, const OptimizerResult* result,
                           const DaylightEnvironment* daylight, const OutputOptions& options) {
    auto start = Clock::now();
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError("cannot create " + folder.string() + ": " + ec.message());

    RunOutputs out;
    auto lap = Clock::now();
    auto timed = [&](const std::string& what) {
        auto now = Clock::now();
        out.timings.push_back({what, std::chrono::duration<double>(now - lap).count()});
        lap = now;
    };
    auto wrote = [&](const std::filesystem::path& file) { out.files.push_back(file); };
    auto begin = [&](const std::string& step) {
        if (options.onStep) options.onStep(step);
    };
    // A stop signal (options.cancel) skips every step not yet begun; what is written stays.
    auto stopped = [&] { return out.cancelled = out.cancelled || (options.cancel && options.cancel->load()); };
    auto finish = [&] {
        out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return out;
    };

    bool fromResult = result && result->bestEvaluation.lightingEvaluated && sameLayout(finalLayout, result->best);
    bool compare = options.comparison && !sameLayout(initialLayout, finalLayout);
    const RoomShell* room = scene.room();
    bool grids = room && (options.plan || compare);

    EmbreeScene rt(scene, finalLayout);
    PathTracer tracer(rt, daylight, options.tracing);
    MeasureOptions measure;
    measure.pathsPerPoint = options.samplerPaths;
    measure.seed = options.seed;
    auto workPlane = [&] {
        return measureWorkPlane(tracer, room->box, options.workPlaneHeight, options.cellSize,
                                options.cellPaths, options.seed);
    };

    // The final layout: samplers, work plane, view, glTF.
    PlanData finalData, initialData;
    if (fromResult) {
        out.samplers = result->bestEvaluation.samplers.samplers;
    } else if (!scene.samplers.empty() && (options.plan || compare || options.html)) {
        begin("measuring " + std::to_string(scene.samplers.size()) + " samplers at " + std::to_string(options.samplerPaths) +
              " paths per point");
        out.samplers = measureSamplers(tracer, measure).samplers;
    }
    if (!scene.samplers.empty()) finalData.samplers = out.samplers;
    if (!fromResult && !scene.samplers.empty()) timed("samplers (" + options.finalLabel + ")");
    std::vector<SamplerBudget> budgets;
    if (options.html && !scene.samplers.empty() && options.budgetPaths > 0 && !stopped()) {
        begin("tracing the samplers' light budgets");
        budgets = measureLightBudgets(tracer, options.budgetPaths, options.seed);
        timed("light budgets");
    }
    std::vector<ReportData::Hour> hours;
    if (options.html && !scene.samplers.empty() && options.hourlyPaths > 0 && scene.daylight && scene.daylight->from &&
        scene.daylight->to && !stopped()) {
        begin("measuring the daylight period hour by hour");
        MeasureOptions hourly = measure;
        hourly.pathsPerPoint = options.hourlyPaths;
        const DateTime from = *scene.daylight->from, to = *scene.daylight->to;
        const double span = (to.julianDayUT() - from.julianDayUT()) * 24 * 60;
        for (double minutes = 0; minutes <= span + 1e-6 && hours.size() < 48 && !stopped(); minutes += 60) {
            DaylightParams instant = *scene.daylight;
            instant.from = from.plusMinutes(minutes);
            instant.to.reset();
            const DaylightEnvironment environment = buildDaylight(instant, scene.site);
            PathTracer at(rt, &environment, options.tracing);
            hours.push_back({instant.from->str(), measureSamplers(at, hourly).samplers});
        }
        timed("hour by hour");
    }
    if (stopped()) return finish();
    if (grids) {
        begin("measuring the work plane");
        finalData.workPlane = workPlane();
        timed("work plane (" + options.finalLabel + ")");
    }
    if (stopped()) return finish();
    if (options.render) {
        begin("rendering " + std::to_string(options.renderWidth) + " x " + std::to_string(options.renderHeight) + " px at " +
              std::to_string(options.renderSamplesPerPixel) + (options.renderSamplesPerPixel == 1 ? " sample" : " samples") +
              " per pixel");
        RenderOptions ro;
        ro.width = options.renderWidth;
        ro.height = options.renderHeight;
        ro.samplesPerPixel = options.renderSamplesPerPixel;
        ro.denoise = options.renderDenoise;
        ro.seed = options.seed;
        ro.cancel = options.cancel;
        ro.rowsDone = options.renderRowsDone;
        LuminanceImage view = renderView(tracer, options.camera.value_or(defaultCamera(scene)), ro);
        if (stopped()) return finish();  // rows after the signal were not traced
        writePng(toneMap(view, autoExposure(view)), folder / "render.png");
        wrote(folder / "render.png");
        if (options.luminanceView) {
            writePng(falseColorView(view, luminanceFalseColor(view)), folder / "render_luminance.png");
            wrote(folder / "render_luminance.png");
        }
        timed("render.png");
    }
    if (stopped()) return finish();
    if (options.glb) {
        writeGlb(folder / "scene.glb", scene, finalLayout, daylight);
        wrote(folder / "scene.glb");
        timed("scene.glb");
    }

    // The initial layout, for the comparison.
    if (stopped()) return finish();
    if (compare) {
        begin("measuring the " + options.initialLabel + " layout for the comparison");
        rt.setLayout(initialLayout);
        tracer.updateLayout();
        if (!scene.samplers.empty()) initialData.samplers = measureSamplers(tracer, measure).samplers;
        if (grids) initialData.workPlane = workPlane();
        timed("samplers and work plane (" + options.initialLabel + ")");
    }

    // Plans on one colour scale (centred on the targets), so that the two sides compare.
    if (stopped()) return finish();
    PlanOptions plan;
    if (grids) {
        std::vector<double> values = finalData.workPlane->values;
        if (initialData.workPlane) {
            const std::vector<double>& more = initialData.workPlane->values;
            values.insert(values.end(), more.begin(), more.end());
        }
        plan.colors = planFalseColor(scene, values);
    }
    if (options.plan) {
        PlanOptions titled = plan;
        titled.title = scene.name + ": " + options.finalLabel;
        writePng(renderPlan(scene, finalLayout, titled, finalData), folder / "plan.png");
        wrote(folder / "plan.png");
    }
    if (compare) {
        Image before = renderPlan(scene, initialLayout, plan, initialData);
        Image after = renderPlan(scene, finalLayout, plan, finalData);
        writePng(sideBySide(before, after, options.initialLabel, options.finalLabel),
                 folder / "plan_initial_vs_optimized.png");
        wrote(folder / "plan_initial_vs_optimized.png");
    }
    if (options.plan || compare) timed("plans");
    if (options.convergence && result && !result->trace.empty()) {
        writePng(plotConvergence(result->trace), folder / "convergence.png");
        wrote(folder / "convergence.png");
        timed("convergence.png");
    }

    if (stopped()) return finish();
    if (options.html) {
        ReportData data;
        data.title = options.title;
        data.layoutLabel = options.finalLabel;
        data.samplers = out.samplers;
        if (!result || !sameLayout(finalLayout, result->best)) {
            GeometryEvaluator geometry(scene);
            data.geometry = geometry.evaluate(worldTransforms(scene, finalLayout), true);
        }
        data.timings = out.timings;
        data.budgets = budgets;
        data.hours = hours;
        if (options.viewer) {
            if (!std::filesystem::is_regular_file(folder / "scene.glb")) data.viewerNote = "scene.glb was not written.";
            else data.viewerNote = copyViewerScripts(folder);
            if (!data.viewerNote.empty() && options.onStep) options.onStep("no 3D view in report.html: " + data.viewerNote);
            else if (data.viewerNote.empty()) for (const char* script : kViewerScripts) wrote(folder / script);
        }
        double total = std::chrono::duration<double>(Clock::now() - start).count();
        data.timings.push_back({"pictures and scene.glb, total", total});
        writeReportHtml(folder, scene, result, data);
        wrote(folder / "report.html");
        timed("report.html");
        // A report.pdf of an earlier run would describe another page.
        std::error_code stale;
        std::filesystem::remove(folder / "report.pdf", stale);
        if (options.pdf && !stopped()) {
            begin("printing report.pdf (headless Chromium)");
            out.pdfNote = writeReportPdf(folder, options.pdfTimeoutSeconds, options.cancel);
            if (out.pdfNote.empty()) {
                wrote(folder / "report.pdf");
                timed("report.pdf");
            } else if (options.onStep) {
                // A missing browser is said once per process; a failure every time.
                static std::atomic<bool> saidNoBrowser{false};
                if (!pdfBrowser().empty() || !saidNoBrowser.exchange(true))
                    options.onStep("warning: report.pdf not written: " + out.pdfNote);
            }
        }
    }
    return finish();
}

}  // namespace luxplan
