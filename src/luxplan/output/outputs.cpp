// A run's pictures, scene.glb and report.html: one ray-tracing scene, measured for
// the final layout first, then (for the comparison) for the initial one.
#include <luxplan/output/outputs.h>

#include <chrono>

#include <luxplan/annual/scene_year.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/lightsamplers/light_budget.h>
#include <luxplan/core/error.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/output/annual_plan.h>
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

// The steps of one call: their timings, the files written, the progress said, and
// whether a stop signal (OutputOptions::cancel) skips every step not yet begun.
class RunSteps {
public:
    explicit RunSteps(const OutputOptions& options) : options_(options) {}
    RunOutputs out;

    void begin(const std::string& step) const {
        if (options_.onStep) options_.onStep(step);
    }
    // The time since the last step's end, as `what`'s.
    void timed(const std::string& what) {
        auto now = Clock::now();
        out.timings.push_back({what, std::chrono::duration<double>(now - lap_).count()});
        lap_ = now;
    }
    void wrote(const std::filesystem::path& file) { out.files.push_back(file); }
    // What is written stays.
    bool stopped() { return out.cancelled = out.cancelled || (options_.cancel && options_.cancel->load()); }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    RunOutputs finish() {
        out.seconds = seconds();
        return out;
    }

private:
    const OutputOptions& options_;
    Clock::time_point start_ = Clock::now(), lap_ = start_;
};

// The daylight period measured hour by hour (at most 48 instants), for report.html.
std::vector<ReportData::Hour> measureHours(const Scene& scene, const EmbreeScene& rt, const MeasureOptions& measure,
                                           const OutputOptions& options, RunSteps& steps) {
    std::vector<ReportData::Hour> hours;
    steps.begin("measuring the daylight period hour by hour");
    MeasureOptions hourly = measure;
    hourly.pathsPerPoint = options.hourlyPaths;
    const DateTime from = *scene.daylight->from, to = *scene.daylight->to;
    const double span = (to.julianDayUT() - from.julianDayUT()) * 24 * 60;
    for (double minutes = 0; minutes <= span + 1e-6 && hours.size() < 48 && !steps.stopped(); minutes += 60) {
        DaylightParams instant = *scene.daylight;
        instant.from = from.plusMinutes(minutes);
        instant.to.reset();
        const DaylightEnvironment environment = buildDaylight(instant, scene.site);
        PathTracer at(rt, &environment, options.tracing);
        hours.push_back({instant.from->str(), measureSamplers(at, hourly).samplers});
    }
    steps.timed("hour by hour");
    return hours;
}

// render.png (and render_luminance.png); false when a stop signal came mid-render.
bool writeRender(const std::filesystem::path& folder, const Scene& scene, const PathTracer& tracer,
                 const OutputOptions& options, RunSteps& steps) {
    steps.begin("rendering " + std::to_string(options.renderWidth) + " x " + std::to_string(options.renderHeight) + " px at " +
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
    if (steps.stopped()) return false;  // rows after the signal were not traced
    writePng(toneMap(view, autoExposure(view)), folder / "render.png");
    steps.wrote(folder / "render.png");
    if (options.luminanceView) {
        writePng(falseColorView(view, luminanceFalseColor(view)), folder / "render_luminance.png");
        steps.wrote(folder / "render_luminance.png");
    }
    steps.timed("render.png");
    return true;
}

// plan.png and the comparison's plans, on one colour scale (centred on the targets) so
// that the two sides compare.
void writePlans(const std::filesystem::path& folder, const Scene& scene, const Layout& initialLayout,
                const Layout& finalLayout, const PlanData& initialData, const PlanData& finalData, bool compare,
                const OutputOptions& options, RunSteps& steps) {
    PlanOptions plan;
    if (finalData.workPlane) {
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
        steps.wrote(folder / "plan.png");
    }
    if (compare) {
        Image before = renderPlan(scene, initialLayout, plan, initialData);
        Image after = renderPlan(scene, finalLayout, plan, finalData);
        writePng(sideBySide(before, after, options.initialLabel, options.finalLabel),
                 folder / "plan_initial_vs_optimized.png");
        steps.wrote(folder / "plan_initial_vs_optimized.png");
    }
    if (options.plan || compare) steps.timed("plans");
}

// report.html (its 3D view's scripts beside it) and, where asked, report.pdf.
void writeHtmlReport(const std::filesystem::path& folder, const Scene& scene, const Layout& finalLayout,
                     const OptimizerResult* result, ReportData data, const OutputOptions& options, RunSteps& steps) {
    data.title = options.title;
    data.layoutLabel = options.finalLabel;
    data.samplers = steps.out.samplers;
    if (!result || !sameLayout(finalLayout, result->best)) {
        GeometryEvaluator geometry(scene);
        data.geometry = geometry.evaluate(worldTransforms(scene, finalLayout), true);
    }
    data.timings = steps.out.timings;
    if (options.viewer) {
        if (!std::filesystem::is_regular_file(folder / "scene.glb")) data.viewerNote = "scene.glb was not written.";
        else data.viewerNote = copyViewerScripts(folder);
        if (!data.viewerNote.empty() && options.onStep) options.onStep("no 3D view in report.html: " + data.viewerNote);
        else if (data.viewerNote.empty()) for (const char* script : kViewerScripts) steps.wrote(folder / script);
    }
    data.timings.push_back({"pictures and scene.glb, total", steps.seconds()});
    writeReportHtml(folder, scene, result, data);
    steps.wrote(folder / "report.html");
    steps.timed("report.html");
    // A report.pdf of an earlier run would describe another page.
    std::error_code stale;
    std::filesystem::remove(folder / "report.pdf", stale);
    if (!options.pdf || steps.stopped()) return;
    steps.begin("printing report.pdf (headless Chromium)");
    steps.out.pdfNote = writeReportPdf(folder, options.pdfTimeoutSeconds, options.cancel);
    if (steps.out.pdfNote.empty()) {
        steps.wrote(folder / "report.pdf");
        steps.timed("report.pdf");
    } else if (options.onStep) {
        // A missing browser is said once per process; a failure every time.
        static std::atomic<bool> saidNoBrowser{false};
        if (!pdfBrowser().empty() || !saidNoBrowser.exchange(true))
            options.onStep("warning: report.pdf not written: " + steps.out.pdfNote);
    }
}

}  // namespace

