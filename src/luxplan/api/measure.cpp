#include <luxplan/api/measure.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <luxplan/annual/annual_metrics.h>
#include <luxplan/annual/scene_year.h>
#include <luxplan/checks/scene_warnings.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/core/error.h>
#include <luxplan/daylight/datetime.h>
#include <luxplan/daylight/weather.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/progress_line.h>
#include <luxplan/optimizer/sampler_report.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan::api {
namespace {

nlohmann::json bound(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The tracing settings as measure applies them (its own defaults where the scene's
// settings leave one to the command).
PathTracerOptions measureTracing(const TracingSettings& s) {
    PathTracerOptions tracing;
    tracing.sunPatches = s.samplesSunPatches(SunPatchUse::On, false);
    tracing.exteriorSun = s.exteriorSun;
    return tracing;
}

// The year at the samplers `which` (daylight coefficients, annual/scene_year.h), at the
// measurement's paths and seed. A sampler whose points are no single sensors is said
// and left out.
AnnualSeries measureYear(const Scene& scene, const EmbreeScene& rt, const std::vector<size_t>& which, int paths,
                         uint64_t seed, const std::string& what, const MeasureHooks& hooks) {
    std::optional<DaylightCoefficients> dc;
    try {
        dc.emplace(sceneYear(scene));
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(what + ": " + e.what());
    }
    std::function<void(size_t, size_t)> progress;
    if (hooks.yearProgress)
        progress = [&](size_t done, size_t total) { hooks.yearProgress(what, done, total, dc->hours().size()); };
    AnnualSeries series = measureYearAt(*dc, rt, which, paths, seed, progress);
    for (size_t k : which) {
        bool measured = false;
        for (const AnnualSampler& a : series.samplers) measured = measured || a.name == scene.samplers[k].name;
        if (!measured && hooks.warning)
            hooks.warning(scene.file.string() + ": " + what + ": sampler \"" + scene.samplers[k].name + "\" (" +
                          scene.samplers[k].type->name() +
                          ") has no hourly values: its points are no single sensors (planar, volume and cylindrical "
                          "samplers are)");
    }
    return series;
}

}  // namespace

DaylightParams daylightAt(const Scene& scene, const std::string& at) {
    if (!scene.daylight)
        throw std::runtime_error("--at " + at + ": the scene has no \"daylight\" to evaluate at an instant");
    std::string why;
    auto t = parseIso8601(at, &why);
    if (!t) throw std::runtime_error("--at " + why);
    DaylightParams d = *scene.daylight;
    d.from = *t;
    d.to.reset();
    if (d.weather) {
        // The file's hour that contains the time (its month, day and hour in the file's
        // time zone, the year ignored), placed and reported at its middle.
        const WeatherFile& w = *d.weather;
        const std::vector<size_t> hours = weatherHoursIn(w, *t, std::nullopt);
        if (hours.empty())
            throw std::runtime_error("--at " + at + ": no hour of " + w.file.string() + " contains it");
        const WeatherHour& h = w.hours[hours.front()];
        for (auto [value, what] : {std::pair{h.directNormalWm2, "direct normal"}, std::pair{h.diffuseHorizontalWm2, "diffuse horizontal"}})
            if (std::isnan(value))
                throw FileError(w.file.string(), std::to_string(h.line),
                                "--at " + at + ": the " + what + " irradiance of that hour (" + w.middleOf(h).str() +
                                    ") is missing (the file's code 9999)");
        d.from = w.middleOf(h);
    }
    return d;
}

std::string fewPathsWarning(const Scene& scene, int paths, bool fromOption, const std::string& key) {
    if (paths >= 2 || scene.samplers.empty()) return "";
    const bool fromSet = std::find(scene.settingsSet.begin(), scene.settingsSet.end(), key) != scene.settingsSet.end();
    const std::string n = std::to_string(paths);
    const std::string source = fromOption ? "--paths " + n
                               : fromSet  ? "--set " + key + "=" + n
                                          : scene.file.string() + ": /optimizer/" + key + ": " + n;
    std::string message = "warning: " + source + ": one path per point gives no standard error (reported as 0, "
                          "n/a in measure's table)";
    for (const LightSamplerSpec& s : scene.samplers)
        if (std::string(s.type->name()) == "directional") {
            message += ", and directional sampler \"" + s.name + "\" reads the plain max of its strata, which errs high "
                       "(its brightest stratum is measured with paths it was not chosen by from 2 paths per point on)";
            break;
        }
    return message;
}

long long samplerPoints(const Scene& scene) {
    long long points = 0;
    for (const LightSamplerSpec& s : scene.samplers) points += s.type->place(Transform())->items();
    return points;
}

std::string largeMeasurementNote(const Scene& scene, int pathsPerPoint, const std::string& what) {
    if (scene.samplers.empty()) return "";
    const std::string warning = largeMeasurementWarning(what, samplerPoints(scene), int(scene.samplers.size()), pathsPerPoint);
    return warning.empty() ? "" : scene.file.string() + ": " + warning;
}

MeasureOutcome measure(Scene scene, const MeasureRequest& request, const MeasureHooks& hooks) {
    auto say = [&](const std::string& line) {
        if (hooks.warning && !line.empty()) hooks.warning(line);
    };
    const TracingSettings settings = scene.optimizer;
    if (scene.optimizer.flatScene) scene = flattenScene(scene).scene;
    MeasureOutcome out;
    out.request = request;
    const Layout layout = request.layoutText ? io::readLayoutText(*request.layoutText, "layout", scene)
                          : request.layoutFile.empty() ? initialLayout(scene)
                                                       : io::readLayout(request.layoutFile, scene);
    // The report's count: one number per quantity, whichever command gives it.
    const int pathsPerPoint = request.paths > 0 ? request.paths : scene.optimizer.reportPathsPerPoint;
    // Said before the daylight's bake, the first thing that takes time.
    say(largeMeasurementNote(scene, pathsPerPoint, "measuring"));
    auto bake = [&](const DaylightParams& d) {
        return hooks.bake ? hooks.bake(d, scene.site) : buildDaylight(d, scene.site);
    };
    std::optional<DaylightEnvironment> daylight;
    out.atReported = request.at;
    if (!request.at.empty()) {
        Scene instant = scene;
        instant.daylight = daylightAt(scene, request.at);
        if (instant.daylight->weather) out.atReported = instant.daylight->from->str();
        // The same warning as a scene whose period is that instant: after sunset.
        for (const Diagnostic& w : darkDaylight(instant))
            say(scene.file.string() + ": --at " + request.at + ": warning: " + w.message);
        daylight = bake(*instant.daylight);
    } else if (scene.daylight) {
        daylight = bake(*scene.daylight);
    }
    EmbreeScene rt(scene, layout);
    PathTracer tracer(rt, daylight ? &*daylight : nullptr, measureTracing(settings));
    MeasureOptions& options = out.options;
    options.pathsPerPoint = pathsPerPoint;
    say(fewPathsWarning(scene, options.pathsPerPoint, request.paths > 0, "report_paths_per_point"));
    options.seed = request.seed.value_or(scene.optimizer.seed);
    options.adaptive = settings.adaptive;
    out.lightRoulette = settings.lightRoulette.value_or(0);
    if (out.lightRoulette > 0) options.lightFloors = lightSampleFloors(tracer, out.lightRoulette, options.seed);
    options.lowDiscrepancy = settings.lowDiscrepancy;
    out.sampling = settings.lowDiscrepancy ? "sobol" : "random";
    out.sunPatches = tracer.samplesSunPatches();
    out.exteriorSun = tracer.samplesExteriorSun();
    const auto samplersStart = std::chrono::steady_clock::now();
    {
        const std::shared_ptr<void> watch =
            hooks.watchSamplers
                ? hooks.watchSamplers(options, (unsigned long long)(samplerPoints(scene)) * (unsigned long long)(pathsPerPoint))
                : nullptr;
        out.result = measureSamplers(tracer, options);
    }
    out.samplersSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - samplersStart).count();
    options.pathsDone = nullptr;  // the watcher's counter is gone
    // The year: with `annual` every sampler's, else the annual goals' (their terms read it).
    if (request.annual || !annualGoalSamplers(scene).empty()) {
        std::vector<size_t> which = annualGoalSamplers(scene);
        if (request.annual) {
            which.clear();
            for (size_t k = 0; k < scene.samplers.size(); ++k) which.push_back(k);
        }
        const auto yearStart = std::chrono::steady_clock::now();
        out.year = measureYear(scene, rt, which, pathsPerPoint, options.seed, request.annual ? "--annual" : "annual goals", hooks);
        out.yearSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - yearStart).count();
        setAnnualInRange(scene, *out.year, out.result.samplers);
    }
    // The objective of Eq. 1 for this layout, as optimize reports it (report.json's C).
    out.lighting = lightingCostOfResults(scene, out.result.samplers);
    out.lightingError = lightingCostError(scene, out.result.samplers);
    out.geometry = GeometryEvaluator(scene).evaluate(worldTransforms(scene, layout));
    out.cost = scene.objective.cost(out.lighting, out.geometry.cost);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - request.started).count();
    out.scene = std::move(scene);
    return out;
}

