// Hierarchical Metropolis over layouts: start state, level schedule, proposals,
// geometric gate, lighting hook, acceptance and the best layout.
#include <luxplan/optimizer/optimizer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <luxplan/constraints/penalty.h>
#include <luxplan/core/parallel.h>
#include <luxplan/optimizer/placement.h>

namespace luxplan {
namespace {

constexpr uint64_t kStreamTag = 0x6c75786f7074ULL;  // "luxopt": the optimizer's random streams
constexpr uint64_t kStartStream = 0, kGroupStream = 1, kObjectStream = 2, kFlatStream = 3;
constexpr int kTraceRows = 10000;
// Independent measurements (LightingEvaluator::measureIndependently): the selection's
// and the report's seeds, drawn apart from the search's.
constexpr uint64_t kIndependentTag = 0x696e646570ULL;  // "indep"
constexpr uint64_t kSelectionStream = 1, kReportStream = 2;
// The noise floor follows the last ~64 lighting evaluations.
constexpr double kNoiseMemory = 1.0 / 64;
constexpr uint64_t kPolishStream = 4, kPlanStream = 5;
// The plans' traced looks: independent measurements, apart from the selection's and the report's.
constexpr uint64_t kLookStream = 3;
// The plans that run at once (Optimizer::plannedStart): a constant, not the thread count,
// so that a seed gives the same plan on every machine.
constexpr int kPlansAtOnce = 2;
// The light surrogate's cells (m): a desk's task grid spans several.
constexpr double kSurrogateCell = 0.25;
// The polish's step scales, times MoveOptions::sigmaFraction: 5%, 1% and 0.25% of a
// region's extent (7 m: 35 cm, 7 cm, 2 cm).
constexpr double kPolishScales[] = {0.2, 0.04, 0.01};

}  // namespace

const char* stopReasonName(StopReason reason) {
    switch (reason) {
        case StopReason::Iterations: return "iterations";
        case StopReason::ZeroCost: return "zero_cost";
        case StopReason::Cancelled: return "cancelled";
        case StopReason::NothingToMove: return "nothing_to_move";
    }
    return "?";
}

double Schedule::temperature(int iteration, int iterations) const {
    if (kind == Kind::Constant || iterations <= 1) return start;
    double t = std::clamp(double(iteration) / double(iterations - 1), 0.0, 1.0);
    return start * std::pow(end / start, t);
}

OptimizerOptions optimizerOptions(const OptimizerSettings& s) {
    OptimizerOptions o;
    o.iterations = s.iterations;
    o.seed = s.seed;
    o.hierarchy = s.flat || s.flatScene ? Hierarchy::Flat : Hierarchy::Hierarchical;
    o.innerIterations = s.innerIterations;
    o.focusInner = s.nested && !s.cycle;
    o.schedule.kind = s.constantTemperature ? Schedule::Kind::Constant : Schedule::Kind::Geometric;
    o.schedule.start = s.temperatureStart;
    o.schedule.end = s.temperatureEnd;
    o.start = s.startFromScene ? StartFrom::Scene : StartFrom::Uniform;
    o.polishShare = s.polishShare;
    o.restartShare = s.restartShare;
    o.restartTemperature = s.temperatureStart / 5;
    o.guidedMoves = s.guided;
    o.planIterations = s.planIterations;
    o.plans = s.plans;
    o.suggestions = s.suggestions;
    o.marginZ = s.margin;
    o.adaptiveShare = s.adaptiveShare;
    o.noiseAware = !s.noiseBlind;
    o.delayedAcceptance = !s.singleTest;
    o.snapshots = s.snapshots;
    return o;
}

Optimizer::Optimizer(const Scene& scene, OptimizerOptions options, LightingEvaluator* lighting)
    : scene_(&scene), options_(options), lighting_(lighting), geometry_(scene),
      candidates_(scene, options.candidates, options.candidateSeparation),
      suggestions_(scene, std::max(1, options.suggestions), options.suggestionSeparation) {
    auto check = [](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(std::string("optimizer options: ") + what);
    };
    check(options_.iterations >= 0, "iterations must be >= 0");
    check(options_.innerIterations >= 0, "inner iterations must be >= 0 (0: by degrees of freedom)");
    check(options_.schedule.start > 0 && options_.schedule.end > 0, "temperatures must be > 0");
    check(options_.startAttempts >= 1, "start attempts must be >= 1");
    check(options_.moves.sigmaFraction > 0, "sigma fraction must be > 0");
    check(options_.progressEvery >= 1, "progress interval must be >= 1");
    check(options_.traceEvery >= 0, "trace interval must be >= 0");
    check(options_.snapshots >= 0, "snapshots must be >= 0");
    check(options_.candidates >= 1, "candidates must be >= 1");
    check(options_.candidateSeparation.metres >= 0 && options_.candidateSeparation.degrees >= 0,
          "candidate separation must be >= 0");
    check(options_.polishShare >= 0 && options_.polishShare < 1, "polish share must be in [0, 1)");
    check(options_.restartShare >= 0 && options_.restartShare < 1, "restart share must be in [0, 1)");
    check(options_.restartTemperature > 0, "restart temperature must be > 0");
    check(options_.suggestions >= 0, "suggestions must be >= 0");
    check(options_.planIterations >= 0 && options_.planPaths >= 1, "plan iterations must be >= 0 and plan paths >= 1");
    check(options_.plans >= 1, "plans must be >= 1");
    check(options_.start != StartFrom::Given ||
              (options_.startLayout && options_.startLayout->placements.size() == scene.entities.size()),
          "a given start needs a layout of every entity");

    check(options_.marginZ >= 0 && std::isfinite(options_.marginZ), "margin must be a finite number >= 0");
    if (lighting_) lighting_->setSearchMargin(options_.marginZ);
    std::vector<int> all, outer, inner;
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        if (!scene.entities[i].movable()) continue;
        all.push_back(int(i));
        (scene.entities[i].parent < 0 ? outer : inner).push_back(int(i));
    }
    if (options_.guidedMoves && lighting_ && !scene.samplers.empty() && scene.objective.lightingWeight > 0) {
        lightMap_ = std::make_unique<LightMap>(scene, all, options_.lightMap);
        if (lightMap_->empty()) lightMap_.reset();
    }
    if (options_.planIterations > 0 && options_.start == StartFrom::Uniform && lighting_ && !scene.samplers.empty() &&
        scene.objective.lightingWeight > 0 && options_.schedule.kind == Schedule::Kind::Geometric) {
        surrogate_ = std::make_unique<LightSurrogate>(scene, kSurrogateCell);
        if (surrogate_->empty()) surrogate_.reset();
    }
    auto addLevel = [&](const char* name, const std::vector<int>& entities, uint64_t stream) {
        MoveSet moves(scene, entities, options_.moves, lightMap_.get());
        if (moves.empty()) return;
        levels_.push_back(std::move(moves));
        stats_.push_back({name, entities, {}});
        rngs_.emplace_back(hashValues({options_.seed, kStreamTag, stream}));
        streams_.push_back(stream);
    };
    if (options_.hierarchy == Hierarchy::Flat) {
        addLevel("flat", all, kFlatStream);
    } else {
        addLevel("group", outer, kGroupStream);
        addLevel("object", inner, kObjectStream);
    }
    if (levels_.size() == 2) setUpNesting(outer, inner);
    // A constant schedule is a plain Metropolis chain (the tests sample its law): no polish.
    if (options_.polishShare > 0 && !all.empty() && options_.schedule.kind == Schedule::Kind::Geometric) {
        MoveOptions fine = options_.moves;
        fine.polish = true;
        fine.stepScales.assign(std::begin(kPolishScales), std::end(kPolishScales));
        MoveSet polish(scene, all, fine);
        if (!polish.empty()) polishSets_.push_back(std::move(polish));
    }
    traceEvery_ = options_.traceEvery > 0 ? options_.traceEvery : std::max(1, options_.iterations / kTraceRows);
}

