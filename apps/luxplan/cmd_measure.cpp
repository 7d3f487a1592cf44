// `luxplan measure SCENE [--layout L] [--paths N] [--seed S] [--threads T] [--set KEY=VALUE] [--json]
// [--at TIME] [--daylight-factor]`: evaluates every light sampler by path tracing. The settings
// (io/settings_table.h) it reads: seed, report_paths_per_point, sampling, sun_patches,
// exterior_sun, light_roulette, adaptive, flat (the flattened scene: the layout_flat.json of
// an optimize run with hierarchy flat). --daylight-factor: each planar sampler's daylight
// factor under the CIE overcast sky instead (lightsamplers/daylight_factor.h).
#include <atomic>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "daylight_progress.h"
#include "option_checks.h"
#include "shared_options.h"
#include <luxplan/api/measure.h>
#include <luxplan/annual/annual_metrics.h>
#include <luxplan/annual/scene_year.h>
#include <luxplan/checks/scene_warnings.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/core/format.h>
#include <luxplan/daylight/datetime.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/weather.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/daylight_factor.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/progress_line.h>
#include <luxplan/optimizer/sampler_report.h>

namespace luxplan::cli {
namespace {

nlohmann::json bound(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

struct MeasureArgs : SharedArgs {
    bool json = false, daylightFactor = false;
    std::string at;  // ISO 8601: one instant of daylight instead of the period
    bool annual = false;  // every occupied hour of the period with the sun up, by daylight coefficients
};

// The tracing settings as measure applies them (its own defaults where the scene's
// settings leave one to the command).
PathTracerOptions measureTracing(const TracingSettings& s) {
    PathTracerOptions tracing;
    tracing.sunPatches = s.samplesSunPatches(SunPatchUse::On, false);
    tracing.exteriorSun = s.exteriorSun;
    return tracing;
}
const char* samplingName(const TracingSettings& s) { return s.lowDiscrepancy ? "sobol" : "random"; }

// The measurement's progress on stderr, a line every 5 s once it has run that long:
// on a terminal, or for a large measurement (kLargeMeasurementPaths) wherever stderr
// goes. Elsewhere quiet: a short measurement's --json output is read with its stderr.
class MeasureProgress {
public:
    MeasureProgress(MeasureOptions& options, unsigned long long total)
        : total_(total), atMost_(options.adaptive), start_(std::chrono::steady_clock::now()) {
        if (!isatty(STDERR_FILENO) && !(double(total) > kLargeMeasurementPaths)) return;
        options.pathsDone = &done_;
        watcher_ = std::thread([this] { watch(); });
    }
    ~MeasureProgress() {
        if (!watcher_.joinable()) return;
        {
            std::lock_guard lock(mutex_);
            finished_ = true;
        }
        wake_.notify_all();
        watcher_.join();
        if (said_) std::cerr << "  measured in " << durationText(seconds()) << "\n";
    }
    MeasureProgress(const MeasureProgress&) = delete;
    MeasureProgress& operator=(const MeasureProgress&) = delete;

private:
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    void watch() {
        std::unique_lock lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::seconds(5), [this] { return finished_; })) {
            said_ = true;
            std::cerr << "  " << measureProgressLine(done_.load(), total_, seconds(), atMost_) << std::endl;
        }
    }

