#include <luxplan/api/optimize.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include <luxplan/api/measure.h>
#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/settings_table.h>
#include <luxplan/optimizer/report.h>

namespace luxplan::api {
namespace {

// optimize's default light roulette floor in the search (the setting light_roulette).
constexpr double kSearchLightRoulette = 0.2;

// The path-traced lighting term (null without samplers): the search's measurements
// at `measure`'s paths, the report's and the selection's at theirs.
std::unique_ptr<PathTracedLighting> makeLighting(const Scene& scene, const DaylightEnvironment* daylight,
                                                 const TracingSettings& tracingSettings, const MeasureOptions& measure,
                                                 int reportPaths, int selectionPaths) {
    if (scene.samplers.empty()) return nullptr;
    PathTracerOptions search, report;
    search.sunPatches = tracingSettings.samplesSunPatches(SunPatchUse::Report, true);
    report.sunPatches = tracingSettings.samplesSunPatches(SunPatchUse::Report, false);
    search.exteriorSun = report.exteriorSun = tracingSettings.exteriorSun;
    auto lighting = std::make_unique<PathTracedLighting>(scene, daylight, measure, search, report);
    lighting->setReportPaths(reportPaths);        // the result's report and the suggestions'
    lighting->setSelectionPaths(selectionPaths);  // confirmations and the candidates' re-measures
    lighting->setIncremental(!tracingSettings.fullEvaluation);
    lighting->setCheckCache(tracingSettings.checkCache);
    lighting->setFreshNoise(tracingSettings.freshNoise);
    lighting->setLightRoulette(*tracingSettings.lightRoulette);
    return lighting;
}

// snapshots.json (the setting snapshots): the best layout at each checkpoint of the run,
// in the scene the search ran on (the flattened one in a flat run: measure with flat
// true reads it).
void writeSnapshots(const std::filesystem::path& file, const Scene& scene, const OptimizerResult& result) {
    nlohmann::json list = nlohmann::json::array();
    for (const Snapshot& s : result.snapshots)
        list.push_back({{"iteration", s.iteration},
                        {"seconds", s.seconds},
                        {"lighting_evaluations", s.lightingEvaluations},
                        {"search_C", std::isfinite(s.searchCost) ? nlohmann::json(s.searchCost) : nlohmann::json(nullptr)},
                        {"feasible", s.feasible},
                        {"layout", nlohmann::json::parse(io::layoutToJson(scene, s.best))}});
    nlohmann::json j = {{"scene", scene.name}, {"seed", result.options.seed}, {"flat", result.options.hierarchy == Hierarchy::Flat},
                        {"iterations", result.iterations}, {"snapshots", list}};
    writeFileAtomically(file, j.dump(1) + "\n");
}

}  // namespace

OptimizerSettings runSettings(const OptimizeRequest& request, const OptimizerSettings& scene) {
    OptimizerSettings s = scene;
    if (request.iterations >= 0) s.iterations = request.iterations;
    if (request.seed) s.seed = *request.seed;
    if (request.suggestions > 0) s.suggestions = request.suggestions;
    if (request.paths > 0) s.pathsPerPoint = s.searchPathsPerPoint = request.paths;
    s.reportPathsPerPoint = std::max(s.reportPathsPerPoint, s.searchPathsPerPoint);
    s.selectionPathsPerPoint = std::max(s.selectionPathsPerPoint, s.searchPathsPerPoint);
    s.sunPatches = s.sunPatches.value_or(SunPatchUse::Report);
    s.lightRoulette = s.lightRoulette.value_or(kSearchLightRoulette);
    return s;
}

void checkOutputFolder(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError(folder.string() + ": cannot create the output folder (" + ec.message() + ")");
    const std::filesystem::path probe = folder / ".luxplan-write-check";
    writeFileAtomically(probe, "");
    std::filesystem::remove(probe, ec);
}

std::unique_ptr<OptimizeRun> optimize(Scene original, const OptimizeRequest& request, const OptimizeHooks& hooks) {
    auto say = [](const std::function<void(const std::string&)>& to, const std::string& line) {
        if (to && !line.empty()) to(line);
    };
    auto run = std::make_unique<OptimizeRun>();
    run->original = std::move(original);
    run->settings = runSettings(request, run->original.optimizer);
    const Scene& scene0 = run->original;
    const OptimizerSettings& settings = run->settings;
    const TracingSettings& tracingSettings = settings;
    // Before the daylight's bake: each layout's measurement and the report's.
    say(hooks.warning, largeMeasurementNote(scene0, settings.searchPathsPerPoint, "the search measures each layout at"));
    say(hooks.warning, largeMeasurementNote(scene0, settings.reportPathsPerPoint, "the report measures the final layout at"));
    if (scene0.daylight)
        run->daylight = hooks.bake ? hooks.bake(*scene0.daylight, scene0.site) : buildDaylight(*scene0.daylight, scene0.site);

    OptimizerOptions options = optimizerOptions(settings);
    // Flat: the same furniture without groups, kept together by cohesion constraints.
    if (options.hierarchy == Hierarchy::Flat) {
        run->flattened = flattenScene(scene0);
        say(hooks.note, "flat: " + std::to_string(run->flattened->scene.entities.size()) + " objects without groups, " +
                            std::to_string(run->flattened->cohesionConstraints) + " cohesion constraints");
    }
    const Scene& scene = run->scene();
    if (!request.startFile.empty() || request.startText) {
        // The designer's own layout (the reader names the file and entry of any error:
        // an unknown or fixed entity, a pose outside its regions).
        const Layout given = request.startText ? io::readLayoutText(*request.startText, "start", scene0)
                                               : io::readLayout(request.startFile, scene0);
        options.start = StartFrom::Given;
        options.startLayout = run->flattened ? flatLayoutOf(scene0, *run->flattened, given) : given;
    }

    MeasureOptions measure;
    measure.pathsPerPoint = settings.searchPathsPerPoint;
    say(hooks.warning, fewPathsWarning(scene0, measure.pathsPerPoint, request.paths > 0, "paths_per_point"));
    measure.seed = options.seed;
    measure.adaptive = !tracingSettings.fixedPaths;
    measure.lowDiscrepancy = tracingSettings.lowDiscrepancy;
    measure.choiceError = false;  // the search's stops do not read it; its report's measurements do
    // The report's count for the result (measure's default: report.json and `measure
    // --layout --seed` give one number); the selection's, far fewer, for the confirmations
    // and the candidates' re-measures (issue 58). Neither below the search's.
    run->lighting = makeLighting(scene, run->daylight ? &*run->daylight : nullptr, tracingSettings, measure,
                                 settings.reportPathsPerPoint, settings.selectionPathsPerPoint);

    // With lighting weight 0 the chain never calls it, but the result's report does.
    Optimizer optimizer(scene, options, run->lighting.get());
    optimizer.initialize({hooks.drawing, hooks.planning}, hooks.cancel);
    run->start = optimizer.current();  // the comparison picture's left side
    if (hooks.started) hooks.started(optimizer);
    run->result = optimizer.run(hooks.progress, hooks.cancel);
    return run;
}

std::string reportText(const OptimizeRun& run) { return reportJson(run.scene(), run.result, io::settingsJson(run.settings)); }

std::string layoutText(const OptimizeRun& run) {
    return run.flattened ? io::layoutToJson(run.original, hierarchicalLayoutOf(run.original, *run.flattened, run.result.best))
                         : io::layoutToJson(run.scene(), run.result.best);
}

void writeOutputs(const OptimizeRun& run, const std::filesystem::path& out) {
    const Scene& scene = run.scene();
    const OptimizerResult& result = run.result;
    writeOptimizerOutputs(out, scene, result, io::settingsJson(run.settings));
    if (!result.snapshots.empty()) writeSnapshots(out / "snapshots.json", scene, result);
    // layout.json (and the suggestions) in the scene file's hierarchy, so that --layout
    // reads them back; in a flat run layout_flat.json keeps every object's own placement
    // (measure --set flat=true).
    if (run.flattened) {
        io::writeLayout(out / "layout_flat.json", scene, result.best);
        io::writeLayout(out / "layout.json", run.original, hierarchicalLayoutOf(run.original, *run.flattened, result.best));
    } else {
        io::writeLayout(out / "layout.json", scene, result.best);
    }
    if (!result.suggestions.empty()) std::filesystem::create_directories(out / "suggestions");
    for (size_t i = 0; i < result.suggestions.size(); ++i) {
        const Layout& layout = result.suggestions[i].layout;
        const std::filesystem::path file = out / suggestionFile(i);
        if (run.flattened) io::writeLayout(file, run.original, hierarchicalLayoutOf(run.original, *run.flattened, layout));
        else io::writeLayout(file, scene, layout);
    }
}

RunOutputs writePictures(const OptimizeRun& run, const std::filesystem::path& folder, int spp, bool pdf,
                         const std::atomic<bool>* cancel, const std::function<std::shared_ptr<void>(OutputOptions&)>& watch) {
    const OptimizerSettings& settings = run.settings;
    OutputOptions pictures;
    pictures.seed = run.result.options.seed;
    pictures.samplerPaths = settings.reportPathsPerPoint;  // the start's too, as the result's
    pictures.tracing.sunPatches = settings.samplesSunPatches(SunPatchUse::Report, false);
    pictures.tracing.exteriorSun = settings.exteriorSun;
    pictures.initialLabel = "start";
    pictures.cancel = cancel;
    if (spp > 0) pictures.renderSamplesPerPixel = spp;
    pictures.pdf = pdf;
    const std::shared_ptr<void> watching = watch ? watch(pictures) : nullptr;
    return writeRunOutputs(folder, run.scene(), run.start, run.result.best, &run.result,
                           run.daylight ? &*run.daylight : nullptr, pictures);
}

}  // namespace luxplan::api