Evaluation Optimizer::evaluate(const Layout& layout, const std::vector<Transform>& world) {
    Evaluation e = evaluateGeometry(world);
    // Section 3: the lighting term only for layouts that pass the geometric test.
    if (!e.rejected) addLighting(e, layout, world);
    return e;
}

Evaluation Optimizer::evaluateGeometry(const std::vector<Transform>& world) {
    GeometryResult g = geometry_.evaluate(world);
    Evaluation e;
    e.geometry = g.cost;
    e.rejected = g.rejected;
    e.violation = g.violation;
    e.rejectedBy = std::move(g.rejectedBy);
    e.cost = scene_->objective.cost(e.lighting, e.geometry);
    return e;
}

void Optimizer::addLighting(Evaluation& e, const Layout& layout, const std::vector<Transform>& world) {
    const double w = scene_->objective.lightingWeight;
    if (lighting_ && !scene_->samplers.empty() && w > 0) {
        e.lighting = lighting_->evaluate(layout, world, &e.samplers);
        ++lightingEvaluations_;
        e.lightingEvaluated = true;
        e.costError = costError(e);
        if (lightMap_) lightMap_->observe(layout, e.samplers.samplers);
        const auto& measured = e.samplers.samplers;
        if (measured.size() == scene_->samplers.size()) {
            samplerRanges_.resize(measured.size());
            for (size_t k = 0; k < measured.size(); ++k) samplerRanges_[k].add(scene_->samplers[k], measured[k].value, measured[k].standardError);
        }
    }
    e.cost = scene_->objective.cost(e.lighting, e.geometry);
}

uint64_t Optimizer::independentSeed(uint64_t stream) const {
    // 53 bits, so that JSON readers that hold numbers as doubles keep it exact; never 0.
    return (hashValues({options_.seed, kIndependentTag, stream}) & ((uint64_t(1) << 53) - 1)) | 1;
}

double Optimizer::costError(const Evaluation& e) const {
    // An evaluator that gives no per-sampler breakdown gives no error either.
    if (e.samplers.samplers.size() != scene_->samplers.size()) return 0.0;
    return scene_->objective.lightingWeight * lightingCostError(*scene_, e.samplers.samplers);
}

double Optimizer::differenceVariance(const Evaluation& a, const Evaluation& b) const {
    if (!a.lightingEvaluated || !b.lightingEvaluated) return a.costError * a.costError + b.costError * b.costError;
    // A sampler that reads the same in both did not change (the path cache reused its
    // paths, or nothing it sees moved): it adds nothing to the difference. The others
    // count as independent estimates, which overstates the difference's noise when
    // they share paths (common random numbers): the test is then the stricter.
    const double w = scene_->objective.lightingWeight;
    // Of a changed sampler, only the paths `b` traced afresh can differ from `a`'s (the
    // rest are read from the path cache, the same numbers): their share of its variance
    // counts, and those are counted as independent of `a`'s, an upper bound (they share
    // random numbers). An evaluation that traced every path (no cache, fresh noise) counts whole.
    double variance = 0;
    const auto &x = a.samplers.samplers, &y = b.samplers.samplers;
    if (x.size() != scene_->samplers.size() || y.size() != x.size()) return 0.0;
    for (size_t k = 0; k < x.size(); ++k) {
        if (x[k].value == y[k].value) continue;
        const double share = y[k].paths > 0 ? std::min(1.0, double(y[k].freshPaths) / double(y[k].paths)) : 1.0;
        const double ex = w * lightingTermError(*scene_, k, x[k]), ey = w * lightingTermError(*scene_, k, y[k]);
        variance += share * (ex * ex + ey * ey);
    }
    return variance;
}

bool Optimizer::metropolis(const Evaluation& proposed, double logHastings, double temperature, Rng& rng) const {
    // Metropolis-Hastings: min(1, exp(-(C' - C) / T) q(x'->x) / q(x->x')).
    double logA = -(proposed.cost - currentEval_.cost) / temperature + logHastings;
    // The penalty method (Ceperley and Dewing 1999) when both ends are fresh estimates:
    // -s^2 / (2 T^2), s^2 the variance of the estimated difference, keeps detailed
    // balance for the true costs where the plain test favours lucky draws. With common
    // random numbers the estimates are a fixed function of the layout, for which the
    // plain test is exact (the chain samples exp(-C_estimated / T)) and the penalty
    // would not be: a(d) / a(-d) = exp(-d / T) fails for |d| < s^2 / (2 T).
    if (options_.noiseAware && lighting_ && lighting_->drawsAnew())
        logA -= differenceVariance(currentEval_, proposed) / (2 * temperature * temperature);
    return logA >= 0 || rng.uniform() < std::exp(logA);
}

bool Optimizer::geometricStage(const Evaluation& proposed, double logHastings, double temperature, Rng& rng) const {
    const double w = scene_->objective.lightingWeight;
    const double logA = -(1 - w) * (proposed.geometry - currentEval_.geometry) / temperature + logHastings;
    return logA >= 0 || rng.uniform() < std::exp(logA);
}

bool Optimizer::lightingStage(const Evaluation& proposed, double temperature, Rng& rng) const {
    // The full test's ratio over the first stage's: exp(-w dL / T), the geometric part
    // and the proposal ratio already tested.
    const double w = scene_->objective.lightingWeight;
    double logA = -w * (proposed.lighting - currentEval_.lighting) / temperature;
    if (options_.noiseAware && lighting_ && lighting_->drawsAnew())
        logA -= differenceVariance(currentEval_, proposed) / (2 * temperature * temperature);
    return logA >= 0 || rng.uniform() < std::exp(logA);
}

void Optimizer::refreshCurrent() {
    // The penalty method tests a fresh estimate of the difference: both ends drawn anew.
    Evaluation& e = currentEval_;
    e.lighting = lighting_->evaluate(current_, worldTransforms(*scene_, current_), &e.samplers);
    ++lightingEvaluations_;
    lighting_->commit();
    e.costError = costError(e);
    e.cost = scene_->objective.cost(e.lighting, e.geometry);
}

