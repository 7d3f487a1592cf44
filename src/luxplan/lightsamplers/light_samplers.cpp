#include <luxplan/lightsamplers/light_samplers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>

#include <luxplan/core/confidence.h>
#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>
#include <luxplan/core/point_statistics.h>

namespace luxplan {
namespace {

// One unit of work: the paths of one item (point or stratum) of one sampler.
struct WorkItem {
    int sampler = 0;
    int item = 0;
};

constexpr int kFolds = ItemEstimates::kFolds;
constexpr uint64_t kSequenceTag = 0x5350'0bb1'5eedULL;  // keys the low-discrepancy sequences
constexpr uint64_t kPilotTag = 0x70696c6f74ULL;            // "pilot": lightSampleFloors' paths
// A look at fewer items than this has each item's paths traced in chunks
// (MeasureOptions::chunkPaths): a glare sampler's focused stratum would otherwise keep
// one core busy while the other idles.
constexpr size_t kSplitBelow = 4;

// What one work item's paths added: per fold an estimator for each item they reach
// (the own item only, or all of a sampler that shares paths).
struct alignas(64) WorkResult {  // a cache line of its own: two threads trace neighbouring items
    std::array<std::vector<MeanEstimator>, kFolds> folds;
    uint64_t finite[kFolds] = {};  // paths kept, per fold
    uint64_t dropped = 0;
    uint64_t fresh = 0;  // paths traced afresh (not read from the path cache)
    RayStats stats;
    CacheCheck check;  // MeasureOptions::checkCache (its rays are not counted in `stats`)