    unsigned long long total_;
    bool atMost_;
    std::chrono::steady_clock::time_point start_;
    std::atomic<uint64_t> done_{0};
    std::mutex mutex_;
    std::condition_variable wake_;
    bool finished_ = false, said_ = false;
    std::thread watcher_;
};
// What the table and JSON say of the luminaires' light: maintained when the scene
// has a maintenance factor below 1.
std::string maintainedLine(const Scene& scene) {
    if (scene.maintenanceFactor == 1) return "";
    std::ostringstream out;
    out << "maintained illuminance: the luminaires' light x " << std::defaultfloat << scene.maintenanceFactor
        << " (maintenance factor)" << (scene.daylight ? ", the daylight as it is" : "") << "\n";
    return out.str();
}

// --daylight-factor: every planar sampler's daylight factor under the CIE overcast sky,
// the luminaires off.
void runDaylightFactor(const MeasureArgs& args, const Scene& scene, const Layout& layout,
                       std::chrono::steady_clock::time_point start) {
    MeasureOptions options;
    options.pathsPerPoint = args.paths > 0 ? args.paths : scene.optimizer.reportPathsPerPoint;
    // Of the samplers it measures (no directional one).
    if (options.pathsPerPoint < 2)
        warnFewPaths(daylightFactorScene(scene).scene, options.pathsPerPoint, args.paths > 0, "report_paths_per_point");
    options.seed = args.seed.value_or(scene.optimizer.seed);
    options.lowDiscrepancy = scene.optimizer.lowDiscrepancy;
    const DaylightFactorResult df = measureDaylightFactors(scene, layout, options, measureTracing(scene.optimizer));
    const DaylightParams sky = daylightFactorSky(scene);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (args.json) {
        nlohmann::json samplers = nlohmann::json::array();
        for (size_t i = 0; i < df.samplers.size(); ++i) {
            const LightSamplerSpec& s = scene.samplers[df.samplers[i]];
            const SamplerResult& m = df.measured.samplers[i];
            const DaylightFactor& f = df.factors[i];
            nlohmann::json points = nlohmann::json::array();
            for (double p : f.points) points.push_back(bound(p));
            nlohmann::json sampler = {{"name", s.name},
                                      {"type", s.type->name()},
                                      {"daylight_factor", f.percent},
                                      {"daylight_factor_std_error", f.stdError},
                                      {"daylight_factor_min", f.min},
                                      {"illuminance_lx", m.value},
                                      {"points", points},
                                      {"covered", m.covered}};
            if (auto grid = s.type->pointGrid()) sampler["grid"] = {(*grid)[0], (*grid)[1]};
            if (m.droppedNonFinite > 0) sampler["dropped_nonfinite"] = m.droppedNonFinite;
            samplers.push_back(sampler);
        }
        nlohmann::json out = {{"daylight_factor", {{"sky", "cie_overcast"},
                                                   {"horizontal_illuminance_lx", df.outdoorLx},
                                                   {"ground_reflectance", sky.groundReflectance},
                                                   {"luminaires", "off"}}},
                              {"samplers", samplers},
                              {"paths_per_point", options.pathsPerPoint},
                              {"sampling", samplingName(scene.optimizer)},
                              {"seed", options.seed},
                              {"seconds", seconds}};
        std::cout << out.dump(2) << "\n";
        return;
    }
    std::cout << "daylight factor: CIE standard overcast sky, " << std::fixed << std::setprecision(0) << df.outdoorLx
              << " lx on the open horizontal plane, ground reflectance " << std::setprecision(2) << sky.groundReflectance
              << ", luminaires off\n";
    std::cout << std::left << std::setw(24) << "sampler" << std::right << std::setw(10) << "DF %" << std::setw(10) << "+-"
              << std::setw(10) << "min %" << std::setw(12) << "E lx" << std::setw(10) << "points" << "\n";
    for (size_t i = 0; i < df.samplers.size(); ++i) {
        const LightSamplerSpec& s = scene.samplers[df.samplers[i]];
        const SamplerResult& m = df.measured.samplers[i];
        const DaylightFactor& f = df.factors[i];
        std::cout << std::left << std::setw(24) << s.name << std::right << std::fixed << std::setprecision(2) << std::setw(10)
                  << f.percent << std::setw(10) << (m.pathsPerPoint < 2 ? "n/a" : fixedDigits(f.stdError, 2)) << std::setw(10) << f.min
                  << std::setprecision(1) << std::setw(12) << m.value << std::setw(10) << (f.points.size() - m.covered.size())
                  << "\n";
    }
    std::cout << std::fixed << std::setprecision(2) << df.measured.paths << " paths (" << options.pathsPerPoint
              << " per point), " << df.measured.rays.closest + df.measured.rays.shadow << " rays in " << seconds << " s\n";
}

// The year's progress on stderr every 5 s once it has run that long (on a terminal, one
// line rewritten).
std::function<void(const std::string&, size_t, size_t, size_t)> yearProgressOnStderr() {
    struct State {
        std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
        std::mutex lock;
    };
    auto state = std::make_shared<State>();
    const bool tty = isatty(STDERR_FILENO);
    return [state, tty](const std::string& what, size_t done, size_t total, size_t hours) {
        const std::lock_guard<std::mutex> guard(state->lock);
        const auto now = std::chrono::steady_clock::now();
        if (done < total && now - state->last < std::chrono::seconds(5)) return;
        state->last = now;
        if (tty || done < total)
            std::cerr << (tty ? "\r" : "") << what << ": " << done << " of " << total << " points traced (" << hours
                      << " hours)" << (tty ? (done < total ? "\033[K" : "\033[K\n") : "\n") << std::flush;
    };
}

void printMeasureTable(const api::MeasureOutcome& m);

void runMeasure(const MeasureArgs& args) {
    auto start = std::chrono::steady_clock::now();
    Scene scene = loadSceneWithSettings(args);
    printSceneWarnings(scene);
    if (args.daylightFactor) {
        const TracingSettings settings = scene.optimizer;
        if (scene.optimizer.flatScene) scene = flattenScene(scene).scene;
        const Layout layout = args.layout.empty() ? initialLayout(scene) : io::readLayout(args.layout, scene);
        // It measures every point at a fixed count, every light sample traced.
        if (settings.adaptive) throw CLI::ValidationError("--daylight-factor", "excludes the setting adaptive (true)");
        if (settings.lightRoulette.value_or(0) > 0)
            throw CLI::ValidationError("--daylight-factor", "excludes the setting light_roulette (above 0)");
        if (std::string why = daylightFactorRefusal(scene); !why.empty()) throw std::runtime_error("--daylight-factor: " + why);
        runDaylightFactor(args, scene, layout, start);
        return;
    }
    api::MeasureRequest request;
    request.layoutFile = args.layout;
    request.paths = args.paths;
    request.seed = args.seed;
    request.at = args.at;
    request.annual = args.annual;
    request.started = start;
    api::MeasureHooks hooks;
    hooks.warning = [](const std::string& line) { std::cerr << line << "\n"; };
    hooks.bake = [](const DaylightParams& d, const Site& site) { return bakeDaylight(d, site); };
    hooks.watchSamplers = [](MeasureOptions& options, unsigned long long total) {
        return std::static_pointer_cast<void>(std::make_shared<MeasureProgress>(options, total));
    };
    hooks.yearProgress = yearProgressOnStderr();
    const api::MeasureOutcome m = api::measure(std::move(scene), request, hooks);
    if (args.json) {
        std::cout << api::measureJson(m).dump(2) << "\n";
        return;
    }
    printMeasureTable(m);
}

void printMeasureTable(const api::MeasureOutcome& m) {
    const Scene& scene = m.scene;
    const MeasureOptions& options = m.options;
    const MeasureResult& result = m.result;
    const std::optional<AnnualSeries>& year = m.year;
    const double w = scene.objective.lightingWeight, cost = m.cost, lighting = m.lighting, lightingError = m.lightingError;
    const GeometryResult& geometry = m.geometry;
    const double seconds = m.seconds, yearSeconds = m.yearSeconds;
    if (!m.request.at.empty()) std::cout << "daylight at " << m.request.at << " (one instant, not the scene's period)\n";
    std::cout << maintainedLine(scene);
    std::cout << std::left << std::setw(24) << "sampler" << std::setw(12) << "type" << std::right << std::setw(12)
              << "value" << std::setw(10) << "+-" << std::setw(8) << "unit" << std::setw(22) << "target" << std::setw(10)
              << "penalty" << "\n";
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        const SamplerRow row(s, result.samplers[k]);
        std::cout << std::left << std::setw(24) << s.name << std::setw(12) << s.type->name() << std::right << std::setw(12)
                  << row.valueText() << std::setw(10) << row.errorText() << std::setw(8) << s.type->unit() << std::setw(22)
                  << row.targetText() << std::fixed << std::setprecision(3) << std::setw(10) << row.penalty()
                  << (row.penalty() > 0 ? "  MISSED" : "  ok") << "\n";
        if (std::string details = row.detailsText(); !details.empty()) std::cout << "    " << details << "\n";
        // A statistics goal's line, under its sampler's columns (U0 is a ratio).
        for (size_t i = 1; i < row.terms().size(); ++i) {
            const LightingTerm& t = row.terms()[i];
            const bool ratio = t.statistic == Statistic::U0 || t.statistic == Statistic::AnnualInRange;
            std::cout << std::left << std::setw(24) << ("    " + std::string(statisticNames().name(t.statistic)))
                      << std::setw(12) << "" << std::right << std::fixed << std::setprecision(ratio ? 3 : 1) << std::setw(12)
                      << t.value << std::setw(10) << t.standardError << std::setw(8) << (ratio ? "" : s.type->unit())
                      << std::setw(22) << targetBandText(t.targetMin, t.targetMax) << std::setprecision(3) << std::setw(10)
                      << t.penalty << (t.penalty > 0 ? "  MISSED" : "  ok") << "\n";
        }
    }
    std::cout << std::defaultfloat << std::setprecision(4) << "C " << cost << " +- " << w * lightingError << " (L "
              << lighting << " +- " << lightingError << ", G " << geometry.cost
              << (geometry.rejected ? ", rejected by the geometric rules: " + geometry.rejectedBy : std::string()) << ")\n";
    std::cout << std::fixed << std::setprecision(2) << result.paths << " paths (" << (options.adaptive ? "adaptive, at most " : "")
              << options.pathsPerPoint << " per point), "
              << result.rays.closest + result.rays.shadow << " rays in " << seconds << " s\n";
    if (year && m.request.annual)
        std::cout << "\n" << annualText(*year) << std::fixed << std::setprecision(2) << "the year: " << year->hours.size()
                  << " hours (occupied, the sun up) from daylight coefficients in " << yearSeconds << " s\n";
}

}  // namespace