void Optimizer::noteNoise(const Evaluation& proposed) {
    if (!proposed.lightingEvaluated || !currentEval_.lightingEvaluated) return;
    // The noise of the decision the test makes: that of the estimated difference.
    const double v = differenceVariance(currentEval_, proposed);
    ++noiseCount_;
    noiseVariance_ += (v - noiseVariance_) * std::max(kNoiseMemory, 1.0 / double(noiseCount_));
}

void Optimizer::noteYield(int level, double gain, uint64_t paths) {
    if (level < 0 || level > 1) return;
    const size_t l = size_t(level);
    ++yieldCount_[l];
    const double w = std::max(1.0 / 200, 1.0 / double(yieldCount_[l]));
    yieldGain_[l] += (gain - yieldGain_[l]) * w;
    yieldPaths_[l] += (double(paths) - yieldPaths_[l]) * w;
}

int Optimizer::objectSteps(Rng& rng) const {
    constexpr int64_t kFirst = 50;
    if (!options_.adaptiveShare || options_.schedule.kind != Schedule::Kind::Geometric || yieldCount_[0] < kFirst ||
        yieldCount_[1] < kFirst)
        return innerSteps_;
    // Cost taken off per path traced; a level that took nothing off yet counts a little.
    auto rate = [&](size_t l) { return (yieldGain_[l] + 1e-12) / std::max(1.0, yieldPaths_[l]); };
    const double share = std::clamp(rate(1) / (rate(0) + rate(1)), 0.1, 0.9);
    const double steps = share / (1 - share);  // object-level steps per group-level one, on average
    const int whole = int(steps);
    return whole + (rng.uniform() < steps - whole ? 1 : 0);
}

int Optimizer::cycleEnd() const {
    const int n = options_.iterations;
    const int length = int(std::lround(n * options_.restartShare));
    if (polishSets_.empty() || length < 1 || cycleStart_ + 2 * length > n) return n;
    return cycleStart_ + length;
}

int Optimizer::searchIterations() const {
    const int end = cycleEnd();
    if (polishSets_.empty()) return end;
    return end - int(std::lround((end - cycleStart_) * options_.polishShare));
}

void Optimizer::startCycle() {
    // From the polished best (the current layout), warm again: the chain may leave its
    // basin for a better one, which the polish alone never does.
    polishing_ = false;
    cycleStart_ = iteration_;
    cycleStartT_ = std::min(options_.schedule.start, options_.restartTemperature);
}

double Optimizer::temperature() const {
    if (polishing_) return 0.0;
    Schedule cycle = options_.schedule;
    cycle.start = cycleStartT_;
    const double t = cycle.temperature(iteration_ - cycleStart_, searchIterations() - cycleStart_);
    if (!options_.noiseAware || options_.schedule.kind == Schedule::Kind::Constant) return t;
    return std::max(t, std::sqrt(noiseVariance_));
}

void Optimizer::initialize(const StartProgress& progress, const std::atomic<bool>* cancel) {
    using Clock = std::chrono::steady_clock;
    const auto started = Clock::now();
    auto lastHeard = started;
    samplerRanges_.clear();
    stats_.resize(levels_.size());  // a polish's level of the last run goes
    for (size_t i = 0; i < levels_.size(); ++i) {
        rngs_[i] = Rng(hashValues({options_.seed, kStreamTag, streams_[i]}));
        stats_[i].moves = {};
    }
    polishRng_ = Rng(hashValues({options_.seed, kStreamTag, kPolishStream}));
    if (lightMap_) lightMap_->clear();
    polishing_ = false;
    polishFrom_ = options_.iterations;
    cycleStart_ = 0;
    cycleStartT_ = options_.schedule.start;
    windowProposed_ = windowAccepted_ = progressProposed_ = progressAccepted_ = 0;
    geometry_.revert();
    Rng rng(hashValues({options_.seed, kStreamTag, kStartStream}));
    Layout base = initialLayout(*scene_);
    Layout start = base;
    if (options_.start == StartFrom::Given) start = *options_.startLayout;
    if (options_.start == StartFrom::Scene || options_.start == StartFrom::Given) {
        for (size_t i = 0; i < scene_->entities.size(); ++i)
            if (scene_->entities[i].movable() && start.placements[i].region < 0)
                start.placements[i] = samplePlacement(scene_->entities[i], base.placements[i].position.z, rng);
    } else {
        // The paper's start: uniform draws; the first that no geometric term rejects,
        // else the least violating one (the chain then repairs it, see step()).
        double leastViolation = kInf;
        for (int attempt = 0; attempt < options_.startAttempts; ++attempt) {
            Layout candidate = sampleLayout(*scene_, base, rng);
            GeometryResult g = geometry_.evaluate(worldTransforms(*scene_, candidate));
            geometry_.commit();
            if (g.rejected && g.violation >= leastViolation) continue;
            leastViolation = g.violation;
            start = std::move(candidate);
            if (!g.rejected) break;
            if (progress.drawing && Clock::now() - lastHeard > std::chrono::milliseconds(500)) {
                progress.drawing(attempt + 1, options_.startAttempts);
                lastHeard = Clock::now();
            }
        }
    }
    planned_ = false;
    planLook_.reset();
    if (options_.start == StartFrom::Uniform && surrogate_ && !levels_.empty()) start = plannedStart(std::move(start), progress, cancel);
    // A plan is refined, not left: its first cycle starts cold, at the schedule's end
    // (the noise floor then sets the temperature); the later cycles warm again as ever.
    if (planned_) cycleStartT_ = options_.schedule.end;
    current_ = start;
    if (lighting_) lighting_->revert();
    currentEval_ = evaluate(current_, worldTransforms(*scene_, current_));
    geometry_.commit();
    if (lighting_) lighting_->commit();
    startEval_ = currentEval_;
    best_ = current_;
    bestEval_ = currentEval_;
    feasible_ = !currentEval_.rejected;
    iteration_ = bestIteration_ = confirmations_ = borrowedRefutations_ = independentMeasurements_ = 0;
    lightingEvaluations_ = 0;
    innerLeft_ = 0, focus_ = -1;
    noiseVariance_ = 0, noiseCount_ = 0;
    yieldGain_ = {}, yieldPaths_ = {}, yieldCount_ = {};
    candidates_.clear();
    candidates_.offer(current_, currentEval_, 0);
    // The plan chosen by its look stays a candidate with that measurement: the traced
    // chain's estimates are lower by luck (the winner's curse), and it must not lose
    // the plan to them.
    startConfirmed_ = false;
    if (planLook_ && !currentEval_.rejected) {
        candidates_.keep(Candidate{current_, currentEval_, planLook_, 0});
        // A look that meets every goal is a confirmation of the start, held to the
        // same standard as one of the chain's zeros (confirmBest).
        if (options_.stopAtZeroCost && planLook_->geometry == 0 && planLook_->lighting == 0) {
            const Evaluation asBest = asConfirmed(currentEval_, *planLook_);
            ++confirmations_;
            if (asBest.cost == 0) bestEval_ = currentEval_ = asBest, startConfirmed_ = true;
        }
    }
    suggestions_.clear();
    suggestions_.offer(current_, currentEval_, 0);
    trace_.clear();
    record();
    initialized_ = true;
    startSeconds_ = std::chrono::duration<double>(Clock::now() - started).count();
}