    // Empty again, for `width` items per fold, keeping the folds' memory.
    void reset(size_t width) {
        for (auto& f : folds) f.assign(width, MeanEstimator{});
        std::fill(std::begin(finite), std::end(finite), uint64_t(0));
        dropped = 0;
        fresh = 0;
        stats = RayStats{};
        check = CacheCheck{};
    }
};

// The work items' results of one measurement, kept on each thread for the next: a search
// measures thousands of layouts, and the office's 144 work items hold 1152 fold vectors,
// whose allocation and release ran on one thread before and after the rounds, the other
// core waiting (1% of the search's profile). A measurement inside another on the same
// thread gets its own.
class WorkResults {
public:
    WorkResults() : mine_(!kept().taken) {
        if (mine_) kept().taken = true;
    }
    ~WorkResults() {
        if (mine_) kept().taken = false;
    }
    WorkResults(const WorkResults&) = delete;
    WorkResults& operator=(const WorkResults&) = delete;
    std::vector<WorkResult>& get() { return mine_ ? kept().results : own_; }

private:
    struct Kept {
        std::vector<WorkResult> results;
        bool taken = false;
    };
    static Kept& kept() {
        thread_local Kept k;
        return k;
    }
    bool mine_;
    std::vector<WorkResult> own_;
};

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
                placed->sample(tracer, int(item), samples, stats, c);
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

namespace {

// [lo, hi] lies inside one linear piece of a term's penalty.
bool settled(double lo, double hi, double targetMin, double targetMax) {
    return hi <= targetMin || (lo >= targetMin && hi <= targetMax) || lo >= targetMax;
}
// ... value +- z standard errors.
bool settled(double value, double standardError, double targetMin, double targetMax, double z) {
    return settled(value - z * standardError, value + z * standardError, targetMin, targetMax);
}

// ... for the sampler's value, at zValue errors (as many as its error's degrees of
// freedom ask: core/confidence.h), from the sampler's lower end up to its upper end
// at z where they say more (PlacedSampler::lowerEnd, upperEnd), and each of its
// statistics goals, at z. The value itself must lie in that piece too: its penalty is
// read there. (A stratum's lower end can clear a glare bound while the cross-fitted
// value, which chose among near-equal heavy-tailed strata, reads below it: in the
// office 95.9 cd/m2 against a bound of 100, its brightest strata at 170 and a truth of
// 172; the penalty read 0.)
bool settled(const LightSamplerSpec& spec, const PlacedSampler& sampler, const Estimate& e, const ItemEstimates& items,
             double zValue, double z) {
    const double hi = std::max(e.value + zValue * e.standardError, sampler.upperEnd(items, z));
    const double lo = std::min(std::max(e.value - zValue * e.standardError, sampler.lowerEnd(items, z)), e.value);
    if (!settled(lo, hi, spec.targetMin, spec.targetMax)) return false;
    if (spec.statistics.empty()) return true;
    std::vector<double> values, errors;
    for (int i = 0; i < items.items(); ++i) {
        const Estimate x = items.of(i);
        values.push_back(x.value), errors.push_back(x.standardError);
    }
    const PointStatistics stats = pointStatistics(values, errors);
    for (const StatisticGoal& goal : spec.statistics) {
        const StatisticEstimate& s = stats.of(goal.statistic);
        if (!settled(s.value, s.standardError, goal.targetMin, goal.targetMax, z)) return false;
    }
    return true;
}

// Where the next look at a sampler that is not settled should come: where its interval,
// narrowing as 1 / sqrt(paths), would clear the nearest bound of its band; at least a
// round on and at most about a quarter more paths (rounded up to whole rounds: a wider
// step overshoots the stop). Fewer looks cost fewer estimates and give the data fewer
// chances to stop by luck. A settled value whose statistics goals are not asks for the
// next round.
// zValue is the value's multiplier, as settled() takes it.
int nextLook(const LightSamplerSpec& spec, const Estimate& value, int paths, int batch, double zValue) {
    double gap = kInf;
    for (double bound : {spec.targetMin, spec.targetMax})
        if (std::isfinite(bound)) gap = std::min(gap, std::abs(value.value - bound));
    const double width = zValue * value.standardError;
    double want = gap > 0 && gap < kInf ? paths * (width / gap) * (width / gap) : 2.0 * paths;
    if (!(want == want)) want = 1.25 * paths;  // a NaN error: the widest step
    want = std::clamp(want, double(paths + batch), std::max(double(paths + batch), 1.25 * paths));
    return int(std::ceil(want / batch)) * batch;
}

// The kept path's point where a fresh trace of it first differs (MeasureOptions::checkCache).
std::optional<Vec3> wherePathsPart(std::span<const Segment> kept, const std::vector<Segment>& fresh) {
    auto point = [](const std::array<float, 3>& p) { return Vec3{p[0], p[1], p[2]}; };
    for (size_t q = 0; q < kept.size(); ++q)
        if (q >= fresh.size() || kept[q].from != fresh[q].from || kept[q].to != fresh[q].to) return point(kept[q].from);
    if (fresh.size() > kept.size()) return point(fresh[kept.size()].from);
    return std::nullopt;
}

}  // namespace

MeasureResult measureSamplers(const PathTracer& tracer, const MeasureOptions& options, PathCache* cache,
                              const PathTracer* glareTracer) {
    const EmbreeScene& rt = tracer.rayTracer();
    const Scene& scene = rt.scene();
    const size_t samplers = scene.samplers.size();
    std::vector<std::unique_ptr<PlacedSampler>> placed;
    std::vector<WorkItem> work;
    std::vector<size_t> firstWork;  // per sampler
    for (size_t k = 0; k < samplers; ++k) {
        placed.push_back(placeSampler(scene.samplers[k], tracer));
        firstWork.push_back(work.size());
        for (int i = 0; i < placed.back()->items(); ++i) work.push_back({int(k), i});
    }
    firstWork.push_back(work.size());
    std::vector<const PathTracer*> tracerOf(samplers, &tracer);
    if (glareTracer)
        for (size_t k = 0; k < samplers; ++k)
            if (scene.samplers[k].type->surveysSources()) tracerOf[k] = glareTracer;
    if (!options.lightFloors.empty() && options.lightFloors.size() != samplers)
        throw std::logic_error("MeasureOptions::lightFloors: one per sampler of the scene");
    std::vector<double> lightFloorOf = options.lightFloors;
    lightFloorOf.resize(samplers, 0.0);
    if (cache) {
        std::vector<int> workSampler;
        for (const WorkItem& w : work) workSampler.push_back(w.sampler);
        cache->begin(rt, workSampler, hashValues({options.seed, uint64_t(options.lowDiscrepancy)}));
    }
    WorkResults workResults;
    std::vector<WorkResult>& done = workResults.get();
    done.resize(work.size());
    for (size_t index = 0; index < work.size(); ++index) {
        const PlacedSampler& sampler = *placed[size_t(work[index].sampler)];
        done[index].reset(sampler.sharesPaths() ? size_t(sampler.items()) : 1);
    }
    const int paths = std::max(1, options.pathsPerPoint);

    // What a path added, into its work item's folds (a path with a non-finite value is
    // dropped whole: core/estimator.h's policy).
    std::vector<char> sharesPaths(samplers);
    for (size_t k = 0; k < samplers; ++k) sharesPaths[k] = placed[k]->sharesPaths();
    auto add = [&](size_t index, int path, const PathContributions& c) {
        const WorkItem& w = work[index];
        const bool shares = sharesPaths[size_t(w.sampler)];
        WorkResult& r = done[index];
        if (!c.finite()) {
            ++r.dropped;
            return;
        }
        auto& fold = r.folds[size_t(path % kFolds)];
        ++r.finite[path % kFolds];
        for (int k = 0; k < c.size(); ++k) {
            if (!shares && c.itemAt(k) != w.item)
                throw std::logic_error("a light sampler that does not share paths added to another item");
            fold[shares ? size_t(c.itemAt(k)) : 0].add(c.valueAt(k));
        }
    };
    // Paths [from, to) of one work item: each read back from the cache or traced
    // afresh, and handed in order to onPath(path, cached or null, askedAgain, traced,
    // footprint), `traced` and `footprint` holding the fresh path where cached is null.
    auto tracePaths = [&](size_t index, int from, int to, RayStats& stats, CacheCheck& check, auto&& onPath) {
        const WorkItem& w = work[index];
        const PlacedSampler& sampler = *placed[size_t(w.sampler)];
        // The item's low-discrepancy sequence (one per fold for types that compare folds).
        const bool folds = sampler.independentFolds();
        // Each thread's buffers (the sequences and the footprint below) keep their memory
        // from one call to the next: a measurement makes thousands of these calls, each a
        // few paths long, and their allocations showed in the search's profile. No call
        // nests in another on the same thread (a path's tracing waits on no task). The
        // sequences are made at the first path traced afresh: about half the calls read
        // every path back from the cache.
        thread_local std::vector<PathSamples::Sequence> sequences;
        sequences.clear();
        auto samplesOf = [&](int path, Rng& rng) {
            if (!options.lowDiscrepancy) return PathSamples(rng);
            if (sequences.empty())
                for (int g = 0; g < (folds ? kFolds : 1); ++g)
                    sequences.emplace_back(hashValues({options.seed, kSequenceTag, uint64_t(w.sampler), uint64_t(w.item),
                                                       folds ? uint64_t(g) : uint64_t(kFolds)}));
            return PathSamples(rng, sequences[folds ? size_t(path % kFolds) : 0], uint32_t(folds ? path / kFolds : path));
        };
        const double lightFloor = lightFloorOf[size_t(w.sampler)];
        auto rngOf = [&](int path) { return Rng(hashValues({options.seed, uint64_t(w.sampler), uint64_t(w.item), uint64_t(path)})); };
        thread_local PathFootprint scratch;  // a path's footprint as it is traced
        PathContributions traced(w.item);  // ... and what it added
        for (int path = from; path < to; ++path) {
            bool askedAgain = false;
            const PathContributions* cached = cache ? cache->holds(index, path, askedAgain) : nullptr;
            if (!cached) {
                traced = PathContributions(w.item);
                Rng rng = rngOf(path);
                PathSamples samples = samplesOf(path, rng);
                samples.setLightFloor(lightFloor);
                if (cache) {
                    scratch.clear();
                    stats.footprint = &scratch;
                }
                sampler.sample(*tracerOf[size_t(w.sampler)], w.item, samples, stats, traced);
                stats.footprint = nullptr;
            } else if (options.checkCache) {
                PathContributions fresh(w.item);
                Rng rng = rngOf(path);
                PathSamples samples = samplesOf(path, rng);
                samples.setLightFloor(lightFloor);
                RayStats uncounted;
                scratch.clear();  // onPath reads it only for a path traced afresh
                uncounted.footprint = &scratch;
                sampler.sample(*tracerOf[size_t(w.sampler)], w.item, samples, uncounted, fresh);
                ++check.checked;
                if (!fresh.sameAs(*cached))
                    check.note({0, w.sampler, w.item, path, cached->sum(), fresh.sum(),
                                wherePathsPart(cache->segmentsOf(index, path), scratch.segments)});
            }
            onPath(path, cached, askedAgain, traced, scratch);
        }
    };
    // Paths [from, to) of one work item, appended to what its earlier rounds traced:
    // the same sums in the same order as one round of all paths.
    auto trace = [&](size_t index, int from, int to) {
        WorkResult& r = done[index];
        tracePaths(index, from, to, r.stats, r.check,
                   [&](int path, const PathContributions* cached, bool askedAgain, const PathContributions& traced,
                       const PathFootprint& footprint) {
                       if (cache) {
                           cache->visit(index, path, cached != nullptr, askedAgain);
                           if (!cached) cache->keep(index, path, traced, footprint.view());
                       }
                       if (!cached) ++r.fresh;
                       add(index, path, cached ? *cached : traced);
                   });
        if (options.pathsDone) options.pathsDone->fetch_add(uint64_t(to - from), std::memory_order_relaxed);
    };
    // Paths [from, to) of one work item traced by one thread into a buffer, and merged
    // into the work item by another in path order: a look at a few items (a glare
    // sampler's focused stratum) is split among the threads, with the same sums.
    struct Chunk {
        size_t index = 0;
        int from = 0, to = 0;
        std::vector<const PathContributions*> cached;  // per path; null: traced afresh
        std::vector<char> askedAgain;                  // per path
        std::vector<PathContributions> traced;         // the fresh paths, in order
        PathFootprint footprints;                      // their footprints, one after another
        std::vector<std::array<uint32_t, 2>> ends;     // ... each one's end in segments and tests
        std::vector<char> usedEmitterChoice;
        RayStats stats;
        CacheCheck check;
    };
    auto traceChunk = [&](Chunk& c) {
        tracePaths(c.index, c.from, c.to, c.stats, c.check,
                   [&](int, const PathContributions* cached, bool askedAgain, const PathContributions& traced,
                       const PathFootprint& footprint) {
                       c.cached.push_back(cached);
                       c.askedAgain.push_back(askedAgain);
                       if (cached) return;
                       c.traced.push_back(traced);
                       if (!cache) return;
                       auto& all = c.footprints;
                       all.segments.insert(all.segments.end(), footprint.segments.begin(), footprint.segments.end());
                       all.tests.insert(all.tests.end(), footprint.tests.begin(), footprint.tests.end());
                       c.ends.push_back({uint32_t(all.segments.size()), uint32_t(all.tests.size())});
                       c.usedEmitterChoice.push_back(footprint.usedEmitterChoice);
                   });
    };
    auto merge = [&](const Chunk& c) {
        WorkResult& r = done[c.index];
        r.stats += c.stats;
        r.check.add(c.check);
        size_t fresh = 0;
        std::array<uint32_t, 2> start{0, 0};
        for (int path = c.from; path < c.to; ++path) {
            const PathContributions* cached = c.cached[size_t(path - c.from)];
            if (cache) cache->visit(c.index, path, cached != nullptr, c.askedAgain[size_t(path - c.from)]);
            if (cached) {
                add(c.index, path, *cached);
                continue;
            }
            ++r.fresh;
            if (cache) {
                const std::array<uint32_t, 2>& end = c.ends[fresh];
                const FootprintView footprint{
                    std::span(c.footprints.segments).subspan(start[0], end[0] - start[0]),
                    std::span(c.footprints.tests).subspan(start[1], end[1] - start[1]), bool(c.usedEmitterChoice[fresh])};
                cache->keep(c.index, path, c.traced[fresh], footprint);
                start = end;
            }
            add(c.index, path, c.traced[fresh++]);
        }
        if (options.pathsDone) options.pathsDone->fetch_add(uint64_t(c.to - c.from), std::memory_order_relaxed);
    };

    // Sampler k's item estimates: the cells of work item `source` (its own item, or every
    // item of a sampler that shares paths) from what it traced so far.
    auto fill = [&](ItemEstimates& e, size_t k, int source) {
        const PlacedSampler& sampler = *placed[k];
        const int n = sampler.items();
        const bool shares = sampler.sharesPaths();
        const WorkResult& w = done[firstWork[k] + size_t(source)];
        for (int i = shares ? 0 : source; i < (shares ? n : source + 1); ++i) {
            for (int g = 0; g < kFolds; ++g) {
                // Paths that added nothing to an item count as zeros there.
                MeanEstimator& cell = e.cell(i, shares ? source : 0, g);
                cell = w.folds[g][shares ? size_t(i) : 0];
                cell.addZeros(w.finite[g] - cell.count());
            }
            e.changed(i, shares ? source : 0);
        }
    };

    // Rounds of paths per point up to the next look (one round of all when not
    // adaptive: MeasureOptions); a sampler stops once its value is settled, and an item
    // once its sampler no longer needs it (ItemNeed). A sampler's stop reads only its own
    // items, so each runs its own rounds, all at once: none waits for the others' rounds.
    std::vector<int> traced(work.size(), 0);
    std::vector<char> needed(work.size(), 1), paused(work.size(), 0);
    // A covered point (furniture on the task) is not traced at all.
    for (size_t k = 0; k < samplers; ++k)
        if (placed[k]->anyCovered() && !placed[k]->sharesPaths())
            for (size_t index = firstWork[k]; index < firstWork[k + 1]; ++index)
                if (placed[k]->covered(int(index - firstWork[k]))) needed[index] = 0;
    // Sampler k's result once its paths are all in: on the thread that traced them, while
    // the other samplers still trace (a result's estimates and error take tens of
    // microseconds, and done serially after the rounds they left a core idle).
    MeasureResult result;
    result.samplers.resize(samplers);
    auto finish = [&](size_t k, const ItemEstimates& e) {
        SamplerResult& r = result.samplers[k];
        for (size_t index = firstWork[k]; index < firstWork[k + 1]; ++index) {
            r.droppedNonFinite += done[index].dropped;
            r.pathsPerPoint = std::max(r.pathsPerPoint, traced[index]);
            r.paths += uint64_t(traced[index]);
            r.freshPaths += done[index].fresh;
        }
        if (firstWork[k + 1] == firstWork[k]) return;
        for (int i = 0; i < e.items(); ++i) {
            if (placed[k]->covered(i)) {
                r.points.push_back(std::numeric_limits<double>::quiet_NaN());
                r.pointErrors.push_back(std::numeric_limits<double>::quiet_NaN());
                r.covered.push_back(i);
                continue;
            }
            Estimate x = e.of(i);
            r.points.push_back(x.value);
            r.pointErrors.push_back(x.standardError);
        }
        Estimate value = placed[k]->combine(e);
        r.value = value.value;
        r.standardError = options.choiceError ? placed[k]->reportedError(e, value) : value.standardError;
        r.glare = placed[k]->survey(r.points);
    };
    parallelFor(samplers, [&](size_t k) {
        const int batch = std::max(1, options.batchPaths);
        int to = !options.adaptive ? paths : std::min(paths, std::max(options.minPaths, batch));
        // The items' estimates, refilled after each round for the work items it traced
        // only (a glare sampler's focused stratum is one of sixteen). No paths yet: every
        // cell empty.
        ItemEstimates e(placed[k]->items(), placed[k]->sharesPaths() ? placed[k]->items() : 1);
        for (;;) {
            // Each item from where it stopped: a paused one that resumes catches up.
            std::vector<size_t> round;
            for (size_t index = firstWork[k]; index < firstWork[k + 1]; ++index)
                if (needed[index] && traced[index] < to) round.push_back(index);
            if (round.empty()) break;
            const int chunk = options.chunkPaths;
            if (round.size() >= kSplitBelow || chunk <= 0 || to - traced[round[0]] <= chunk) {
                parallelFor(round.size(), [&](size_t i) { trace(round[i], traced[round[i]], to); });
            } else {
                std::vector<Chunk> chunks;
                for (size_t index : round)
                    for (int from = traced[index]; from < to; from += chunk) {
                        Chunk& c = chunks.emplace_back();
                        c.index = index, c.from = from, c.to = std::min(to, from + chunk);
                    }
                parallelFor(chunks.size(), [&](size_t i) { traceChunk(chunks[i]); });
                for (const Chunk& c : chunks) merge(c);
            }
            for (size_t index : round) {
                traced[index] = to;
                fill(e, k, int(index - firstWork[k]));
            }
            if (!options.adaptive || to == paths) break;
            const Estimate value = placed[k]->combine(e);
            const double zValue = confidenceMultiplier(options.confidenceZ, value.degreesOfFreedom);
            const LightSamplerSpec& spec = scene.samplers[k];
            if (settled(spec, *placed[k], value, e, zValue, options.confidenceZ)) {
                // At or below the band's top, only with every paused item's paths too.
                const double hi = std::max(value.value + zValue * value.standardError,
                                           placed[k]->upperEnd(e, options.confidenceZ));
                bool resumed = false;
                for (size_t index = firstWork[k]; index < firstWork[k + 1] && hi <= spec.targetMax; ++index)
                    if (paused[index]) paused[index] = 0, needed[index] = 1, resumed = true;
                if (!resumed) break;
                continue;  // the same look again, once they have caught up
            }
            const std::vector<char> need = placed[k]->stillNeeded(e, options.confidenceZ, spec.targetMin, spec.targetMax);
            for (size_t i = 0; i < need.size(); ++i) {
                const size_t index = firstWork[k] + i;
                if (!needed[index] && !paused[index]) continue;  // no more paths, for good
                needed[index] = need[i] == kMorePaths;
                paused[index] = need[i] == kPaused;
            }
            to = std::min(paths, std::max(to + batch, nextLook(spec, value, to, batch, zValue)));
        }
        finish(k, e);
    });

    // Sums over the samplers, in a fixed order.
    if (cache) result.reusedPaths = cache->reused();
    result.cacheCheck.on = cache && options.checkCache;
    for (const WorkResult& w : done) result.cacheCheck.add(w.check);
    for (size_t k = 0; k < samplers; ++k) {
        for (size_t index = firstWork[k]; index < firstWork[k + 1]; ++index) {
            result.rays += done[index].stats;
            result.paths += uint64_t(traced[index]);
        }
        result.droppedNonFinite += result.samplers[k].droppedNonFinite;
    }
    return result;
}

}  // namespace luxplan
