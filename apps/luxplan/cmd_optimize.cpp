// `luxplan optimize SCENE -o OUTDIR [--iterations N] [--seed S] [--threads T] [--set KEY=VALUE]`:
// the hierarchical Metropolis search with path-traced lighting; writes layout.json,
// report.json, trace.csv, then the pictures, scene.glb, report.html and report.pdf
// (unless --no-pictures; --no-pdf: no report.pdf). Ctrl-C stops the run and still
// writes the best layout. The search's and the tracing's settings come from the scene's
// "optimizer" object and --set (io/settings_table.h); hierarchy flat (or flat true) runs
// the paper's flat baseline on the flattened scene (optimizer/flatten.h).
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "daylight_progress.h"
#include "option_checks.h"
#include "shared_options.h"
#include "picture_progress.h"
#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/progress_line.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include <luxplan/optimizer/report.h>
#include <luxplan/output/outputs.h>

namespace luxplan::cli {
namespace {

// SIGINT (Ctrl-C), SIGTERM and SIGHUP stop the search; the best layout is written and
// the exit status is 128 + the signal, the shell's convention (130, 143, 129).
std::atomic<bool> interrupted{false};
std::atomic<int> stopSignal{0};
extern "C" void onInterrupt(int signal) {
    int none = 0;
    stopSignal.compare_exchange_strong(none, signal);  // the first one sets the exit status
    interrupted.store(true);
}
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Catches the stop signals for its lifetime.
class StopSignals {
public:
    StopSignals() {
        interrupted.store(false);
        stopSignal.store(0);
        for (size_t k = 0; k < std::size(kStopSignals); ++k) previous_[k] = std::signal(kStopSignals[k], onInterrupt);
    }
    ~StopSignals() {
        for (size_t k = 0; k < std::size(kStopSignals); ++k) std::signal(kStopSignals[k], previous_[k]);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    void (*previous_[std::size(kStopSignals)])(int) = {};
};

struct OptimizeArgs : SharedArgs {
    std::string out;
    int iterations = -1, spp = 0, suggestions = 0;
    std::string start;  // --start LAYOUT.json
    bool noPdf = false, noPictures = false;
};

// optimize's default light roulette floor in the search (the setting light_roulette).
constexpr double kSearchLightRoulette = 0.2;

// One status line, redrawn in place on a terminal, printed every few seconds
// otherwise; and once, the moment the first layout passes the rules (the cost then
// starts to include the light).
// `feasibleSeen`: whether a layout within every rule's limit has been seen (the start's).
void showProgress(const Progress& p, bool tty, bool& feasibleSeen) {
    static auto lastPrint = std::chrono::steady_clock::now() - std::chrono::hours(1);
    auto now = std::chrono::steady_clock::now();
    if (p.feasible && !feasibleSeen && p.iteration > 0) {
        feasibleSeen = true;
        std::cerr << (tty ? "\r\033[K" : "") << lightingStartsLine(p) << "\n";
    }
    feasibleSeen = feasibleSeen || p.feasible;
    bool done = p.iteration >= p.iterations;
    if (!tty && !done && now - lastPrint < std::chrono::seconds(5)) return;
    lastPrint = now;
    const int width = 20;
    int filled = p.iterations > 0 ? int(double(width) * p.iteration / p.iterations) : width;
    std::string line = tty ? "[" + std::string(size_t(filled), '#') + std::string(size_t(width - filled), '.') + "] " : "";
    line += progressLine(p);
    std::cerr << (tty ? "\r" : "") << line << (tty ? "\033[K" : "\n") << std::flush;
}

// Fails now, not after the search, when the output folder cannot take files.
void checkOutputFolder(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError(folder.string() + ": cannot create the output folder (" + ec.message() + ")");
    const std::filesystem::path probe = folder / ".luxplan-write-check";
    writeFileAtomically(probe, "");
    std::filesystem::remove(probe, ec);
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

// check_cache's verdict: every reused path traced again, and what differed.
void printCacheCheck(const Scene& scene, const CacheCheck& check) {
    if (check.differing == 0) {
        std::cout << "  path cache check: all " << check.checked
                  << " reused paths traced again from scratch gave the same numbers, bit for bit\n";
        return;
    }
    std::cerr << "warning: path cache check: " << check.differing << " of " << check.checked
              << " reused paths traced again from scratch differ (a ray meeting two entities' faces of different "
                 "materials in one plane, which the BVH of the moment decides: separate them by 0.1 mm; "
                 "docs/light-transport.md, \"What is left\"). The first (report.json, path_cache_check):\n";
    for (size_t k = 0; k < check.first.size() && k < 3; ++k) {
        const CacheDifference& d = check.first[k];
        std::cerr << "  evaluation " << d.evaluation << ", sampler \"" << scene.samplers[size_t(d.sampler)].name
                  << "\" item " << d.item << " path " << d.path << ": cached " << d.cached << ", fresh " << d.fresh;
        if (d.where) std::cerr << "; the rays part at (" << d.where->x << ", " << d.where->y << ", " << d.where->z << ") m";
        std::cerr << "\n";
    }
}

// The settings the run uses: the scene's (--set over them), then the command line's,
// the report's and the selection's counts not below the search's, and the optional ones
// at optimize's defaults (report.json's "settings").
OptimizerSettings runSettings(const OptimizeArgs& args, const OptimizerSettings& scene) {
    OptimizerSettings s = scene;
    if (args.iterations >= 0) s.iterations = args.iterations;
    if (args.seed) s.seed = *args.seed;
    if (args.suggestions > 0) s.suggestions = args.suggestions;
    if (args.paths > 0) s.pathsPerPoint = s.searchPathsPerPoint = args.paths;
    s.reportPathsPerPoint = std::max(s.reportPathsPerPoint, s.searchPathsPerPoint);
    s.selectionPathsPerPoint = std::max(s.selectionPathsPerPoint, s.searchPathsPerPoint);
    s.sunPatches = s.sunPatches.value_or(SunPatchUse::Report);
    s.lightRoulette = s.lightRoulette.value_or(kSearchLightRoulette);
    return s;
}

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

// The start (its draws said on stderr while none passes the rules) and the run, its
// progress on stderr unless quiet; `start` receives the start layout.
OptimizerResult search(Optimizer& optimizer, bool quiet, Layout& start) {
    bool tty = !quiet && isatty(STDERR_FILENO);
    bool drew = false;
    auto lastLine = std::chrono::steady_clock::now();
    auto drawing = [&](int drawn, int most) {
        // A start that keeps failing the geometric rules (furniture that cannot fit):
        // its draws can take seconds in all. Without a terminal, a line every 5 s.
        if (!tty && drew && std::chrono::steady_clock::now() - lastLine < std::chrono::seconds(5)) return;
        lastLine = std::chrono::steady_clock::now();
        drew = true;
        std::cerr << (tty ? "\r" : "") << "drawing a start layout: " << drawn << " of at most " << most
                  << " draws, none within the geometric rules' hard limits yet" << (tty ? "\033[K" : "\n") << std::flush;
    };
    optimizer.initialize(quiet ? std::function<void(int, int)>() : drawing);
    if (drew && tty) std::cerr << "\n";
    start = optimizer.current();  // the comparison picture's left side
    ProgressCallback progress;
    // The start within every rule's limit: no "by iteration N: a layout keeps every rule" line.
    bool feasibleSeen = !optimizer.currentEvaluation().rejected;
    if (!quiet) progress = [tty, &feasibleSeen](const Progress& p) { showProgress(p, tty, feasibleSeen); };
    OptimizerResult result = optimizer.run(progress, &interrupted);
    if (tty) std::cerr << "\n";
    if (result.stop == StopReason::Cancelled) std::cerr << "interrupted: writing the best layout found so far\n";
    return result;
}

// layout.json (and the suggestions) in the scene file's hierarchy, so that --layout
// reads them back; in a flat run layout_flat.json keeps every object's own placement
// (measure --set flat=true).
void writeLayouts(const std::filesystem::path& out, const Scene& original, const Scene& scene,
                  const std::optional<FlatScene>& flattened, const OptimizerResult& result) {
    if (flattened) {
        io::writeLayout(out / "layout_flat.json", scene, result.best);
        io::writeLayout(out / "layout.json", original, hierarchicalLayoutOf(original, *flattened, result.best));
    } else {
        io::writeLayout(out / "layout.json", scene, result.best);
    }
    if (!result.suggestions.empty()) std::filesystem::create_directories(out / "suggestions");
    for (size_t i = 0; i < result.suggestions.size(); ++i) {
        const Layout& layout = result.suggestions[i].layout;
        const std::filesystem::path file = out / suggestionFile(i);
        if (flattened) io::writeLayout(file, original, hierarchicalLayoutOf(original, *flattened, layout));
        else io::writeLayout(file, scene, layout);
    }
}

// The run in words on stdout: its cost, the goals and rules held, each target missed.
void printSummary(const Scene& scene, const OptimizerResult& result, int reportPaths) {
    std::cout << "optimize: " << result.iterations << " iterations in " << durationText(result.seconds) << " ("
              << stopReasonName(result.stop) << ")";
    if (result.feasible) {
        const Evaluation& best = result.bestEvaluation;
        std::cout << "; best C " << best.cost;
        if (best.costError > 0) std::cout << " +- " << best.costError;
        std::cout << " (L " << best.lighting << ", G " << best.geometry << ") at iteration " << result.bestIteration;
        if (best.lightingEvaluated && scene.objective.lightingWeight == 0)
            std::cout << "\n  lighting weight 0: C is G, exact; L was measured for the report only";
        else if (best.lightingEvaluated && result.independentMeasurements > 0)
            std::cout << "\n  that C is a fresh measurement of the result, with " << reportPaths
                      << " paths per point and a seed of its own, so it differs from the progress line: the search "
                      << "estimated C " << result.bestSearchEvaluation.cost
                      << (result.candidates.size() > 1
                              ? "; the result is the best of " + std::to_string(result.candidates.size()) +
                                    " candidates re-measured (candidate " + std::to_string(result.chosenCandidate + 1) + ")"
                              : std::string("; the one candidate"));
    }
    else
        std::cout << "; no layout passed the geometric rules";
    if (result.feasible) {
        const GoalCount goals = countGoals(scene, result);
        std::cout << "\n  " << goals.sentence() << " (a rule at any penalty above 0 is not held)";
        if (scene.maintenanceFactor != 1 && !scene.samplers.empty())
            std::cout << "\n  the illuminances are maintained ones: the luminaires' light x " << scene.maintenanceFactor
                      << " (maintenance factor)" << (scene.daylight ? ", the daylight as it is" : "");
    }
    // Each target the result misses, and whether any layout the search measured met it.
    if (result.feasible)
        for (size_t k = 0; k < scene.samplers.size() && k < result.bestEvaluation.samplers.samplers.size(); ++k) {
            const ReachVerdict verdict =
                reachVerdict(scene.samplers[k], result.samplerRanges[k], result.bestEvaluation.samplers.samplers[k]);
            if (verdict.reach == Reach::Met) continue;
            std::cout << "\n  " << scene.samplers[k].name
                      << (verdict.reach == Reach::WithinNoise ? " is at its target's bound (" : " misses its target (")
                      << (verdict.reach == Reach::WithinNoise ? "within noise"
                          : verdict.reach == Reach::OutOfReach ? "out of reach"
                          : verdict.reach == Reach::NeverMet   ? "never met"
                          : verdict.reach == Reach::GoalMissed ? "a goal missed"
                                                               : reachName(verdict.reach)) << "): "
                      << verdict.reason;
        }
}

// The pictures, scene.glb, report.html and report.pdf, said on stdout.
void writePictures(const OptimizeArgs& args, const Scene& scene, const OptimizerSettings& settings, const Layout& start,
                   const OptimizerResult& result, const DaylightEnvironment* daylight) {
    OutputOptions pictures;
    pictures.seed = result.options.seed;
    pictures.samplerPaths = settings.reportPathsPerPoint;  // the start's too, as the result's
    pictures.tracing.sunPatches = settings.samplesSunPatches(SunPatchUse::Report, false);
    pictures.tracing.exteriorSun = settings.exteriorSun;
    pictures.initialLabel = "start";
    // A (second) stop signal from now on skips the pictures still to make.
    interrupted.store(false);
    pictures.cancel = &interrupted;
    if (args.spp > 0) pictures.renderSamplesPerPixel = args.spp;
    pictures.pdf = !args.noPdf;
    RunOutputs outputs;
    {
        std::cout.flush();  // the summary before the pictures' progress on stderr, also in a log
        PictureProgress progress(pictures);
        outputs = writeRunOutputs(args.out, scene, start, result.best, &result, daylight, pictures);
    }
    if (outputs.files.empty() && outputs.cancelled) {
        std::cout << "  pictures: stopped before the first was written\n";
    } else {
        std::cout << "  wrote";
        for (const auto& f : outputs.files) std::cout << " " << f.filename().string();
        std::cout << " in " << durationText(outputs.seconds) << (outputs.cancelled ? " (stopped: the rest skipped)" : "") << "\n";
    }
}

// Returns the signal that interrupted the run after its outputs were written, or 0.
int runOptimize(const OptimizeArgs& args) {
    // From the start, so that a signal during loading still ends in written outputs.
    StopSignals stopSignals;
    const Scene original = loadSceneWithSettings(args);
    const OptimizerSettings settings = runSettings(args, original.optimizer);
    const TracingSettings& tracingSettings = settings;
    printSceneWarnings(original);
    checkOutputFolder(args.out);
    // Before the daylight's bake: each layout's measurement and the report's.
    warnLargeMeasurement(original, settings.searchPathsPerPoint, "the search measures each layout at");
    warnLargeMeasurement(original, settings.reportPathsPerPoint, "the report measures the final layout at");
    std::optional<DaylightEnvironment> daylight;
    if (original.daylight) daylight = bakeDaylight(*original.daylight, original.site, args.quiet);

    OptimizerOptions options = optimizerOptions(settings);
    // Flat: the same furniture without groups, kept together by cohesion constraints.
    std::optional<FlatScene> flattened;
    if (options.hierarchy == Hierarchy::Flat) {
        flattened = flattenScene(original);
        if (!args.quiet)
            std::cerr << "flat: " << flattened->scene.entities.size() << " objects without groups, "
                      << flattened->cohesionConstraints << " cohesion constraints\n";
    }
    const Scene& scene = flattened ? flattened->scene : original;
    if (!args.start.empty()) {
        // The designer's own layout (readLayout names the file and entry of any error:
        // an unknown or fixed entity, a pose outside its regions).
        const Layout given = io::readLayout(args.start, original);
        options.start = StartFrom::Given;
        options.startLayout = flattened ? flatLayoutOf(original, *flattened, given) : given;
    }

    MeasureOptions measure;
    measure.pathsPerPoint = settings.searchPathsPerPoint;
    warnFewPaths(original, measure.pathsPerPoint, args.paths > 0);
    measure.seed = options.seed;
    measure.adaptive = !tracingSettings.fixedPaths;
    measure.lowDiscrepancy = tracingSettings.lowDiscrepancy;
    measure.choiceError = false;  // the search's stops do not read it; its report's measurements do
    // The report's count for the result (measure's default: report.json and `measure
    // --layout --seed` give one number); the selection's, far fewer, for the confirmations
    // and the candidates' re-measures (issue 58). Neither below the search's.
    const int reportPaths = settings.reportPathsPerPoint;
    const int selectionPaths = settings.selectionPathsPerPoint;
    std::unique_ptr<PathTracedLighting> lighting =
        makeLighting(scene, daylight ? &*daylight : nullptr, tracingSettings, measure, reportPaths, selectionPaths);

    // With lighting weight 0 the chain never calls it, but the result's report does.
    Optimizer optimizer(scene, options, lighting.get());
    Layout start;
    OptimizerResult result = search(optimizer, args.quiet, start);

    writeOptimizerOutputs(args.out, scene, result, io::settingsJson(settings));
    if (!result.snapshots.empty()) writeSnapshots(std::filesystem::path(args.out) / "snapshots.json", scene, result);
    writeLayouts(args.out, original, scene, flattened, result);
    printSummary(scene, result, reportPaths);
    std::cout << "\n  wrote " << args.out << "/layout.json, report.json, trace.csv\n";
    if (!args.noPictures) writePictures(args, scene, settings, start, result, daylight ? &*daylight : nullptr);
    if (lighting)
        std::cout << "  lighting: " << lighting->evaluations() << " evaluations, "
                  << lighting->rays().closest + lighting->rays().shadow << " rays, " << lighting->tracedPaths()
                  << " paths traced, " << lighting->reusedPaths() << " reused from earlier layouts\n";
    if (lighting && tracingSettings.checkCache) printCacheCheck(scene, lighting->cacheCheck());
    return result.stop == StopReason::Cancelled || interrupted.load() ? stopSignal.load() : 0;
}

}  // namespace

void registerOptimizeCommand(CLI::App& app, int& threads) {
    auto args = std::make_shared<OptimizeArgs>();
    auto* cmd = app.add_subcommand("optimize", "Search the furniture layout for the design rules and lighting goals");
    cmd->add_option("-o,--out", args->out, "Output folder (layout.json, report.json, trace.csv)")->required();
    cmd->add_option("--iterations", args->iterations, "Iterations (default: optimizer.iterations)")
        ->check(wholeNumber(0));
    addSharedOptions(cmd, *args, threads,
                     "Paths per sampler point during the search (default: optimizer.paths_per_point, or 64 if the scene "
                     "does not give it)",
                     kQuietOption);
    cmd->add_option("--suggestions", args->suggestions,
                    "Also write OUTDIR/suggestions/1.json ... K.json: the K best mutually distinct layouts (some movable "
                    "entity more than 0.5 m or 45 degrees apart, or in another region), each measured again like the result")
        ->check(CLI::Range(1, kMostSuggestions));
    cmd->add_option("--start", args->start,
                    "Start the search from this layout file (as layout.json; entities it does not name keep the scene's "
                    "placement) instead of a uniform draw");
    cmd->add_flag("--no-pictures", args->noPictures, "Skip the pictures, scene.glb, report.html and report.pdf");
    cmd->add_flag("--no-pdf", args->noPdf, "Skip report.pdf (report.html printed by headless Chromium)")->group(advancedGroup());
    cmd->add_option("--spp", args->spp, "Samples per pixel of render.png (default 16)")
        ->check(wholeNumber(1))
        ->group(advancedGroup());
    cmd->callback([args] {
        namingScene(args->scene, [&] {
            if (int signal = runOptimize(*args)) throw CLI::RuntimeError(128 + signal);
        });
    });
}

}  // namespace luxplan::cli