Layout Optimizer::plannedStart(Layout start, const StartProgress& progress, const std::atomic<bool>* cancel) {
    if (!surrogate_->ready()) {
        // The room without its furniture, traced once for every run of this optimizer.
        const uint64_t seed = hashValues({options_.seed, kStreamTag, kPlanStream});
        const std::vector<Vec3> points = surrogate_->points();
        std::vector<double> lux;
        if (!points.empty()) {
            lux = lighting_->emptyRoomIlluminance(points, options_.planPaths, seed);
            if (lux.empty()) {  // the evaluator cannot tell
                surrogate_.reset();
                return start;
            }
        }
        surrogate_->setIlluminance(lux);
        // The pose tables: each piece that carries a screen's eye, alone in the room.
        std::vector<std::vector<std::vector<double>>> tables;
        for (const LightSurrogate::PoseQuery& q : surrogate_->poseQueries()) {
            tables.push_back(lighting_->aloneInEmptyRoom(q.entity, q.placements, q.samplers, options_.planTablePaths, seed));
            if (tables.back().empty()) {
                tables.clear();
                break;
            }
        }
        surrogate_->setPoseValues(tables);
        if (surrogate_->empty()) {
            surrogate_.reset();
            return start;
        }
    }
    // Metropolis on C's stand-in, w L_surrogate + (1 - w) G, the rules exact: a rejected
    // start is repaired first, as the chain's is (step()).
    const double w = scene_->objective.lightingWeight;
    using Correction = LightSurrogate::Correction;
    auto costOf = [&](const Layout& layout, const std::vector<Transform>& world, double g, const Correction& correction) {
        return w * surrogate_->lighting(layout, world, correction) + (1 - w) * g;
    };
    // What the tables hold still (a monitor on its desk) stands at the scene's placement
    // and stays there: the traced chain turns it.
    const Layout scenePlacement = initialLayout(*scene_);
    std::vector<int> held;
    for (int e : surrogate_->heldAtScenePlacement())
        if (scenePlacement.placements[size_t(e)].region >= 0) {
            held.push_back(e);
            start.placements[size_t(e)] = scenePlacement.placements[size_t(e)];
        }
    auto movesHeld = [&](const Layout& proposed) {
        for (int e : held) {
            const Placement &a = proposed.placements[size_t(e)], &b = scenePlacement.placements[size_t(e)];
            if (a.position != b.position || a.rotationDeg != b.rotationDeg) return true;
        }
        return false;
    };
    // A plan's state: its own random stream and rules' cache, so that plans run at once
    // and each draws the same numbers whatever runs beside it.
    struct Planner {
        Rng rng;
        GeometryEvaluator geometry;
        Correction correction;  // from its look (empty: none yet)
    };
    // A chain of `n` proposals from `from` at the schedule's temperatures from proposal
    // `skip` of skip + n on: its best feasible layout, its stand-in cost (kInf: never
    // feasible) and G there.
    struct Planned {
        Layout layout;
        double cost = kInf, geometry = 0;
    };
    auto chain = [&](Planner& planner, Layout from, int n, int skip) {
        GeometryEvaluator& geometry = planner.geometry;
        Rng& rng = planner.rng;
        std::vector<Transform> world = worldTransforms(*scene_, from);
        const GeometryResult g = geometry.evaluate(world);
        geometry.commit();
        bool feasible = !g.rejected;
        double violation = g.violation, cost = feasible ? costOf(from, world, g.cost, planner.correction) : kInf;
        Planned best{from, cost, g.cost};
        for (int i = 0; i < n; ++i) {
            const double t = options_.schedule.temperature(skip + i, skip + n);
            const MoveSet& moves = levels_[levels_.size() == 1 ? 0 : rng.uniformInt(uint32_t(levels_.size()))];
            Layout proposed = from;
            const Proposal p = moves.propose(proposed, rng);
            if (!p.valid || movesHeld(proposed)) continue;
            world = worldTransforms(*scene_, proposed);
            const GeometryResult pg = geometry.evaluate(world);
            double proposedCost = kInf;
            bool accept = false;
            if (!feasible) {
                accept = !pg.rejected || pg.violation <= violation;
                if (!pg.rejected) proposedCost = costOf(proposed, world, pg.cost, planner.correction);
            } else if (!pg.rejected) {
                proposedCost = costOf(proposed, world, pg.cost, planner.correction);
                const double logA = -(proposedCost - cost) / t + p.logHastings;
                accept = logA >= 0 || rng.uniform() < std::exp(logA);
            }
            if (!accept) {
                geometry.revert();
                continue;
            }
            geometry.commit();
            from = std::move(proposed);
            feasible = feasible || !pg.rejected;
            violation = pg.violation, cost = proposedCost;
            if (feasible && cost < best.cost) best = {from, cost, pg.cost};
        }
        return best;
    };
    // A traced look at a plan: the light measured independently of the search's random
    // numbers (the selection's paths), every plan's look with the same ones, so that
    // their differences owe little to noise.
    auto look = [&](const Planned& plan) {
        Evaluation e;
        e.geometry = plan.geometry;
        e.lighting = lighting_->measureIndependently(plan.layout, worldTransforms(*scene_, plan.layout), &e.samplers,
                                                     independentSeed(kLookStream), IndependentUse::Selection);
        lighting_->revert();
        e.lightingEvaluated = true;
        e.costError = costError(e);
        e.cost = scene_->objective.cost(e.lighting, e.geometry);
        return e;
    };
    // Several plans, each from the drawn start on its own random stream. Each is looked
    // at once, its surrogate scaled by what the look read (the furniture's own shadows on
    // a desk, what the other pieces add to a screen), and its last quarter runs again; the
    // refined plan is looked at too. The start is the plan whose look reads the lowest C:
    // the surrogate's error is as large as the differences between arrangements, the
    // looks' is not. A look that meets every goal as the run's stop reads it ends the
    // planning.
    const int n = options_.planIterations;
    Planned chosen;
    Evaluation chosenLook;
    // Ranked by the look's C, then (several at 0) by its C under the search's margin:
    // the one further inside its bands.
    double chosenMargined = kInf;
    auto consider = [&](const Planned& plan, const Evaluation& e) {
        // Solved as the run's stop would read it (initialize(), confirmBest()): the look
        // with the margin, its errors widened by how far the search's estimate reads.
        if (e.geometry == 0 && e.lighting == 0 && e.samplers.samplers.size() == scene_->samplers.size()) {
            Evaluation search = e;
            search.lighting = lighting_->evaluate(plan.layout, worldTransforms(*scene_, plan.layout), &search.samplers);
            lighting_->revert();
            if (asConfirmed(search, e).cost == 0) {
                chosen = plan, chosenLook = e;
                return true;
            }
        }
        const double m = costUnderMargin(e);
        if (chosen.cost == kInf || e.cost < chosenLook.cost || (e.cost == chosenLook.cost && m < chosenMargined))
            chosen = plan, chosenLook = e, chosenMargined = m;
        return false;
    };
    // The plans go kPlansAtOnce at a time: their chains at once (the looks trace on every
    // thread themselves), then their looks in the plans' order. The batch is fixed, not the
    // thread count, so that the same seed gives the same plan on any machine.
    bool solvedPlan = false;
    for (int first = 0; first < options_.plans && !solvedPlan; first += kPlansAtOnce) {
        if (first > 0 && cancel && cancel->load(std::memory_order_relaxed)) break;
        const int count = std::min(kPlansAtOnce, options_.plans - first);
        const auto batch = static_cast<size_t>(count);
        std::vector<Planner> planners;
        for (int k = 0; k < count; ++k)
            planners.push_back({Rng(hashValues({options_.seed, kStreamTag, kPlanStream, uint64_t(first + k)})), geometry_, {}});
        std::vector<Planned> best(batch), refined(batch);
        parallelFor(batch, [&](size_t k) { best[k] = chain(planners[k], start, n, 0); });
        std::vector<bool> refine(batch, false);
        int looked = first + count;  // or fewer, where a look ends the planning
        for (size_t k = 0; k < batch && !solvedPlan; ++k) {
            if (!std::isfinite(best[k].cost)) continue;  // never feasible
            const Evaluation seen = look(best[k]);
            solvedPlan = consider(best[k], seen);
            if (solvedPlan) looked = first + int(k) + 1;
            if (solvedPlan || seen.samplers.samplers.size() != scene_->samplers.size()) continue;
            planners[k].correction =
                surrogate_->correction(best[k].layout, worldTransforms(*scene_, best[k].layout), seen.samplers.samplers);
            refine[k] = true;
        }
        const int quarter = n / 4;
        if (!solvedPlan)
            parallelFor(batch, [&](size_t k) {
                if (refine[k]) refined[k] = chain(planners[k], best[k].layout, quarter, n - quarter);
            });
        for (size_t k = 0; k < batch && !solvedPlan; ++k)
            if (refine[k] && std::isfinite(refined[k].cost) && consider(refined[k], look(refined[k])))
                solvedPlan = true, looked = first + int(k) + 1;
        if (progress.planning && std::isfinite(chosen.cost)) progress.planning(looked, options_.plans, chosenLook.cost);
    }
    if (!std::isfinite(chosen.cost)) return start;  // never feasible: the chain repairs it
    planned_ = true;
    planLook_ = chosenLook;
    return chosen.layout;
}

