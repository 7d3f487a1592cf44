// The hierarchical Metropolis optimizer of the paper's Section 6: group-level and
// object-level proposals, the geometric test before the lighting hook, Metropolis
// acceptance on C = w L + (1 - w) G (Eq. 1) under a temperature schedule, and the
// best layout kept.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/core/rng.h>
#include <luxplan/optimizer/candidates.h>
#include <luxplan/optimizer/evaluation.h>
#include <luxplan/optimizer/light_map.h>
#include <luxplan/optimizer/light_surrogate.h>
#include <luxplan/optimizer/lighting.h>
#include <luxplan/optimizer/moves.h>
#include <luxplan/optimizer/reach.h>

namespace luxplan {

// Hierarchical: two levels as in the paper (top-level entities, then the entities
// inside groups). Flat: one level holding every movable entity.
enum class Hierarchy { Hierarchical, Flat };

// Uniform: the paper's start, every movable entity drawn uniformly from its regions
// (redrawn until no geometric term rejects, up to `startAttempts` draws). Scene: the
// placement the scene file gives (entities outside their regions drawn uniformly).
// Given: OptimizerOptions::startLayout (a designer's own layout, optimize --start).
enum class StartFrom { Uniform, Scene, Given };

// Temperature T of the Metropolis test exp(-(C' - C) / T). Costs are dimensionless:
// every penalty is 1 at its rule's elastic limit. Geometric cooling (Kirkpatrick et
// al. 1983) from `start` to `end` over the run: at T = 0.1 a step that costs a tenth
// of an elastic limit passes with probability 1/e, so the chain crosses mildly
// penalized states early; at T = 0.001 the same step passes with e^-100, so the last
// iterations descend into the best basin found. Constant keeps T = `start`
// (a plain Metropolis chain whose stationary law is exp(-C/T)).
struct Schedule {
    enum class Kind { Constant, Geometric };
    Kind kind = Kind::Geometric;
    double start = 0.1;
    double end = 0.001;
    // T at `iteration` of a run of `iterations`: start (end / start)^(i / (n - 1)).
    double temperature(int iteration, int iterations) const;
};

struct OptimizerOptions {
    int iterations = 10000;  // proposals, both levels together
    uint64_t seed = 1;
    Hierarchy hierarchy = Hierarchy::Hierarchical;
    // Object-level proposals after each group-level one (the paper gives the inner
    // level more iterations, so that a group arrangement is refined before the next
    // group-level change). 0: set by the levels' degrees of freedom, the object
    // level's over the group level's (rounded, at least 1; with focusInner, those of
    // the moved group's members over the group's own).
    int innerIterations = 0;
    // Nested: the object-level proposals after a group-level one move only the members
    // of the group it chose (its movable descendants), refining that group's new
    // arrangement before the next group move; a group without movable members is
    // followed by none. The group is chosen uniformly, whatever the state, so every
    // step stays a Metropolis step of the same target.
    bool focusInner = false;
    Schedule schedule;
    StartFrom start = StartFrom::Uniform;
    int startAttempts = 1000;
    MoveOptions moves;
    // The paper stops as soon as C = 0. With a lighting term the chain first confirms
    // it with an independent measurement (LightingEvaluator::measureIndependently); a
    // confirmed C above 0 replaces the best layout's estimate and the run goes on.
    bool stopAtZeroCost = true;
    // Noise-aware: a geometric schedule's temperature never falls below the noise of the
    // decisions it makes (the RMS standard error of the recent proposals' estimated
    // differences of C: under common random numbers only the samplers that changed and,
    // of their paths, those traced afresh count), and when the
    // lighting evaluator draws every estimate anew the Metropolis test is the penalty
    // method of Ceperley and Dewing (1999), exp(-dC / T - s^2 / (2 T^2)) with s the
    // standard error of dC. Off: the plain test on the estimates, as the paper does.
    bool noiseAware = true;
    // Delayed acceptance (Christen and Fox 2005): a proposal is first tested on its
    // geometric change alone, min(1, exp(-(1 - w) dG / T) q'/q); only one that passes is
    // lit and tested again on its lighting change, min(1, exp(-w dL / T)) (with the
    // noise penalty). The product is the full Metropolis-Hastings acceptance's
    // detailed balance, and a proposal that worsens the layout's rules beyond the
    // temperature costs no light. Off: one test on dC after lighting every proposal.
    bool delayedAcceptance = true;
    // How many distinct layouts the run keeps for its result, and what distinct means
    // (optimizer/candidates.h). At the end, each is measured again independently and
    // the best of those measurements is the result, measured once more for the report.
    int candidates = 4;
    CandidateSeparation candidateSeparation;
    // The search's margin: every lighting term's band narrowed by this many standard
    // errors of the term's estimate at each finite end (LightingEvaluator::setSearchMargin),
    // and a zero confirmed only when the confirmation lies that far inside every band
    // too, so that a result the run stops on is met in other measurements as well, not
    // only in the lucky one. The report's C takes no margin. 0: the plain penalty.
    double marginZ = 2;
    // The object level's share of proposals follows what the levels' proposals yield:
    // cost taken off per path traced, each level's over its last ~200 lit proposals
    // (a geometric schedule's run only; the first 50 of each level keep the fixed
    // cycle). A level whose moves the cost does not care about (monitors the chain
    // moves freely, 95% accepted) gets fewer; the share stays within [0.1, 0.9].
    bool adaptiveShare = true;
    // The polish: this share of each cycle (restartShare) ends it as a descent from the best
    // layout at zero temperature (a proposal is kept when C does not rise), with
    // translate and rotate at the fine step scales only and the snap to the room's
    // quarter turns (MoveOptions::polish). The schedule cools over the iterations before
    // it. 0: no polish; a constant schedule (a plain chain) has none either.
    double polishShare = 0.2;
    // Restarts: the schedule and its polish run in cycles of this share of `iterations`
    // (the last cycle takes the rest, up to twice that), each later one from the
    // polished best at restartTemperature, cooling again to the schedule's end. 0: one
    // cycle, the whole run. Only with a polish. optimizerOptions() sets the temperature
    // to a fifth of the schedule's start.
    double restartShare = 0.3;
    double restartTemperature = 0.02;
    // Suggestions: how many mutually distinct layouts (optimize --suggestions) to keep
    // beside the result, and what distinct means for them (0: none).
    int suggestions = 0;
    CandidateSeparation suggestionSeparation{0.5, 45};
    // The guided move (MoveType::Guided): each top-level entity that carries samplers
    // also draws placements from a map of where its own targets held in the layouts lit
    // so far (optimizer/light_map.h). Off: the paper's blind moves only.
    bool guidedMoves = true;
    LightMapOptions lightMap;
    // The planned start (StartFrom::Uniform, a geometric schedule, a lighting hook that
    // can trace the empty room): from the drawn start, a chain of planIterations proposals
    // on the light surrogate (optimizer/light_surrogate.h: the desks' illuminance read
    // from the room without its furniture, the screens' glare from pose tables) and the
    // exact rules, cooling on the schedule, no light traced; one traced look at its best
    // (measured independently, at the selection's paths) corrects the surrogate and its
    // last quarter runs again, looked at too. Of `plans` such plans, the one whose look
    // reads the lowest C is where the traced chain starts, its first cycle cold (at the
    // schedule's end: the noise floor sets the temperature), and stays a candidate with
    // that look; a look that meets every goal with the margin ends the planning.
    // planIterations 0: off (the paper's start).
    int planIterations = 20000;
    int plans = 8;
    int planPaths = 64;       // per cell of the surrogate's fields
    int planTablePaths = 32;  // per point or stratum of a pose table's samplers, at each pose
    // StartFrom::Given's layout (optimize --start): every movable entity placed.
    std::optional<Layout> startLayout;
    // Best-so-far snapshots (OptimizerResult::snapshots) at this many checkpoints,
    // iteration ceil(iterations (k / n)^2) for k = 1..n (dense early, where the cost
    // falls fastest), and where the run stops; 0: none.
    int snapshots = 0;
    // The result and the suggestions rounded as layout.json writes them (0.1 mm, 0.01
    // degree: roundedLayout, scene/layout.h) before they are evaluated and measured for
    // the report, so that the file measures what the report says. Where the nearest
    // rounding breaks a rule the unrounded layout held (a footprint against a wall), each
    // moved entity tries the other ways. Off: the chain's layouts as they are.
    bool roundResult = true;
    int progressEvery = 100;     // iterations between progress callbacks
    int traceEvery = 0;          // iterations between trace rows; 0: about 10^4 rows per run
};

// The search's settings from the scene's "optimizer" object (with any --set over it:
// scene/settings.h); the rest at their defaults.
OptimizerOptions optimizerOptions(const OptimizerSettings& settings);
inline OptimizerOptions optimizerOptions(const Scene& scene) { return optimizerOptions(scene.optimizer); }

struct MoveStats {
    int64_t proposed = 0;
    int64_t outside = 0;           // left the regions (or a null move): stayed without evaluating
    int64_t rejectedGeometry = 0;  // a geometric term rejected the proposal (no lighting evaluated)
    int64_t screened = 0;          // rejected on its geometric change alone (delayed acceptance; no lighting evaluated)
    int64_t accepted = 0;
    // Paths the light of these proposals traced afresh (LightingEvaluator::tracedPaths):
    // where the search's time goes.
    uint64_t pathsTraced = 0;
    double acceptance() const { return proposed ? double(accepted) / double(proposed) : 0.0; }
};

struct LevelStats {
    std::string name;  // "group", "object" or "flat"
    std::vector<int> entities;
    std::array<MoveStats, kMoveTypeCount> moves{};
};

struct TracePoint {
    int iteration = 0;  // proposals made so far
    double current = 0;
    double best = 0;        // kInf while no feasible layout has been found
    bool feasible = false;  // the current layout passes the geometric test
    double temperature = 0;  // of the Metropolis test (0 in the polish)
    double acceptance = 0;   // of the proposals since the previous row
};

// The best layout so far at a checkpoint of the run, with what it had cost to find:
// convergence against wall time and lighting evaluations, re-measured independently
// by scripts/experiments.py.
struct Snapshot {
    int iteration = 0;             // proposals made so far
    double seconds = 0;            // wall time since run() started
    int64_t lightingEvaluations = 0;
    double searchCost = kInf;      // the best layout's cost as the search estimated it
    bool feasible = false;         // some layout passed the geometric test (else `best` is the least violating)
    Layout best;
};

enum class StopReason { Iterations, ZeroCost, Cancelled, NothingToMove };
const char* stopReasonName(StopReason reason);

struct Progress {
    int iteration = 0, iterations = 0;
    double current = 0, best = 0, temperature = 0;
    double recentAcceptance = 0;  // of the proposals since the previous callback
    bool polishing = false;       // in the final zero-temperature polish
    bool feasible = false;          // the chain's layout passes the geometric rules
    bool lightingMeasured = false;  // ... and its cost includes the light (L)
    std::array<double, kMoveTypeCount> acceptance{};  // per move type, over the run so far
    std::array<uint64_t, kMoveTypeCount> proposed{};  // ... of how many proposals
    double seconds = 0, etaSeconds = 0;
};
using ProgressCallback = std::function<void(const Progress&)>;

struct OptimizerResult {
    Layout best;
    // The best layout's cost measured for the report: with a lighting term, by an
    // independent measurement (stream 2) no choice depended on. Without one, exact.
    Evaluation bestEvaluation;
    Evaluation bestSearchEvaluation;  // the same layout as the chain estimated it
    // The candidates the result was chosen from, best search estimate first, each
    // with its independent measurement (stream 1) when a lighting term was measured.
    std::vector<Candidate> candidates;
    int chosenCandidate = 0;
    uint64_t reportSeed = 0;  // the seed bestEvaluation's lighting was measured with (0: none)
    // Per sampler (Scene::samplers order): its range over every layout the search
    // measured, for the verdict on whether its target can be met (optimizer/reach.h).
    std::vector<SamplerRange> samplerRanges;
    GeometryResult bestGeometry;  // with every term (per-constraint penalties)
    Evaluation startEvaluation;
    int iterations = 0;  // proposals made
    int bestIteration = 0;
    int confirmations = 0;  // zero-cost estimates measured again before stopping
    int borrowedRefutations = 0;  // zero-cost estimates refuted by an earlier measurement of the same candidate
    int independentMeasurements = 0;  // confirmations, candidate selection and report together
    double seconds = 0;
    double startSeconds = 0;  // of `seconds`, the start's: its draws, the plan and its measurement
    StopReason stop = StopReason::Iterations;
    bool feasible = false;       // some layout passed the geometric test
    bool startFeasible = false;  // the start did
    bool planned = false;        // the start was planned on the light surrogate (OptimizerOptions::planIterations)
    std::vector<LevelStats> levels;
    std::vector<TracePoint> trace;
    std::vector<Snapshot> snapshots;  // OptimizerOptions::snapshots
    int64_t lightingEvaluations = 0;  // by the chain (not the final measurements)
    LightingNotes lightingNotes;  // the lighting evaluator's own report fields
    // OptimizerOptions::suggestions: distinct layouts, the result first, then the others
    // by their independent measurement (the report's seed), best first.
    std::vector<Candidate> suggestions;
    int polishFrom = 0;  // the iteration the last polish began at (iterations: none)
    OptimizerOptions options;
};

// What initialize() tells while it works; each may be empty. `drawing`: the uniform
// start's draws (how many so far, of at most how many) while none passes the geometric
// rules, about twice a second. `planning`: the planned start's plans looked at so far, of
// how many, and the lowest C a look read (after each pair of plans).
struct StartProgress {
    std::function<void(int drawn, int most)> drawing;
    std::function<void(int looked, int plans, double lowestC)> planning;
};

class Optimizer {
public:
    // `lighting` may be null: L = 0 (so it is when the scene has no samplers).
    Optimizer(const Scene& scene, OptimizerOptions options, LightingEvaluator* lighting = nullptr);