nlohmann::json measureJson(const MeasureOutcome& m) {
    const Scene& scene = m.scene;
    const MeasureOptions& options = m.options;
    const double w = scene.objective.lightingWeight;
    nlohmann::json samplers = nlohmann::json::array();
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        const SamplerResult& r = m.result.samplers[k];
        const SamplerRow row(s, r);
        nlohmann::json sampler = {{"name", s.name},
                                  {"type", s.type->name()},
                                  {"unit", s.type->unit()},
                                  {"value", r.value},
                                  {"std_error", r.standardError},
                                  {"target", {bound(s.targetMin), bound(s.targetMax)}},
                                  {"penalty", row.penalty()},
                                  {"points", r.points},
                                  {"point_std_errors", r.pointErrors}};
        sampler.update(nlohmann::json(row.detailsJson()));
        // The points furniture covers (null in `points`), for every sampler with point statistics.
        if (s.type->hasPointStatistics()) sampler["covered"] = r.covered;
        // Only when it happened, so that the usual output stays as it was.
        if (r.droppedNonFinite > 0) sampler["dropped_nonfinite"] = r.droppedNonFinite;
        if (options.adaptive) sampler["paths_per_point"] = r.pathsPerPoint;
        if (!options.lightFloors.empty()) sampler["light_floor"] = options.lightFloors[k];
        samplers.push_back(sampler);
    }
    nlohmann::json out = {{"samplers", samplers},
                          {"paths_per_point", options.pathsPerPoint},
                          {"adaptive", options.adaptive}, {"sampling", m.sampling}, {"sun_patches", m.sunPatches},
                          {"exterior_sun", m.exteriorSun},
                          {"light_roulette", m.lightRoulette},
                          {"seed", options.seed},
                          {"maintenance_factor", scene.maintenanceFactor},
                          {"L", m.lighting}, {"L_std_error", m.lightingError},
                          {"G", m.geometry.cost}, {"C", m.cost}, {"C_std_error", w * m.lightingError},
                          {"geometric_rules_pass", !m.geometry.rejected},
                          {"seconds", m.seconds}};
    if (!m.request.at.empty()) out["at"] = m.atReported;
    if (m.year && m.request.annual) {
        addAnnualJson(out, *m.year);
        out["annual_seconds"] = m.yearSeconds;
        out["samplers_seconds"] = m.samplersSeconds;  // the one measurement's, beside the year's
    }
    return out;
}

}  // namespace luxplan::api