namespace {

// What a proposal can change about an entity: x and y where some region has an extent,
// the rotation where some region has two or more, and at least 1 (a jump).
int degreesOfFreedom(const Entity& e) {
    bool x = false, y = false, rotation = false;
    for (const Region& r : e.regions) {
        x |= r.hi.x > r.lo.x, y |= r.hi.y > r.lo.y;
        rotation |= (r.continuousRotation && r.rotationMaxDeg > r.rotationMinDeg) || distinctRotations(r).size() > 1;
    }
    return std::max(1, int(x) + int(y) + int(rotation));
}

int degreesOfFreedom(const Scene& scene, const std::vector<int>& entities) {
    int n = 0;
    for (int e : entities) n += degreesOfFreedom(scene.entities[size_t(e)]);
    return n;
}

// Object-level steps per group-level one from the levels' degrees of freedom.
int stepsFor(int objectDof, int groupDof) {
    return std::max(1, int(std::lround(double(objectDof) / std::max(1, groupDof))));
}

}  // namespace

void Optimizer::setUpNesting(const std::vector<int>& outer, const std::vector<int>& inner) {
    innerSteps_ = options_.innerIterations > 0
                      ? options_.innerIterations
                      : stepsFor(degreesOfFreedom(*scene_, inner), degreesOfFreedom(*scene_, outer));
    focusOf_.assign(scene_->entities.size(), -1);
    if (!options_.focusInner) return;
    for (int g : outer) {
        std::vector<int> members;
        for (int e : inner) {
            int top = e;
            while (scene_->entities[size_t(top)].parent >= 0) top = scene_->entities[size_t(top)].parent;
            if (top == g) members.push_back(e);
        }
        MoveSet moves(*scene_, members, options_.moves);
        if (moves.empty()) continue;
        focusOf_[size_t(g)] = int(focusSets_.size());
        focusSteps_.push_back(options_.innerIterations > 0
                                  ? options_.innerIterations
                                  : stepsFor(degreesOfFreedom(*scene_, members),
                                             degreesOfFreedom(scene_->entities[size_t(g)])));
        focusSets_.push_back(std::move(moves));
    }
}

const MoveSet& Optimizer::nextMoves(int& level) {
    if (levels_.size() < 2) {
        level = 0;
        return levels_[0];
    }
    if (innerLeft_ > 0) {
        --innerLeft_;
        level = 1;
        return focus_ >= 0 ? focusSets_[size_t(focus_)] : levels_[1];
    }
    level = 0;
    return levels_[0];
}

void Optimizer::record() {
    const double acceptance = windowProposed_ > 0 ? double(windowAccepted_) / double(windowProposed_) : 0.0;
    trace_.push_back({iteration_, currentEval_.cost, feasible_ ? bestEval_.cost : kInf, !currentEval_.rejected,
                      temperature(), acceptance});
    windowProposed_ = windowAccepted_ = 0;
}

void Optimizer::startPolish() {
    // From the best layout, measured again by the search's own estimator (the best's
    // cost may be a confirmation's, from other random numbers).
    polishing_ = true;
    polishFrom_ = iteration_;
    polishLevel();
    if (lighting_) lighting_->revert();
    geometry_.revert();
    const std::vector<Transform> world = worldTransforms(*scene_, best_);
    Evaluation e = evaluate(best_, world);
    geometry_.commit();
    if (lighting_) lighting_->commit();
    current_ = best_;
    currentEval_ = std::move(e);
}

LevelStats& Optimizer::polishLevel() {
    if (stats_.size() == levels_.size()) stats_.push_back({"polish", polishSets_[0].entities(), {}});
    return stats_.back();
}

void Optimizer::snapCurrent() {
    // Each entity that turns, once, to the room's nearest quarter turn, kept when C does
    // not rise: a run that stops on a zero before its polish still ends square.
    if (polishSets_.empty() || currentEval_.rejected) return;
    const MoveSet& set = polishSets_[0];
    for (int entity : set.candidates(MoveType::Snap)) {
        Layout proposed = current_;
        Proposal p = set.apply(MoveType::Snap, entity, proposed, polishRng_);
        MoveStats& s = polishLevel().moves[int(MoveType::Snap)];
        ++s.proposed;
        if (!p.valid) {
            ++s.outside;
            continue;
        }
        Evaluation e;
        const bool accept = descends(proposed, s, e);
        if (accept) geometry_.commit();
        else geometry_.revert();
        if (lighting_) accept ? lighting_->commit() : lighting_->revert();
        if (!accept) continue;
        ++s.accepted;
        current_ = std::move(proposed);
        currentEval_ = std::move(e);
    }
}

void Optimizer::polishStep() {
    Layout proposed = current_;
    Proposal p = polishSets_[0].propose(proposed, polishRng_);
    MoveStats& s = stats_.back().moves[int(p.type)];
    ++s.proposed;
    bool accept = false;
    Evaluation e;
    if (!p.valid) ++s.outside;
    else accept = descends(proposed, s, e);
    settle(p.valid, accept, s, std::move(proposed), std::move(e));
}