    // The start state (StartFrom); resets the counters and random streams, so a
    // second call starts the same chain again. Called by run() when not called before.
    // `cancel` ends the planned start between its pairs of plans.
    void initialize(const StartProgress& progress = {}, const std::atomic<bool>* cancel = nullptr);
    // One proposal at the level the hierarchy schedule gives, then the Metropolis test.
    void step();
    // Runs to the iteration limit, C = 0 or cancellation (checked before every
    // iteration), then evaluates the best layout's breakdown.
    OptimizerResult run(const ProgressCallback& progress = {}, const std::atomic<bool>* cancel = nullptr);

    const Layout& current() const { return current_; }
    const Evaluation& currentEvaluation() const { return currentEval_; }
    const Layout& best() const { return best_; }
    const Evaluation& bestEvaluation() const { return bestEval_; }
    int iteration() const { return iteration_; }
    // The temperature of the next Metropolis test: the schedule's, raised to the cost's
    // noise when noise-aware (geometric schedules only: a constant one is a plain chain).
    double temperature() const;
    // Whether the run is in its final zero-temperature polish.
    bool polishing() const { return polishing_; }
    const std::vector<LevelStats>& levels() const { return stats_; }
    // Evaluates a layout: G first, the lighting hook only when nothing rejects. The
    // overlap cache follows the layout until step() commits or reverts it.
    Evaluation evaluate(const Layout& layout, const std::vector<Transform>& world);
    // The two halves of evaluate(): the geometric terms (cost without light), then the
    // lighting term of a layout that passed the geometric test.
    Evaluation evaluateGeometry(const std::vector<Transform>& world);
    void addLighting(Evaluation& e, const Layout& layout, const std::vector<Transform>& world);

private:
    // The next proposal's move set and level (stats, random stream); updates the
    // nesting state after a group-level proposal.
    const MoveSet& nextMoves(int& level);
    void setUpNesting(const std::vector<int>& outer, const std::vector<int>& inner);
    void record();
    // Metropolis-Hastings acceptance of `proposed` from the current state.
    bool metropolis(const Evaluation& proposed, double logHastings, double temperature, Rng& rng) const;
    // Delayed acceptance's first stage: the geometric change and the proposal ratio.
    bool geometricStage(const Evaluation& proposed, double logHastings, double temperature, Rng& rng) const;
    // ... and its second: the lighting change, with the noise penalty.
    bool lightingStage(const Evaluation& proposed, double temperature, Rng& rng) const;
    // The variance of the estimated difference of C between two evaluations.
    double differenceVariance(const Evaluation& a, const Evaluation& b) const;
    void noteNoise(const Evaluation& proposed);
    // The polish: from the best layout, zero temperature, fine steps (OptimizerOptions::polishShare).
    Layout plannedStart(Layout start, const StartProgress& progress, const std::atomic<bool>* cancel);
    void startPolish();
    // The polish's level of statistics (added on first use).
    LevelStats& polishLevel();
    // Each turning entity of the current layout snapped to the room's quarter turns, one
    // proposal each, kept where C does not rise (before a zero is confirmed).
    void snapCurrent();
    // The zero-temperature test of the polish and the snaps: G, the light unless the
    // rules alone already exceed the current C, kept when C does not rise (the caches
    // still to commit or revert). Counts into `s`.
    bool descends(const Layout& proposed, MoveStats& s, Evaluation& e);
    // The bookkeeping of an accepted proposal: current, candidates, best.
    void acceptProposal(Layout proposed, Evaluation e);
    // The end of every proposal: the caches follow the decision (when it was
    // evaluated), then the counters, the accepted state and the trace.
    void settle(bool evaluated, bool accept, MoveStats& stats, Layout proposed, Evaluation e);
    void polishStep();
    // Where this cycle's polish begins, and where the cycle ends (Options::restartShare).
    int searchIterations() const;
    int cycleEnd() const;
    void startCycle();
    void refreshCurrent();
    double costError(const Evaluation& e) const;
    // The seed of independent measurement stream `stream`: not the search's.
    uint64_t independentSeed(uint64_t stream) const;
    // The progress callback's report of the run begun at iteration `first`; starts the
    // next window of the recent acceptance.
    Progress progressNow(double seconds, int first);
    // Whether the run may stop at a zero cost: the best layout's zero confirmed by an
    // independent measurement (`confirmedZeroAt`: the best iteration already confirmed)
    // and as many suggestions at zero as asked for.
    bool solved(int& confirmedZeroAt);
    bool enoughSuggestions() const;
    // The best layout measured again independently, kept among the candidates: its cost
    // from here, with the search's margin.
    Evaluation confirmBest();
    // An independent measurement of a layout as the stop reads it: its cost under the
    // search's margin, each error at least what the search's estimate and it differ by.
    Evaluation asConfirmed(const Evaluation& search, const Evaluation& confirmed) const;
    // C with every lighting band narrowed by the search's margin (options_.marginZ errors):
    // between equal costs, the layout further inside its bands.
    double costUnderMargin(const Evaluation& e) const;
    // The run's result once it stopped (all but its seconds).
    OptimizerResult resultOf(StopReason stop, std::vector<Snapshot> snapshots);
    // The result: the candidates measured independently, the best of them measured again.
    void chooseResult(OptimizerResult& r);
    // `layout` as layout.json writes it (OptimizerOptions::roundResult) and `e` with the
    // geometric terms of that layout (its light still to be measured again).
    std::pair<Layout, Evaluation> asWritten(const Layout& layout, const Evaluation& e);
    // OptimizerOptions::suggestions: the distinct layouts kept, each measured with the
    // report's seed, the result among them, best measurement first.
    void chooseSuggestions(OptimizerResult& r);

