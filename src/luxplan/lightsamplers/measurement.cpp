// measureSamplers in its parts: the work plan (measure_plan.h: what to trace), the
// path source (path_source.h: each path traced afresh or read back), the adaptive
// rounds (Rounds, below: how many paths each item gets, and in what order they are
// traced and added up) and the reducer (reduceSampler: a sampler's result from its
// items' estimates).
#include <luxplan/lightsamplers/light_samplers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <luxplan/core/confidence.h>
#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>
#include <luxplan/core/point_statistics.h>
#include <luxplan/lightsamplers/fresh_paths.h>
#include <luxplan/lightsamplers/measure_plan.h>
#include <luxplan/lightsamplers/path_source.h>

namespace luxplan {
namespace {

constexpr int kFolds = ItemEstimates::kFolds;
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
    uint64_t fresh = 0;  // paths traced afresh (not read back from a path source)
    RayStats stats;

    // Empty again, for `width` items per fold, keeping the folds' memory.
    void reset(size_t width) {
        for (auto& f : folds) f.assign(width, MeanEstimator{});
        std::fill(std::begin(finite), std::end(finite), uint64_t(0));
        dropped = 0;
        fresh = 0;
        stats = RayStats{};
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

// The source of a measurement without one: every path traced afresh, no footprints.
class FreshOnly final : public PathSource {
public:
    void begin(const EmbreeScene&, const std::vector<int>&, uint64_t) override {}
    Path get(size_t work, int path, RayStats& stats, FreshPaths& fresh) override {
        return {&fresh.trace(work, path, stats, false), false, false};
    }
    void used(size_t, int, const Path&, const FootprintView&) override {}
    uint64_t reused() const override { return 0; }
};

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

// The reducer: sampler k's result from its items' estimates and what its work items
// traced (`traced`: paths per work item).
SamplerResult reduceSampler(const WorkPlan& plan, size_t k, const ItemEstimates& e, const std::vector<WorkResult>& done,
                            const std::vector<int>& traced, bool choiceError) {
    const PlacedSampler& placed = *plan.placed[k];
    SamplerResult r;
    for (size_t index = plan.firstWork[k]; index < plan.firstWork[k + 1]; ++index) {
        r.droppedNonFinite += done[index].dropped;
        r.pathsPerPoint = std::max(r.pathsPerPoint, traced[index]);
        r.paths += uint64_t(traced[index]);
        r.freshPaths += done[index].fresh;
    }
    if (plan.firstWork[k + 1] == plan.firstWork[k]) return r;
    for (int i = 0; i < e.items(); ++i) {
        if (placed.covered(i)) {
            r.points.push_back(std::numeric_limits<double>::quiet_NaN());
            r.pointErrors.push_back(std::numeric_limits<double>::quiet_NaN());
            r.covered.push_back(i);
            continue;
        }
        Estimate x = e.of(i);
        r.points.push_back(x.value);
        r.pointErrors.push_back(x.standardError);
    }
    Estimate value = placed.combine(e);
    r.value = value.value;
    r.standardError = choiceError ? placed.reportedError(e, value) : value.standardError;
    r.glare = placed.survey(r.points);
    return r;
}

// The adaptive rounds: each sampler's paths per point up to its next look (one round
// of all when not adaptive: MeasureOptions), a sampler stopping once its value is
// settled, and an item once its sampler no longer needs it (ItemNeed). A sampler's
// stop reads only its own items, so each runs its own rounds, all at once: none waits
// for the others' rounds. Paths are added to their work item in path order, whichever
// thread traced them: the same sums as one round of all paths on one thread.
class Rounds {
public:
    Rounds(const WorkPlan& plan, const MeasureOptions& options, PathSource& source, bool keepsFootprints)
        : plan_(plan), options_(options), source_(source), fresh_(plan, options), keepsFootprints_(keepsFootprints),
          done_(results_.get()), traced_(plan.work.size(), 0), needed_(plan.work.size(), 1), paused_(plan.work.size(), 0) {
        done_.resize(plan.work.size());
        for (size_t index = 0; index < plan.work.size(); ++index) {
            const PlacedSampler& sampler = *plan.placed[size_t(plan.work[index].sampler)];
            done_[index].reset(sampler.sharesPaths() ? size_t(sampler.items()) : 1);
        }
        // A covered point (furniture on the task) is not traced at all.
        for (size_t k = 0; k < plan.samplers(); ++k)
            if (plan.placed[k]->anyCovered() && !plan.placed[k]->sharesPaths())
                for (size_t index = plan.firstWork[k]; index < plan.firstWork[k + 1]; ++index)
                    if (plan.placed[k]->covered(int(index - plan.firstWork[k]))) needed_[index] = 0;
    }

    MeasureResult run(const Scene& scene) {
        MeasureResult result;
        result.samplers.resize(plan_.samplers());
        // Sampler k's result once its paths are all in: on the thread that traced them,
        // while the other samplers still trace (a result's estimates and error take tens
        // of microseconds, and done serially after the rounds they left a core idle).
        parallelFor(plan_.samplers(), [&](size_t k) {
            const ItemEstimates e = roundsOf(k, scene.samplers[k]);
            result.samplers[k] = reduceSampler(plan_, k, e, done_, traced_, options_.choiceError);
        });
        // Sums over the samplers, in a fixed order.
        result.reusedPaths = source_.reused();
        for (size_t k = 0; k < plan_.samplers(); ++k) {
            for (size_t index = plan_.firstWork[k]; index < plan_.firstWork[k + 1]; ++index) {
                result.rays += done_[index].stats;
                result.paths += uint64_t(traced_[index]);
            }
            result.droppedNonFinite += result.samplers[k].droppedNonFinite;
        }
        return result;
    }

private:
    // Paths [from, to) of one work item traced by one thread into a buffer, and merged
    // into the work item by another in path order: a look at a few items (a glare
    // sampler's focused stratum) is split among the threads, with the same sums.
    struct Chunk {
        size_t index = 0;
        int from = 0, to = 0;
        std::vector<PathSource::Path> paths;        // per path; a fresh one's contributions in `traced`
        std::vector<PathContributions> traced;      // the fresh paths, in order
        PathFootprint footprints;                   // their footprints, one after another
        std::vector<std::array<uint32_t, 2>> ends;  // ... each one's end in segments and tests
        std::vector<char> usedEmitterChoice;
        RayStats stats;
    };

    // Sampler k's rounds, to its last look: its items' estimates.
    ItemEstimates roundsOf(size_t k, const LightSamplerSpec& spec);
    // Paths [from, to) of one work item, appended to what its earlier rounds traced.
    void trace(size_t index, int from, int to);
    void traceChunk(Chunk& c);
    void merge(const Chunk& c);
    // What a path added, into its work item's folds (a path with a non-finite value is
    // dropped whole: core/estimator.h's policy).
    void add(size_t index, int path, const PathContributions& c);
    // Sampler k's item estimates: the cells of work item `source` (its own item, or every
    // item of a sampler that shares paths) from what it traced so far.
    void fill(ItemEstimates& e, size_t k, int source) const;
    void countDone(int paths) const {
        if (options_.pathsDone) options_.pathsDone->fetch_add(uint64_t(paths), std::memory_order_relaxed);
    }

    const WorkPlan& plan_;
    const MeasureOptions& options_;
    PathSource& source_;
    FreshPaths fresh_;
    bool keepsFootprints_;  // the source keeps fresh paths' footprints: chunks copy them
    WorkResults results_;
    std::vector<WorkResult>& done_;
    std::vector<int> traced_;              // paths per work item so far
    std::vector<char> needed_, paused_;    // per work item
};

void Rounds::add(size_t index, int path, const PathContributions& c) {
    const WorkItem& w = plan_.work[index];
    const bool shares = plan_.sharesPaths[size_t(w.sampler)];
    WorkResult& r = done_[index];
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
}

void Rounds::trace(size_t index, int from, int to) {
    WorkResult& r = done_[index];
    for (int path = from; path < to; ++path) {
        const PathSource::Path p = source_.get(index, path, r.stats, fresh_);
        source_.used(index, path, p, FreshPaths::footprint().view());
        if (!p.reused) ++r.fresh;
        add(index, path, *p.contributions);
    }
    countDone(to - from);
}

void Rounds::traceChunk(Chunk& c) {
    for (int path = c.from; path < c.to; ++path) {
        PathSource::Path p = source_.get(c.index, path, c.stats, fresh_);
        if (!p.reused) {
            c.traced.push_back(*p.contributions);
            p.contributions = nullptr;  // c.traced's, once merged
            if (keepsFootprints_) {
                const PathFootprint& footprint = FreshPaths::footprint();
                auto& all = c.footprints;
                all.segments.insert(all.segments.end(), footprint.segments.begin(), footprint.segments.end());
                all.tests.insert(all.tests.end(), footprint.tests.begin(), footprint.tests.end());
                c.ends.push_back({uint32_t(all.segments.size()), uint32_t(all.tests.size())});
                c.usedEmitterChoice.push_back(footprint.usedEmitterChoice);
            }
        }
        c.paths.push_back(p);
    }
}

void Rounds::merge(const Chunk& c) {
    WorkResult& r = done_[c.index];
    r.stats += c.stats;
    size_t fresh = 0;
    std::array<uint32_t, 2> start{0, 0};
    for (int path = c.from; path < c.to; ++path) {
        PathSource::Path p = c.paths[size_t(path - c.from)];
        if (p.reused) {
            source_.used(c.index, path, p, {});
            add(c.index, path, *p.contributions);
            continue;
        }
        ++r.fresh;
        p.contributions = &c.traced[fresh];
        FootprintView footprint;
        if (keepsFootprints_) {
            const std::array<uint32_t, 2>& end = c.ends[fresh];
            footprint = {std::span(c.footprints.segments).subspan(start[0], end[0] - start[0]),
                         std::span(c.footprints.tests).subspan(start[1], end[1] - start[1]),
                         bool(c.usedEmitterChoice[fresh])};
            start = end;
        }
        source_.used(c.index, path, p, footprint);
        add(c.index, path, c.traced[fresh++]);
    }
    countDone(c.to - c.from);
}

void Rounds::fill(ItemEstimates& e, size_t k, int source) const {
    const PlacedSampler& sampler = *plan_.placed[k];
    const int n = sampler.items();
    const bool shares = sampler.sharesPaths();
    const WorkResult& w = done_[plan_.firstWork[k] + size_t(source)];
    for (int i = shares ? 0 : source; i < (shares ? n : source + 1); ++i) {
        for (int g = 0; g < kFolds; ++g) {
            // Paths that added nothing to an item count as zeros there.
            MeanEstimator& cell = e.cell(i, shares ? source : 0, g);
            cell = w.folds[g][shares ? size_t(i) : 0];
            cell.addZeros(w.finite[g] - cell.count());
        }
        e.changed(i, shares ? source : 0);
    }
}

ItemEstimates Rounds::roundsOf(size_t k, const LightSamplerSpec& spec) {
    const PlacedSampler& placed = *plan_.placed[k];
    const size_t first = plan_.firstWork[k], end = plan_.firstWork[k + 1];
    const int paths = plan_.paths;
    const int batch = std::max(1, options_.batchPaths);
    int to = !options_.adaptive ? paths : std::min(paths, std::max(options_.minPaths, batch));
    // The items' estimates, refilled after each round for the work items it traced
    // only (a glare sampler's focused stratum is one of sixteen). No paths yet: every
    // cell empty.
    ItemEstimates e(placed.items(), placed.sharesPaths() ? placed.items() : 1);
    for (;;) {
        // Each item from where it stopped: a paused one that resumes catches up.
        std::vector<size_t> round;
        for (size_t index = first; index < end; ++index)
            if (needed_[index] && traced_[index] < to) round.push_back(index);
        if (round.empty()) break;
        const int chunk = options_.chunkPaths;
        if (round.size() >= kSplitBelow || chunk <= 0 || to - traced_[round[0]] <= chunk) {
            parallelFor(round.size(), [&](size_t i) { trace(round[i], traced_[round[i]], to); });
        } else {
            std::vector<Chunk> chunks;
            for (size_t index : round)
                for (int from = traced_[index]; from < to; from += chunk) {
                    Chunk& c = chunks.emplace_back();
                    c.index = index, c.from = from, c.to = std::min(to, from + chunk);
                }
            parallelFor(chunks.size(), [&](size_t i) { traceChunk(chunks[i]); });
            for (const Chunk& c : chunks) merge(c);
        }
        for (size_t index : round) {
            traced_[index] = to;
            fill(e, k, int(index - first));
        }
        if (!options_.adaptive || to == paths) break;
        const Estimate value = placed.combine(e);
        const double zValue = confidenceMultiplier(options_.confidenceZ, value.degreesOfFreedom);
        if (settled(spec, placed, value, e, zValue, options_.confidenceZ)) {
            // At or below the band's top, only with every paused item's paths too.
            const double hi = std::max(value.value + zValue * value.standardError, placed.upperEnd(e, options_.confidenceZ));
            bool resumed = false;
            for (size_t index = first; index < end && hi <= spec.targetMax; ++index)
                if (paused_[index]) paused_[index] = 0, needed_[index] = 1, resumed = true;
            if (!resumed) break;
            continue;  // the same look again, once they have caught up
        }
        const std::vector<char> need = placed.stillNeeded(e, options_.confidenceZ, spec.targetMin, spec.targetMax);
        for (size_t i = 0; i < need.size(); ++i) {
            const size_t index = first + i;
            if (!needed_[index] && !paused_[index]) continue;  // no more paths, for good
            needed_[index] = need[i] == kMorePaths;
            paused_[index] = need[i] == kPaused;
        }
        to = std::min(paths, std::max(to + batch, nextLook(spec, value, to, batch, zValue)));
    }
    return e;
}

}  // namespace

MeasureResult measureSamplers(const PathTracer& tracer, const MeasureOptions& options, PathSource* source,
                              const PathTracer* glareTracer) {
    const EmbreeScene& rt = tracer.rayTracer();
    const WorkPlan plan = planWork(tracer, options, glareTracer);
    FreshOnly freshOnly;
    if (source) source->begin(rt, plan.workSamplers(), hashValues({options.seed, uint64_t(options.lowDiscrepancy)}));
    Rounds rounds(plan, options, source ? *source : freshOnly, source != nullptr);
    return rounds.run(rt.scene());
}

}  // namespace luxplan