bool Optimizer::descends(const Layout& proposed, MoveStats& s, Evaluation& e) {
    const std::vector<Transform> world = worldTransforms(*scene_, proposed);
    const uint64_t tracedBefore = lighting_ ? lighting_->tracedPaths() : 0;
    e = evaluateGeometry(world);
    bool accept = false;
    if (e.rejected) {
        ++s.rejectedGeometry;
    } else if ((1 - scene_->objective.lightingWeight) * e.geometry > currentEval_.cost) {
        ++s.screened;  // no light could bring C down to the current cost
    } else {
        addLighting(e, proposed, world);
        accept = e.cost <= currentEval_.cost;
    }
    if (lighting_) s.pathsTraced += lighting_->tracedPaths() - tracedBefore;
    return accept;
}

void Optimizer::settle(bool evaluated, bool accept, MoveStats& stats, Layout proposed, Evaluation e) {
    if (evaluated) {
        if (accept) geometry_.commit();
        else geometry_.revert();
        if (lighting_) accept ? lighting_->commit() : lighting_->revert();
    }
    ++iteration_;
    ++windowProposed_, ++progressProposed_;
    if (accept) {
        ++stats.accepted;
        acceptProposal(std::move(proposed), std::move(e));
    }
    if (iteration_ % traceEvery_ == 0) record();
}

void Optimizer::acceptProposal(Layout proposed, Evaluation e) {
    ++windowAccepted_, ++progressAccepted_;
    current_ = std::move(proposed);
    currentEval_ = std::move(e);
    candidates_.offer(current_, currentEval_, iteration_);
    if (options_.suggestions > 0) suggestions_.offer(current_, currentEval_, iteration_);
    bool better = !feasible_ || currentEval_.cost < bestEval_.cost;
    if (!currentEval_.rejected && better) {
        feasible_ = true;
        best_ = current_;
        bestEval_ = currentEval_;
        bestIteration_ = iteration_;
    } else if (!feasible_) {
        best_ = current_;  // the least violating layout so far
        bestEval_ = currentEval_;
        bestIteration_ = iteration_;
    }
}

void Optimizer::step() {
    if (!initialized_) initialize();
    if (levels_.empty()) {
        ++iteration_;
        return;
    }
    if (polishing_ && iteration_ >= cycleEnd() && cycleEnd() < options_.iterations) startCycle();
    if (!polishing_ && feasible_ && !polishSets_.empty() && iteration_ >= searchIterations()) startPolish();
    if (polishing_) {
        polishStep();
        return;
    }
    int level = 0;
    const MoveSet& moves = nextMoves(level);
    const double t = temperature();
    Rng& rng = rngs_[size_t(level)];
    Layout proposed = current_;
    Proposal p = moves.propose(proposed, rng);
    if (levels_.size() == 2 && level == 0) {
        // The chosen group (valid or not: the choice never depends on the state).
        focus_ = options_.focusInner ? focusOf_[size_t(p.entity)] : -1;
        innerLeft_ = !options_.focusInner ? objectSteps(rng) : focus_ >= 0 ? focusSteps_[size_t(focus_)] : 0;
    }
    MoveStats& stats = stats_[size_t(level)].moves[int(p.type)];
    ++stats.proposed;

    bool accept = false;
    Evaluation e;
    if (!p.valid) {
        ++stats.outside;
    } else {
        const std::vector<Transform> world = worldTransforms(*scene_, proposed);
        const uint64_t tracedBefore = lighting_ ? lighting_->tracedPaths() : 0;
        if (options_.delayedAcceptance && !currentEval_.rejected) {
            // Delayed acceptance: the rules' change first, the light only if it passes.
            e = evaluateGeometry(world);
            if (!e.rejected && !geometricStage(e, p.logHastings, t, rng)) {
                ++stats.screened;
            } else if (!e.rejected) {
                if (lighting_ && lighting_->drawsAnew() && currentEval_.lightingEvaluated) refreshCurrent();
                addLighting(e, proposed, world);
                accept = lightingStage(e, t, rng);
            }
        } else {
            if (lighting_ && lighting_->drawsAnew() && currentEval_.lightingEvaluated) refreshCurrent();
            e = evaluate(proposed, world);
            if (currentEval_.rejected) {
                // Repair (only before the first feasible state): descend on the total
                // violation; a feasible proposal always ends the repair.
                accept = !e.rejected || e.violation <= currentEval_.violation;
            } else if (!e.rejected) {
                accept = metropolis(e, p.logHastings, t, rng);
            }
        }
        if (lighting_) stats.pathsTraced += lighting_->tracedPaths() - tracedBefore;
        if (e.lightingEvaluated && currentEval_.lightingEvaluated)
            noteYield(level, accept ? std::max(0.0, currentEval_.cost - e.cost) : 0.0,
                      lighting_ ? lighting_->tracedPaths() - tracedBefore : 0);
        if (options_.noiseAware && !currentEval_.rejected) noteNoise(e);
        if (e.rejected && !accept) ++stats.rejectedGeometry;
    }
    settle(p.valid, accept, stats, std::move(proposed), std::move(e));
}

Progress Optimizer::progressNow(double seconds, int first) {
    Progress pr;
    pr.iteration = iteration_;
    pr.iterations = options_.iterations;
    pr.current = currentEval_.cost;
    pr.best = feasible_ ? bestEval_.cost : kInf;
    pr.feasible = !currentEval_.rejected;
    pr.lightingMeasured = currentEval_.lightingEvaluated;
    pr.temperature = temperature();
    pr.polishing = polishing_;
    pr.recentAcceptance = progressProposed_ > 0 ? double(progressAccepted_) / double(progressProposed_) : 0.0;
    progressProposed_ = progressAccepted_ = 0;
    for (MoveType t : kMoveTypes) {
        MoveStats total;
        for (const auto& level : stats_) {
            total.proposed += level.moves[int(t)].proposed;
            total.accepted += level.moves[int(t)].accepted;
        }
        pr.acceptance[int(t)] = total.acceptance();
        pr.proposed[int(t)] = uint64_t(total.proposed);
    }
    pr.seconds = seconds;
    int done = iteration_ - first;
    pr.etaSeconds = done > 0 ? pr.seconds / done * std::max(0, options_.iterations - iteration_) : 0.0;
    return pr;
}

// With suggestions asked for, the run goes on past a confirmed 0 until it holds as
// many distinct layouts the search estimated at 0 (or runs out of iterations).
bool Optimizer::enoughSuggestions() const {
    if (options_.suggestions <= 1) return true;
    int zeros = 0;
    for (const Candidate& c : suggestions_.all()) zeros += c.search.cost == 0;
    return zeros >= options_.suggestions;
}