void warnFewPaths(const Scene& scene, int paths, bool fromOption, const std::string& key) {
    if (const std::string w = api::fewPathsWarning(scene, paths, fromOption, key); !w.empty()) std::cerr << w << "\n";
}

void warnLargeMeasurement(const Scene& scene, int pathsPerPoint, const std::string& what) {
    if (const std::string w = api::largeMeasurementNote(scene, pathsPerPoint, what); !w.empty()) std::cerr << w << "\n";
}

void registerMeasureCommand(CLI::App& app, int& threads) {
    auto args = std::make_shared<MeasureArgs>();
    auto* cmd = app.add_subcommand("measure", "Evaluate every light sampler of a scene by path tracing");
    addSharedOptions(cmd, *args, threads, "Paths per sampler point (default: the report's, optimizer.report_paths_per_point)",
                     kLayoutOption);
    cmd->add_flag("--json", args->json, "Print JSON with per-point values");
    auto* at = cmd->add_option("--at", args->at,
                               "One instant of daylight (ISO 8601 with its UTC offset, e.g. 2026-03-20T16:30+02:00) instead "
                               "of the scene's period averaged");
    auto* annual = cmd->add_flag("--annual", args->annual,
                                 "Every occupied hour of the daylight's period with the sun up (a weather file's year), "
                                 "from daylight coefficients: each sampler's hourly values, in-range share, sDA, ASE, UDI")
                       ->excludes(at);
    cmd->add_flag("--daylight-factor", args->daylightFactor,
                  "Each planar sampler's mean daylight factor (%): its illuminance under the CIE standard overcast "
                  "sky over the open horizontal plane's, the luminaires off (the scene's own daylight not used)")
        ->excludes(at)
        ->excludes(annual);
    cmd->callback([args] { namingScene(args->scene, [&] { runMeasure(*args); }); });
}

}  // namespace luxplan::cli
