#include <luxplan/optimizer/path_traced_lighting.h>

#include <stdexcept>

#include <luxplan/annual/scene_year.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/core/rng.h>
#include <luxplan/json/fields.h>
#include <luxplan/pathtracer/illuminance_at.h>

namespace luxplan {
namespace {

constexpr uint64_t kFreshTag = 0x6672657368ULL;  // "fresh"
constexpr uint64_t kEmptyRoomTag = 0x656d707479ULL;  // "empty"
constexpr uint64_t kAloneTag = 0x616c6f6e65ULL;      // "alone"
// How far below the floor the movable furniture goes while the empty room is traced:
// under the room's own floor, no path from inside reaches it.
constexpr double kOutOfTheWay = 1000;

// The scene's placement with every top-level movable entity but `keep` (-1: none) far
// below the floor: the room without its furniture.
Layout furnitureAway(const Scene& scene, int keep = -1) {
    Layout away = initialLayout(scene);
    for (size_t e = 0; e < scene.entities.size(); ++e)
        if (int(e) != keep && scene.entities[e].parent < 0 && scene.entities[e].movable())
            away.placements[e].position.z -= kOutOfTheWay;
    return away;
}

}  // namespace

PathTracedLighting::PathTracedLighting(const Scene& scene, const DaylightEnvironment* daylight, const MeasureOptions& options,
                                       const PathTracerOptions& searchTracing, const PathTracerOptions& reportTracing)
    : scene_(scene), rt_(scene, initialLayout(scene)), tracer_(rt_, daylight, searchTracing),
      reportTracer_(rt_, daylight, reportTracing), searchTracing_(searchTracing), options_(options), cache_(scene) {
    for (const LightSamplerSpec& s : scene.samplers) hasGlareSurveys_ = hasGlareSurveys_ || s.type->surveysSources();
    if (const std::vector<size_t> annual = annualGoalSamplers(scene); !annual.empty()) {
        year_ = std::make_unique<const DaylightCoefficients>(sceneYear(scene));
        yearTracer_ = std::make_unique<PathTracer>(rt_, &year_->basis(), DaylightCoefficients::tracing());
        yearCache_ = std::make_unique<CoefficientCache>(scene, *year_, annual, options.pathsPerPoint, options.seed);
    }
}

PathTracedLighting::~PathTracedLighting() noexcept {
    try {
        settleCache();
    } catch (...) {  // an error of the cache's update, with no caller left to report it to
    }
}

void PathTracedLighting::commit() {
    if (yearCache_) yearCache_->commit();
    settleCache();
    cacheUpdate_.run([this] { cache_.commit(); });
    cacheUpdating_ = true;
}

void PathTracedLighting::revert() {
    if (yearCache_) yearCache_->discard();
    settleCache();
    cacheUpdate_.run([this] { cache_.discard(); });
    cacheUpdating_ = true;
}

void PathTracedLighting::settleCache() {
    if (!cacheUpdating_) return;
    cacheUpdating_ = false;
    cacheUpdate_.wait();
}

double PathTracedLighting::evaluate(const Layout& /*layout*/, const std::vector<Transform>& world, LightingBreakdown* out) {
    if (fresh_) {
        MeasureOptions fresh = options_;
        fresh.seed = hashValues({options_.seed, kFreshTag, ++freshDraws_});
        fresh.choiceError = true;  // the noise penalty reads the errors
        return measure(tracer_, world, fresh, nullptr, out, hasGlareSurveys_ ? &reportTracer_ : nullptr, margin_);
    }
    PathSource* source = !incremental_ ? nullptr : checkCache_ ? static_cast<PathSource*>(&checked_) : &cache_;
    return measure(tracer_, world, options_, source, out,
                   hasGlareSurveys_ ? &reportTracer_ : nullptr, margin_);
}

double PathTracedLighting::measureIndependently(const Layout& /*layout*/, const std::vector<Transform>& world,
                                                LightingBreakdown* out, uint64_t seed, IndependentUse use) {
    MeasureOptions independent = options_;
    independent.seed = seed;
    const int paths = use == IndependentUse::Report ? reportPaths_ : selectionPaths_;
    if (paths > 0) independent.pathsPerPoint = paths;
    independent.adaptive = false;
    independent.choiceError = true;
    independent.lightFloors.clear();  // as `measure` traces
    // Not through the cache: its committed paths are the search's, and stay so.
    return measure(reportTracer_, world, independent, nullptr, out);
}

std::vector<double> PathTracedLighting::emptyRoomIlluminance(const std::vector<Vec3>& points, int paths, uint64_t seed) {
    const EmbreeScene rt(scene_, furnitureAway(scene_));
    const PathTracer tracer(rt, tracer_.daylight(), searchTracing_);
    return illuminanceAt(tracer, points, Vec3(0, 0, 1), paths, seed, kEmptyRoomTag).values;
}

std::vector<std::vector<double>> PathTracedLighting::aloneInEmptyRoom(int entity, const std::vector<Placement>& placements,
                                                                      const std::vector<int>& samplers, int paths,
                                                                      uint64_t seed) {
    // A copy of the scene whose samplers are these alone, so that a measurement traces them only.
    Scene alone = scene_;
    alone.samplers.clear();
    for (Entity& e : alone.entities) e.samplers.clear();
    for (int k : samplers) {
        const LightSamplerSpec& s = scene_.samplers.at(size_t(k));
        if (s.entity >= 0) alone.entities[size_t(s.entity)].samplers.push_back(int(alone.samplers.size()));
        alone.samplers.push_back(s);
    }
    int root = entity;
    while (scene_.entities[size_t(root)].parent >= 0) root = scene_.entities[size_t(root)].parent;
    Layout layout = furnitureAway(alone, root);
    EmbreeScene rt(alone, layout);
    PathTracer tracer(rt, tracer_.daylight(), searchTracing_);
    MeasureOptions options = options_;
    options.pathsPerPoint = std::max(1, paths);
    options.seed = hashValues({seed, kAloneTag});
    options.adaptive = false;
    options.choiceError = false;
    options.lightFloors.clear();
    options.pathsDone = nullptr;
    std::vector<std::vector<double>> values;
    values.reserve(placements.size());
    for (const Placement& p : placements) {
        layout.placements[size_t(entity)] = p;
        const std::vector<Transform> world = worldTransforms(alone, layout);
        for (size_t i = 0; i < world.size(); ++i) rt.setEntityTransform(int(i), world[i]);
        rt.commit();
        tracer.updateLayout();
        const MeasureResult m = measureSamplers(tracer, options);
        std::vector<double> v;
        for (const SamplerResult& r : m.samplers) v.push_back(r.value);
        values.push_back(std::move(v));
    }
    return values;
}

void PathTracedLighting::setLightRoulette(double share) {
    // The tracer stands at the scene's own layout until the first evaluation.
    if (evaluations_ > 0) throw std::logic_error("PathTracedLighting::setLightRoulette: after the first evaluation");
    options_.lightFloors = share > 0 ? lightSampleFloors(tracer_, share, options_.seed) : std::vector<double>{};
}

double PathTracedLighting::measure(PathTracer& tracer, const std::vector<Transform>& world, const MeasureOptions& options,
                                   PathSource* source, LightingBreakdown* out, PathTracer* glareTracer, double margin) {
    // The moved entities' vertices are rewritten and the top level rebuilt (EmbreeScene).
    for (size_t i = 0; i < world.size(); ++i) rt_.setEntityTransform(int(i), world[i]);
    rt_.commit();
    settleCache();  // the cache reads the new layout (begin) and measureSamplers traces in it
    tracer.updateLayout();
    if (glareTracer) glareTracer->updateLayout();
    last_ = measureSamplers(tracer, options, source, glareTracer);
    measureYear(options, source != nullptr);
    ++evaluations_;
    rays_ += last_.rays;
    reusedPaths_ += last_.reusedPaths;
    if (source == &checked_) {
        CacheCheck found = checked_.found();
        for (CacheDifference& d : found.first) d.evaluation = int64_t(evaluations_);
        check_.add(found);
    }
    tracedPaths_ += last_.paths - last_.reusedPaths;
    if (out) out->samplers = last_.samplers;
    return scene_.samplers.empty() ? 0.0 : lightingCostOfResults(scene_, last_.samplers, margin);
}

void PathTracedLighting::measureYear(const MeasureOptions& options, bool cached) {
    if (!year_) return;
    yearTracer_->updateLayout();
    size_t points = 0;
    const AnnualSeries series =
        cached ? yearCache_->measure(*yearTracer_)
               : year_->measure(*yearTracer_, yearCache_->samplers(), options.pathsPerPoint, options.seed, {}, &points);
    setAnnualInRange(scene_, series, last_.samplers);
    if (cached) {
        tracedPaths_ += yearCache_->tracedPaths();
        reusedPaths_ += yearCache_->reusedPaths();
    } else {
        tracedPaths_ += uint64_t(options.pathsPerPoint) * points;
    }
}

LightingNotes PathTracedLighting::notes() const {
    using Json = nlohmann::ordered_json;
    LightingNotes notes;
    for (double floor : options_.lightFloors) notes.samplers.push_back({{"search_light_floor", floor}});
    if (check_.on) {  // optimize --set check_cache=true
        Json first = Json::array();
        for (const CacheDifference& d : check_.first)
            first.push_back({{"evaluation", d.evaluation},
                             {"sampler", d.sampler < int(scene_.samplers.size()) ? scene_.samplers[size_t(d.sampler)].name : ""},
                             {"item", d.item}, {"path", d.path}, {"cached", json::numberOrNull(d.cached)},
                             {"fresh", json::numberOrNull(d.fresh)},
                             {"parts_at", d.where ? Json{d.where->x, d.where->y, d.where->z} : Json(nullptr)}});
        notes.run["path_cache_check"] = {{"checked", check_.checked}, {"differing", check_.differing}, {"first", first}};
    }
    return notes;
}

}  // namespace luxplan