Evaluation Optimizer::confirmBest() {
    // A zero the same as one an independent measurement already refuted (within the
    // candidates' separation) reads as that measurement did: near a band's edge the
    // chain's estimates read 0 again and again where the light does not, and each
    // measurement at the selection's paths costs hundreds of the chain's steps. Only
    // a refutation is borrowed; a zero is always measured at its own layout.
    for (const Candidate& c : candidates_.all()) {
        if (!c.independent || !sameCandidate(*scene_, c.layout, best_, options_.candidateSeparation)) continue;
        Evaluation borrowed = *c.independent;
        borrowed.geometry = bestEval_.geometry;
        borrowed.cost = scene_->objective.cost(borrowed.lighting, borrowed.geometry);
        const Evaluation refuted = asConfirmed(bestEval_, borrowed);
        if (refuted.cost > 0) {
            ++borrowedRefutations_;
            return refuted;
        }
    }
    // A noisy estimate of L reaches 0 before the layout does: measure it again,
    // independently of the search's random numbers.
    ++confirmations_;
    ++independentMeasurements_;
    Evaluation confirmed = bestEval_;
    confirmed.lighting = lighting_->measureIndependently(best_, worldTransforms(*scene_, best_), &confirmed.samplers,
                                                         independentSeed(kSelectionStream), IndependentUse::Selection);
    confirmed.costError = costError(confirmed);
    confirmed.cost = scene_->objective.cost(confirmed.lighting, confirmed.geometry);
    // Kept among the candidates with its measurement, even past their capacity: the
    // run may stop on it, and the result must be chosen among what it stopped on.
    candidates_.keep(Candidate{best_, bestEval_, confirmed, bestIteration_});
    return asConfirmed(bestEval_, confirmed);
}

double Optimizer::costUnderMargin(const Evaluation& e) const {
    if (e.samplers.samplers.size() != scene_->samplers.size()) return e.cost;
    return scene_->objective.cost(lightingCostOfResults(*scene_, e.samplers.samplers, options_.marginZ), e.geometry);
}

Evaluation Optimizer::asConfirmed(const Evaluation& search, const Evaluation& confirmed) const {
    // The best's cost from here: the confirmation's, with the search's margin (a
    // layout at a band's edge is met in one measurement in two: not a zero to stop on).
    // The margin's error is the larger of the confirmation's own and what the two
    // independent estimates of the layout, the search's and the confirmation's, say
    // by their difference (|a - b| / sqrt 2): a glare sampler's brightest stratum
    // differs between seeds by more than its error says.
    Evaluation asBest = confirmed;
    if (confirmed.samplers.samplers.size() == scene_->samplers.size()) {
        std::vector<SamplerResult> spread = confirmed.samplers.samplers;
        const auto& estimated = search.samplers.samplers;
        for (size_t k = 0; k < spread.size() && estimated.size() == spread.size(); ++k)
            spread[k].standardError =
                std::max(spread[k].standardError, std::abs(spread[k].value - estimated[k].value) / std::sqrt(2.0));
        asBest.lighting = lightingCostOfResults(*scene_, spread, options_.marginZ);
        asBest.cost = scene_->objective.cost(asBest.lighting, asBest.geometry);
    }
    return asBest;
}

bool Optimizer::solved(int& confirmedZeroAt) {
    if (!options_.stopAtZeroCost || !feasible_ || bestEval_.cost != 0) return false;
    if (confirmedZeroAt == bestIteration_) return enoughSuggestions();
    if (bestIteration_ == iteration_ && iteration_ > 0) {
        // The best is the current layout: square it with the room before confirming.
        snapCurrent();
        if (currentEval_.cost <= bestEval_.cost) {
            best_ = current_;
            bestEval_ = currentEval_;
            candidates_.offer(current_, currentEval_, iteration_);
        }
    }
    if (!bestEval_.lightingEvaluated) {
        confirmedZeroAt = bestIteration_;
        return enoughSuggestions();
    }
    const Evaluation asBest = confirmBest();
    if (bestIteration_ == iteration_) currentEval_ = asBest;  // the current layout is the best one
    bestEval_ = asBest;
    if (asBest.cost == 0) confirmedZeroAt = bestIteration_;
    return asBest.cost == 0 && enoughSuggestions();
}

OptimizerResult Optimizer::run(const ProgressCallback& progress, const std::atomic<bool>* cancel) {
    using Clock = std::chrono::steady_clock;
    if (!initialized_) initialize();
    const int first = iteration_;
    // A run from the start counts the start's draws and measurement too.
    const double before = first == 0 ? startSeconds_ : 0.0;
    const auto started = Clock::now();
    auto seconds = [&] { return before + std::chrono::duration<double>(Clock::now() - started).count(); };
    int reported = -1;
    auto report = [&] {
        if (!progress || reported == iteration_) return;
        reported = iteration_;
        progress(progressNow(seconds(), first));
    };
    int confirmedZeroAt = startConfirmed_ && iteration_ == 0 ? 0 : -1;  // the best iteration whose zero a confirmation held

    // Best-so-far snapshots at the checkpoints still ahead, and where the run stops.
    std::vector<Snapshot> snapshots;
    std::vector<int> checkpoints;
    for (int k = options_.snapshots; k >= 1; --k) {
        const double f = double(k) / options_.snapshots;
        const int at = int(std::ceil(options_.iterations * f * f));
        if (at > iteration_ && (checkpoints.empty() || at < checkpoints.back())) checkpoints.push_back(at);
    }
    auto snapshot = [&] {
        if (options_.snapshots <= 0 || (!snapshots.empty() && snapshots.back().iteration == iteration_)) return;
        snapshots.push_back({iteration_, seconds(), lightingEvaluations_, feasible_ ? bestEval_.cost : kInf, feasible_, best_});
    };
    auto atCheckpoint = [&] {
        while (!checkpoints.empty() && checkpoints.back() <= iteration_) {
            checkpoints.pop_back();
            snapshot();
        }
    };

    StopReason stop = StopReason::Iterations;
    if (levels_.empty()) stop = StopReason::NothingToMove;
    else if (solved(confirmedZeroAt)) stop = StopReason::ZeroCost;
    else
        while (iteration_ < options_.iterations) {
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                stop = StopReason::Cancelled;
                break;
            }
            step();
            if (iteration_ % options_.progressEvery == 0) report();
            const bool zero = solved(confirmedZeroAt);  // a confirmation may replace the best estimate
            atCheckpoint();
            if (zero) {
                stop = StopReason::ZeroCost;
                break;
            }
        }
    snapshot();
    if (trace_.empty() || trace_.back().iteration != iteration_) record();
    report();
    OptimizerResult r = resultOf(stop, std::move(snapshots));
    r.seconds = seconds();
    return r;
}

OptimizerResult Optimizer::resultOf(StopReason stop, std::vector<Snapshot> snapshots) {
    OptimizerResult r;
    chooseResult(r);
    chooseSuggestions(r);
    // The per-term breakdown of the result; the cache goes back to the current layout.
    r.bestGeometry = geometry_.evaluate(worldTransforms(*scene_, r.best), /* breakdown = */ true);
    geometry_.revert();
    r.startEvaluation = startEval_;
    r.iterations = iteration_;
    r.confirmations = confirmations_;
    r.borrowedRefutations = borrowedRefutations_;
    r.independentMeasurements = independentMeasurements_;
    r.samplerRanges = samplerRanges_;
    r.samplerRanges.resize(scene_->samplers.size());
    r.stop = stop;
    r.feasible = feasible_;
    r.startFeasible = !startEval_.rejected;
    r.planned = planned_;
    r.startSeconds = startSeconds_;
    r.levels = stats_;
    r.trace = trace_;
    r.snapshots = std::move(snapshots);
    r.lightingEvaluations = lightingEvaluations_;
    r.polishFrom = polishFrom_;
    if (lighting_) r.lightingNotes = lighting_->notes();
    r.options = options_;
    return r;
}

