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
#include <luxplan/api/optimize.h>
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

// The run's progress on stderr unless quiet: the start's draws while none passes the
// rules, the progress line, and the stop by a signal.
api::OptimizeHooks progressHooks(bool quiet) {
    api::OptimizeHooks hooks;
    hooks.warning = [](const std::string& line) { std::cerr << line << "\n"; };
    if (!quiet) hooks.note = [](const std::string& line) { std::cerr << line << "\n"; };
    hooks.bake = [quiet](const DaylightParams& d, const Site& site) { return bakeDaylight(d, site, quiet); };
    hooks.cancel = &interrupted;
    if (quiet) return hooks;
    struct State {
        bool tty = isatty(STDERR_FILENO), drew = false, planned = false, feasibleSeen = false;
        std::chrono::steady_clock::time_point lastLine = std::chrono::steady_clock::now();
    };
    auto state = std::make_shared<State>();
    hooks.drawing = [state](int drawn, int most) {
        // A start that keeps failing the geometric rules (furniture that cannot fit):
        // its draws can take seconds in all. Without a terminal, a line every 5 s.
        if (!state->tty && state->drew && std::chrono::steady_clock::now() - state->lastLine < std::chrono::seconds(5)) return;
        state->lastLine = std::chrono::steady_clock::now();
        state->drew = true;
        std::cerr << (state->tty ? "\r" : "") << "drawing a start layout: " << drawn << " of at most " << most
                  << " draws, none within the geometric rules' hard limits yet" << (state->tty ? "\033[K" : "\n")
                  << std::flush;
    };
    hooks.planning = [state](int looked, int plans, double lowestC) {
        // The plans take seconds before the first proposal (about one a second on 2 threads).
        if (!state->tty && state->drew && std::chrono::steady_clock::now() - state->lastLine < std::chrono::seconds(5)) return;
        if (state->drew && state->tty && !state->planned) std::cerr << "\n";  // after the draws' line
        state->lastLine = std::chrono::steady_clock::now();
        state->drew = state->planned = true;
        std::cerr << (state->tty ? "\r" : "") << "planning the start: " << looked << " of " << plans
                  << " plans looked at, the lowest C " << lowestC << (state->tty ? "\033[K" : "\n") << std::flush;
    };
    hooks.started = [state](const Optimizer& optimizer) {
        if (state->drew && state->tty) std::cerr << "\n";
        // The start within every rule's limit: no "by iteration N: a layout keeps every rule" line.
        state->feasibleSeen = !optimizer.currentEvaluation().rejected;
    };
    hooks.progress = [state](const Progress& p) { showProgress(p, state->tty, state->feasibleSeen); };
    return hooks;
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
void writePictures(const OptimizeArgs& args, const api::OptimizeRun& run) {
    // A (second) stop signal from now on skips the pictures still to make.
    interrupted.store(false);
    std::cout.flush();  // the summary before the pictures' progress on stderr, also in a log
    const RunOutputs outputs = api::writePictures(run, args.out, args.spp, !args.noPdf, &interrupted, [](OutputOptions& o) {
        return std::static_pointer_cast<void>(std::make_shared<PictureProgress>(o));
    });
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
    Scene original = loadSceneWithSettings(args);
    printSceneWarnings(original);
    api::checkOutputFolder(args.out);
    api::OptimizeRequest request;
    request.iterations = args.iterations;
    request.paths = args.paths;
    request.suggestions = args.suggestions;
    request.seed = args.seed;
    request.startFile = args.start;
    const std::unique_ptr<api::OptimizeRun> run = api::optimize(std::move(original), request, progressHooks(args.quiet));
    const OptimizerResult& result = run->result;
    if (!args.quiet && isatty(STDERR_FILENO)) std::cerr << "\n";
    if (result.stop == StopReason::Cancelled) std::cerr << "interrupted: writing the best layout found so far\n";

    api::writeOutputs(*run, args.out);
    printSummary(run->scene(), result, run->settings.reportPathsPerPoint);
    std::cout << "\n  wrote " << args.out << "/layout.json, report.json, trace.csv\n";
    if (!args.noPictures) writePictures(args, *run);
    if (const PathTracedLighting* lighting = run->lighting.get()) {
        std::cout << "  lighting: " << lighting->evaluations() << " evaluations, "
                  << lighting->rays().closest + lighting->rays().shadow << " rays, " << lighting->tracedPaths()
                  << " paths traced, " << lighting->reusedPaths() << " reused from earlier layouts\n";
        if (run->settings.checkCache) printCacheCheck(run->scene(), lighting->cacheCheck());
    }
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