    const Scene* scene_;
    OptimizerOptions options_;
    LightingEvaluator* lighting_;
    GeometryEvaluator geometry_;
    std::unique_ptr<LightSurrogate> surrogate_;  // the planned start's (null: none)
    bool planned_ = false;                        // this run's chain started from a plan
    std::optional<Evaluation> planLook_;          // the chosen plan's traced look (an independent measurement)
    bool startConfirmed_ = false;                 // that look confirmed the start's zero: the run is solved
    std::unique_ptr<LightMap> lightMap_;  // OptimizerOptions::guidedMoves (null: off or nothing to map)
    std::vector<MoveSet> levels_;
    // Nesting: per top-level entity, the index of its members' move set in focusSets_
    // (-1: no movable members); the object-level steps each set gets; the state.
    std::vector<int> focusOf_;
    std::vector<MoveSet> focusSets_;
    std::vector<int> focusSteps_;
    int innerSteps_ = 4;  // unfocused: object-level steps per group-level one
    // The levels' yield (OptimizerOptions::adaptiveShare): per level, moving means of the
    // cost a lit proposal took off (0 unless accepted and lower) and of the paths it traced.
    std::array<double, 2> yieldGain_{}, yieldPaths_{};
    std::array<int64_t, 2> yieldCount_{};
    void noteYield(int level, double gain, uint64_t paths);
    int objectSteps(Rng& rng) const;
    int innerLeft_ = 0, focus_ = -1;
    std::vector<LevelStats> stats_;
    std::vector<Rng> rngs_;  // one stream per level
    std::vector<uint64_t> streams_;  // the stream id each level's Rng is seeded with
    bool initialized_ = false;
    double startSeconds_ = 0;  // initialize()'s, counted in the first run's seconds
    Layout current_, best_;
    Evaluation currentEval_, bestEval_, startEval_;
    bool feasible_ = false;
    int iteration_ = 0, bestIteration_ = 0, traceEvery_ = 1;
    int confirmations_ = 0, borrowedRefutations_ = 0, independentMeasurements_ = 0;
    int64_t lightingEvaluations_ = 0;
    std::vector<TracePoint> trace_;
    Candidates candidates_;
    double noiseVariance_ = 0;  // moving mean of the decisions' variance over lit proposals
    int64_t noiseCount_ = 0;
    std::vector<MoveSet> polishSets_;  // one over every movable entity (empty: nothing to polish)
    Rng polishRng_{0};
    bool polishing_ = false;
    int polishFrom_ = 0;
    int cycleStart_ = 0;       // the iteration the schedule's cycle began at
    double cycleStartT_ = 0;   // ... and its first temperature
    int64_t windowProposed_ = 0, windowAccepted_ = 0;  // since the last trace row
    int64_t progressProposed_ = 0, progressAccepted_ = 0;  // since the last progress callback
    Candidates suggestions_;
    std::vector<SamplerRange> samplerRanges_;
};

}  // namespace luxplan
