#include <luxplan/lightsamplers/light_samplers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>

namespace luxplan {
namespace {

constexpr uint64_t kPilotTag = 0x70696c6f74ULL;  // "pilot": lightSampleFloors' paths

}  // namespace

ItemEstimates::ItemEstimates(int items, int sources)
    : items_(items), sources_(sources), cells_(size_t(items) * sources * kFolds) {}

namespace {

// A stratum of a stratified estimate: its mean and the variance of that mean.
void addStratum(const MeanEstimator& m, double& mean, double& variance) {
    if (m.allZero()) return;  // adds exactly 0 to both (most of a glare survey's cells)
    mean += m.mean();
    variance += m.count() > 0 ? m.variance() / double(m.count()) : 0.0;
}

}  // namespace

// The stratified estimate: each source's mean weighs 1 / sources whatever its path
// count, and so does its variance of the mean (squared).
Estimate ItemEstimates::stratified(int item, int heldOut) const {
    if (totals_.empty()) {
        totals_.resize(size_t(items_) * sources_);
        for (int i = 0; i < items_; ++i)
            for (int source = 0; source < sources_; ++source)
                for (int g = 0; g < kFolds; ++g) totals_[size_t(i) * sources_ + source].merge(cells_[index(i, source, g)]);
    }
    double mean = 0, variance = 0;
    for (int source = 0; source < sources_; ++source) {
        const MeanEstimator& total = totals_[size_t(item) * sources_ + source];
        if (total.allZero()) continue;  // so is every fold of it
        addStratum(heldOut < 0 ? total : total.without(cells_[index(item, source, heldOut)]), mean, variance);
    }
    return {mean / sources_, std::sqrt(variance) / sources_};
}

Estimate ItemEstimates::of(int item) const {
    if (all_.empty()) all_.resize(size_t(items_)), allSet_.assign(size_t(items_), 0);
    if (!allSet_[size_t(item)]) all_[size_t(item)] = stratified(item, -1), allSet_[size_t(item)] = 1;
    return all_[size_t(item)];
}

Estimate ItemEstimates::ofFold(int item, int fold) const {
    double mean = 0, variance = 0;
    for (int source = 0; source < sources_; ++source) addStratum(cells_[index(item, source, fold)], mean, variance);
    return {mean / sources_, std::sqrt(variance) / sources_};
}

void ItemEstimates::changed(int item, int source) {
    if (!allSet_.empty()) allSet_[size_t(item)] = 0;
    if (totals_.empty()) return;
    MeanEstimator& total = totals_[size_t(item) * sources_ + source];
    total = MeanEstimator{};
    for (int g = 0; g < kFolds; ++g) total.merge(cells_[index(item, source, g)]);  // as stratified() first does
}

uint64_t ItemEstimates::pathsInFold(int item, int fold) const {
    uint64_t n = 0;
    for (int source = 0; source < sources_; ++source) n += cells_[index(item, source, fold)].count();
    return n;
}

std::vector<char> PlacedSampler::stillNeeded(const ItemEstimates& items, double, double, double) const {
    return std::vector<char>(size_t(items.items()), kMorePaths);
}

std::unique_ptr<Sensor> PlacedSampler::sensorOf(int /*item*/) const { return nullptr; }

Estimate PlacedSampler::combine(const ItemEstimates& items) const {
    Estimate e;
    int n = 0;
    double sum = 0, var = 0;
    for (int i = 0; i < items.items(); ++i) {
        if (covered(i)) continue;  // not on the task: left out
        Estimate x = items.of(i);
        sum += x.value, var += x.standardError * x.standardError, ++n;
    }
    if (n == 0) return e;  // nothing measured, or every point covered: no light on the task
    e.value = sum / n;
    e.standardError = std::sqrt(var) / n;
    return e;
}

std::vector<char> findCoveredPoints(const PathTracer& tracer, const std::vector<Vec3>& points, Vec3 normal, int carrier) {
    // A point in a closed opaque box (the solid boxes the presets are built of: a
    // monitor's foot) is covered: the tracer reads it 0 (PathTracer::sealedAt). In any
    // other closed solid (a mesh) every ray leaves through a face seen from behind: five
    // rays from 1 mm above the point (along the normal and tilted 27 degrees four ways)
    // must all meet, first, the back of another entity's face. The carrier's own mesh
    // faces (the desk under its work plane) never cover.
    const EmbreeScene& rt = tracer.rayTracer();
    std::vector<char> covered(points.size(), 0);
    const Vec3 n = normalize(normal);
    const Vec3 a = normalize(std::abs(n.z) < 0.9 ? cross(n, Vec3(0, 0, 1)) : cross(n, Vec3(1, 0, 0)));
    const Vec3 b = cross(n, a);
    const Vec3 directions[] = {n, normalize(n + a * 0.5), normalize(n - a * 0.5), normalize(n + b * 0.5),
                               normalize(n - b * 0.5)};
    for (size_t i = 0; i < points.size(); ++i) {
        if (tracer.sealedAt(points[i])) {
            covered[i] = 1;
            continue;
        }
        bool inside = true;
        for (const Vec3& d : directions) {
            Ray ray;
            ray.origin = points[i] + n * 1e-3;
            ray.direction = d;
            const std::optional<Hit> hit = rt.intersect(ray);
            if (!hit || hit->kind != HitKind::Entity || hit->index == carrier || dot(hit->geometricNormal, d) <= 0) {
                inside = false;
                break;
            }
        }
        covered[i] = inside;
    }
    return covered;
}

std::unique_ptr<PlacedSampler> placeSampler(const LightSamplerSpec& s, const PathTracer& tracer) {
    const EmbreeScene& rt = tracer.rayTracer();
    std::unique_ptr<PlacedSampler> placed = s.type->place(s.entity >= 0 ? rt.worldFromEntity(s.entity) : Transform());
    const DaylightEnvironment* daylight = tracer.daylight();
    placed->setSources(int(tracer.emitters().size()), daylight ? int(daylight->sunDisks().size()) : 0);
    Vec3 normal;
    const std::vector<Vec3> probes = placed->coverageProbes(normal);
    if (!probes.empty()) placed->setCovered(findCoveredPoints(tracer, probes, normal, s.entity));
    return placed;
}

std::vector<double> lightSampleFloors(const PathTracer& tracer, double share, uint64_t seed, int pilotPaths) {
    const Scene& scene = tracer.rayTracer().scene();
    std::vector<double> floors(scene.samplers.size(), 0.0);
    if (!(share > 0)) return floors;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        // A survey's paths measure its sources, each on a scale of its own.
        if (scene.samplers[k].type->surveysSources()) continue;
        const std::unique_ptr<PlacedSampler> placed = placeSampler(scene.samplers[k], tracer);
        const int items = placed->items();
        // Per item: the sum of its paths' values, of their squares (in the tracer's
        // unit: what a light sample's worth is compared with), and their count.
        std::vector<std::array<double, 3>> sums(static_cast<size_t>(items));
        parallelFor(size_t(items), [&](size_t item) {
            const double scale = placed->sharesPaths() ? 1.0 / items : 1.0;
            RayStats stats;
            for (int path = 0; path < pilotPaths; ++path) {
                Rng rng(hashValues({seed, kPilotTag, uint64_t(k), uint64_t(item), uint64_t(path)}));
                PathSamples samples(rng);
                PathContributions c(static_cast<int>(item));
                placed->sample(tracer, int(item), samples, stats, PathParams{}, c);
                if (!c.finite()) continue;
                double own = 0;
                for (int j = 0; j < c.size(); ++j)
                    if (c.itemAt(j) == int(item)) own += c.valueAt(j);
                own *= scale;
                sums[item][0] += own, sums[item][1] += own * own, sums[item][2] += 1;
            }
        });
        double mean = 0, variance = 0, counted = 0;
        for (const auto& [sum, squares, n] : sums) {
            if (n < 2) continue;
            const double m = sum / n;
            mean += m, variance += std::max(0.0, (squares - n * m * m) / (n - 1)), counted += 1;
        }
        if (counted > 0 && mean > 0) floors[k] = share * variance / mean;  // both over `counted` items
    }
    return floors;
}

}  // namespace luxplan