RunOutputs writeRunOutputs(const std::filesystem::path& folder, const Scene& scene, const Layout& initialLayout,
                           const Layout& finalLayout, const OptimizerResult* result,
                           const DaylightEnvironment* daylight, const OutputOptions& options) {
    RunSteps steps(options);
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError("cannot create " + folder.string() + ": " + ec.message());
    RunOutputs& out = steps.out;

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

    // A scene with annual goals: its year, whose shares in range the goals' terms read
    // and whose pictures show the final layout's year.
    const std::vector<size_t> annualGoals = annualGoalSamplers(scene);
    std::optional<DaylightCoefficients> year;
    if (!annualGoals.empty()) year.emplace(sceneYear(scene));
    auto measureAnnualGoals = [&](std::vector<SamplerResult>& results) {
        if (year) setAnnualInRange(scene, measureYearAt(*year, rt, annualGoals, options.samplerPaths, options.seed), results);
    };

    // The final layout: samplers, work plane, view, glTF.
    PlanData finalData, initialData;
    if (fromResult) {
        out.samplers = result->bestEvaluation.samplers.samplers;
    } else if (!scene.samplers.empty() && (options.plan || compare || options.html)) {
        steps.begin("measuring " + std::to_string(scene.samplers.size()) + " samplers at " +
                    std::to_string(options.samplerPaths) + " paths per point");
        out.samplers = measureSamplers(tracer, measure).samplers;
        measureAnnualGoals(out.samplers);
    }
    if (year && options.plan && !steps.stopped()) {
        steps.begin("measuring the year's " + std::to_string(year->hours().size()) + " hours (daylight coefficients)");
        std::vector<size_t> all(scene.samplers.size());
        for (size_t k = 0; k < all.size(); ++k) all[k] = k;
        for (const std::filesystem::path& f :
             writeAnnualPictures(folder, scene, finalLayout, measureYearAt(*year, rt, all, options.samplerPaths, options.seed)))
            steps.wrote(f);
        steps.timed("the year's pictures");
    }
    if (!scene.samplers.empty()) finalData.samplers = out.samplers;
    if (!fromResult && !scene.samplers.empty()) steps.timed("samplers (" + options.finalLabel + ")");
    ReportData report;
    if (options.html && !scene.samplers.empty() && options.budgetPaths > 0 && !steps.stopped()) {
        steps.begin("tracing the samplers' light budgets");
        report.budgets = measureLightBudgets(tracer, options.budgetPaths, options.seed);
        steps.timed("light budgets");
    }
    if (options.html && !scene.samplers.empty() && options.hourlyPaths > 0 && scene.daylight && scene.daylight->from &&
        scene.daylight->to && !steps.stopped())
        report.hours = measureHours(scene, rt, measure, options, steps);
    if (steps.stopped()) return steps.finish();
    if (grids) {
        steps.begin("measuring the work plane");
        finalData.workPlane = workPlane();
        steps.timed("work plane (" + options.finalLabel + ")");
    }
    if (steps.stopped()) return steps.finish();
    if (options.render && !writeRender(folder, scene, tracer, options, steps)) return steps.finish();
    if (steps.stopped()) return steps.finish();
    if (options.glb) {
        writeGlb(folder / "scene.glb", scene, finalLayout, daylight);
        steps.wrote(folder / "scene.glb");
        steps.timed("scene.glb");
    }

    // The initial layout, for the comparison.
    if (steps.stopped()) return steps.finish();
    if (compare) {
        steps.begin("measuring the " + options.initialLabel + " layout for the comparison");
        rt.setLayout(initialLayout);
        tracer.updateLayout();
        if (!scene.samplers.empty()) {
            initialData.samplers = measureSamplers(tracer, measure).samplers;
            measureAnnualGoals(*initialData.samplers);
        }
        if (grids) initialData.workPlane = workPlane();
        steps.timed("samplers and work plane (" + options.initialLabel + ")");
    }

    if (steps.stopped()) return steps.finish();
    writePlans(folder, scene, initialLayout, finalLayout, initialData, finalData, compare, options, steps);
    if (options.convergence && result && !result->trace.empty()) {
        writePng(plotConvergence(result->trace), folder / "convergence.png");
        steps.wrote(folder / "convergence.png");
        steps.timed("convergence.png");
    }

    if (steps.stopped()) return steps.finish();
    if (options.html) writeHtmlReport(folder, scene, finalLayout, result, std::move(report), options, steps);
    return steps.finish();
}

}  // namespace luxplan