std::pair<Layout, Evaluation> Optimizer::asWritten(const Layout& layout, const Evaluation& e) {
    if (!options_.roundResult) return {layout, e};
    auto geometryOf = [&](const Layout& l) {
        Evaluation g = evaluateGeometry(worldTransforms(*scene_, l));
        geometry_.revert();
        return g;
    };
    // Whether `a` keeps the rules worse than `b`: rejected, more violating, higher G.
    auto worse = [](const Evaluation& a, const Evaluation& b) {
        if (a.rejected != b.rejected) return a.rejected;
        return a.rejected ? a.violation > b.violation : a.geometry > b.geometry;
    };
    Layout rounded = roundedLayout(*scene_, layout);
    Evaluation g = geometryOf(rounded);
    // Rounding to the nearest step broke a rule (or raised a penalty): each entity it
    // moved tries rounding each value the other way, one entity after the other.
    constexpr RoundTowards kWays[] = {RoundTowards::Down, RoundTowards::Up};
    for (size_t i = 0; i < scene_->entities.size() && worse(g, e); ++i) {
        const Placement &from = layout.placements[i], &to = rounded.placements[i];
        if (!scene_->entities[i].movable() ||
            (from.position == to.position && from.rotationDeg == to.rotationDeg))
            continue;
        for (RoundTowards x : kWays)
            for (RoundTowards y : kWays)
                for (RoundTowards turn : kWays) {
                    Layout trial = rounded;
                    trial.placements[i] = roundedPlacement(scene_->entities[i], from, x, y, turn);
                    Evaluation h = geometryOf(trial);
                    if (worse(g, h)) rounded = std::move(trial), g = std::move(h);
                }
    }
    Evaluation out = e;
    out.geometry = g.geometry;
    out.rejected = g.rejected;
    out.violation = g.violation;
    out.rejectedBy = g.rejectedBy;
    out.cost = scene_->objective.cost(out.lighting, out.geometry);
    return {std::move(rounded), std::move(out)};
}

void Optimizer::chooseResult(OptimizerResult& r) {
    std::tie(r.best, r.bestEvaluation) = asWritten(best_, bestEval_);
    r.bestSearchEvaluation = bestEval_;
    r.bestIteration = bestIteration_;
    const bool measured = lighting_ && !scene_->samplers.empty();
    if (!measured) return;
    const double w = scene_->objective.lightingWeight;
    // The selection's stream at the selection's paths, the report's at the report's.
    auto measure = [&](const Layout& layout, Evaluation e, uint64_t stream) {
        ++independentMeasurements_;
        e.lighting = lighting_->measureIndependently(
            layout, worldTransforms(*scene_, layout), &e.samplers, independentSeed(stream),
            stream == kReportStream ? IndependentUse::Report : IndependentUse::Selection);
        e.lightingEvaluated = true;
        e.costError = costError(e);
        e.cost = scene_->objective.cost(e.lighting, e.geometry);
        return e;
    };
    if (!feasible_) {
        // Only the least violating layout, which no cost describes (a hard limit is
        // passed): its light is still what layout.json would measure.
        r.bestEvaluation = measure(r.best, r.bestEvaluation, kReportStream);
        r.reportSeed = independentSeed(kReportStream);
        return;
    }
    std::vector<Candidate>& all = candidates_.all();
    size_t chosen = 0;
    if (w > 0 && all.size() > 1) {
        // The winner's curse: the lowest of many noisy estimates is low by luck. Each
        // candidate is measured again (stream 1), and the lowest of those is chosen (a
        // lone candidate, as when nothing moves, is chosen without).
        // Between equal costs (several at 0), the one with the lower cost under the
        // search's margin: the one further inside its bands, likelier met in another
        // measurement.
        std::vector<double> margined(all.size());
        for (size_t i = 0; i < all.size(); ++i) {
            if (!all[i].independent) all[i].independent = measure(all[i].layout, all[i].search, kSelectionStream);
            margined[i] = costUnderMargin(*all[i].independent);
            const double c = all[i].independent->cost, best = all[chosen].independent->cost;
            if (c < best || (c == best && margined[i] < margined[chosen])) chosen = i;
        }
    } else {
        // L took no part in the run: the best by G, which is exact.
        chosen = 0;
    }
    if (all.empty()) return;
    const Candidate& c = all[chosen];
    // As layout.json will hold it (OptimizerOptions::roundResult).
    auto [written, evaluation] = asWritten(c.layout, c.search);
    r.best = written;
    r.bestSearchEvaluation = c.search;
    r.bestIteration = c.iteration;
    r.chosenCandidate = int(chosen);
    // Measured once more (stream 2), so that the reported value owes nothing to the
    // choice it made.
    r.bestEvaluation = measure(written, evaluation, kReportStream);
    r.reportSeed = independentSeed(kReportStream);
    r.candidates = all;
}

void Optimizer::chooseSuggestions(OptimizerResult& r) {
    if (options_.suggestions <= 0 || !feasible_) return;
    // The result is the first suggestion: it takes the place of the one it is the same as.
    Candidate result{r.best, r.bestSearchEvaluation, r.bestEvaluation, r.bestIteration};
    std::vector<Candidate> list;
    for (const Candidate& c : suggestions_.all())
        if (!sameCandidate(*scene_, c.layout, result.layout, options_.suggestionSeparation)) list.push_back(c);
    const bool measured = lighting_ && !scene_->samplers.empty();
    for (Candidate& c : list) {
        // As its file will hold it, like the result.
        auto [written, e] = asWritten(c.layout, c.search);
        c.layout = std::move(written);
        if (measured) {
            ++independentMeasurements_;
            e.lighting = lighting_->measureIndependently(c.layout, worldTransforms(*scene_, c.layout), &e.samplers,
                                                         independentSeed(kReportStream), IndependentUse::Report);
            e.lightingEvaluated = true;
            e.costError = costError(e);
            e.cost = scene_->objective.cost(e.lighting, e.geometry);
        }
        c.independent = e;
    }
    // The result first (layout.json), then the others by their measurement.
    std::vector<size_t> order(list.size());
    std::vector<double> cost(list.size());
    for (size_t i = 0; i < list.size(); ++i) order[i] = i, cost[i] = list[i].independent ? list[i].independent->cost : kInf;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cost[a] < cost[b]; });
    order.resize(std::min(order.size(), size_t(options_.suggestions - 1)));
    r.suggestions.push_back(std::move(result));
    for (size_t i : order) r.suggestions.push_back(std::move(list[i]));
}

}  // namespace luxplan
