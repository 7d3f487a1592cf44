// The chain samples the Boltzmann law exp(-C/T) at a fixed temperature: visit
// frequencies pass a chi-square test on small targets, which checks that every
// proposal is symmetric or carries its Hastings factor (translate, rotate, swap,
// jump, and the two hierarchy levels together).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/core/rng.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/optimizer.h>
#include "support/chi2.h"
#include "support/scene_builder.h"

namespace luxplan {
namespace {

// L(x) from a function of the world transforms; with lighting weight 1, C = L.
class FunctionLighting : public LightingEvaluator {
public:
    explicit FunctionLighting(std::function<double(const std::vector<Transform>&)> f) : f_(std::move(f)) {}
    double evaluate(const Layout&, const std::vector<Transform>& world, LightingBreakdown* out) override {
        double v = f_(world);
        if (out) out->samplers = {{v, 0, {}, {}}};
        return v;
    }

private:
    std::function<double(const std::vector<Transform>&)> f_;
};

// L(x) estimated with Gaussian noise of standard deviation `sigma` around a
// function of the world transforms. Fresh: each call draws anew. Frozen: the noise is
// a fixed function of the state (as the path tracer's common random numbers make it).
// The breakdown's one sampler carries the estimate and its standard error, with a
// target whose penalty is the value itself (noisyChainScene), so the optimizer sees
// the error it must allow for.
class NoisyLighting : public LightingEvaluator {
public:
    NoisyLighting(std::function<double(const std::vector<Transform>&)> f, double sigma, bool fresh)
        : f_(std::move(f)), sigma_(sigma), fresh_(fresh) {}
    double evaluate(const Layout&, const std::vector<Transform>& world, LightingBreakdown* out) override {
        const double truth = f_(world);
        Rng rng(fresh_ ? hashValues({7, ++calls_}) : hashValues({7, uint64_t(std::llround(truth * 1e9))}));
        // Box-Muller.
        const double u = 1 - rng.uniform(), v = rng.uniform();
        const double estimate = truth + sigma_ * std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * v);
        if (out) out->samplers = {{estimate, sigma_, {}, {}}};
        return estimate;
    }
    bool drawsAnew() const override { return fresh_; }

private:
    std::function<double(const std::vector<Transform>&)> f_;
    double sigma_;
    bool fresh_;
    uint64_t calls_ = 0;
};

// C = L (lighting weight 1), with a sampler so that L is measured at all; the
// entities are the test's.
test::SceneBuilder chainScene() {
    test::SceneBuilder b;
    b.lightingWeight(1).sampler("s", planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 0, 100);
    return b;
}

// The same with a sampler whose penalty is its value above 0 (target [0, 0], elastic
// limit 1), so that L's standard error is the sampler's while estimates stay well
// above 0.
test::SceneBuilder noisyChainScene() {
    test::SceneBuilder b;
    b.lightingWeight(1).sampler("s", planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 0, 0, 1.0);
    return b;
}

struct ChainSetup {
    double temperature = 0.2;
    int samples = 20000;
    int thin = 25;
    Hierarchy hierarchy = Hierarchy::Hierarchical;
    bool hastings = true;
    uint64_t seed = 1;
    bool noiseAware = true;
    bool nested = false;
    int innerIterations = 4;
    bool delayedAcceptance = true;
    // The guided move, its map frozen after `freezeAfter` lit layouts; the first
    // `burnIn` samples are not binned (the map's adaptive part).
    bool guided = false;
    int64_t freezeAfter = 2000;
    int burnIn = 0;
};

// Runs the chain from the scene's placement and bins the state every `thin` steps.
test::Chi2Result sampleChain(const Scene& scene, LightingEvaluator& lighting, const ChainSetup& setup,
                             const std::function<int(const Layout&, const std::vector<Transform>&)>& bin,
                             const std::vector<double>& weights, int64_t* guided = nullptr) {
    OptimizerOptions o;
    o.iterations = setup.samples * setup.thin;
    o.seed = setup.seed;
    o.hierarchy = setup.hierarchy;
    o.schedule.kind = Schedule::Kind::Constant;
    o.schedule.start = setup.temperature;
    o.start = StartFrom::Scene;
    o.stopAtZeroCost = false;
    o.moves.jumpHastings = setup.hastings;
    o.noiseAware = setup.noiseAware;
    o.focusInner = setup.nested;
    o.innerIterations = setup.innerIterations;
    o.delayedAcceptance = setup.delayedAcceptance;
    o.guidedMoves = setup.guided;
    o.lightMap.freezeAfter = setup.freezeAfter;
    Optimizer chain(scene, o, &lighting);
    chain.initialize();
    for (int s = 0; s < setup.burnIn * setup.thin; ++s) chain.step();
    std::vector<double> observed(weights.size(), 0);
    for (int s = 0; s < setup.samples; ++s) {
        for (int t = 0; t < setup.thin; ++t) chain.step();
        const Layout& l = chain.current();
        int b = bin(l, worldTransforms(scene, l));
        EXPECT_GE(b, 0);
        if (b >= 0) observed[size_t(b)] += 1;
    }
    if (guided)
        for (const LevelStats& level : chain.levels()) *guided += level.moves[int(MoveType::Guided)].proposed;
    double total = 0;
    for (double w : weights) total += w;
    std::vector<double> expected;
    for (double w : weights) expected.push_back(setup.samples * w / total);
    return test::chi2Test(observed, expected);
}

// Discrete target: three point regions holding 2, 1 and 3 rotations (rotate + jump,
// where the jump needs its Hastings factor: the regions differ in size). Seven
// states: the first region's two rotations, the second region, the third's four.
Scene threeSlots(test::SceneBuilder b) {
    return b.entity("e")
        .region({0, 0}, {0, 0}, {0, 90})
        .region({5, 0}, {5, 0}, {0})
        .region({10, 0}, {10, 0}, {0, 90, 180, 270})
        .end()
        .build();
}

int threeSlotsState(const std::vector<Transform>& world) {
    double x = world[0].t.x, rot = std::atan2(world[0].m[3], world[0].m[0]);
    int r = (int(std::lround(degrees(rot) / 90)) + 4) % 4;
    return x < 1 ? r : x < 6 ? 2 : 3 + r;
}

TEST(Chain, DiscreteStatesFollowTheBoltzmannLaw) {
    Scene s = threeSlots(chainScene());
    // The state from the placement, the cost from the world transforms: both agree.
    auto state = [](const Layout& l, const std::vector<Transform>&) {
        const Placement& p = l.placements[0];
        int r = int(std::lround(p.rotationDeg / 90)) % 4;
        return p.region == 0 ? r : p.region == 1 ? 2 : 3 + r;
    };
    auto cost = [](int state) { return 0.2 + 0.04 * state; };
    FunctionLighting lighting([&](const std::vector<Transform>& world) { return cost(threeSlotsState(world)); });
    ChainSetup setup;
    std::vector<double> weights;
    for (int st = 0; st < 7; ++st) weights.push_back(std::exp(-cost(st) / setup.temperature));
    auto r = sampleChain(s, lighting, setup, state, weights);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

// Both terms vary: C = 0.5 L + 0.5 G, L from the state and G a distance rule to a
// fixed entity 12 m along x (soft, tolerance 20 m, so the slots pay 0.55, 0.3 and
// 0.05). Delayed acceptance (the rules' change first, the light's after) and the
// single test both sample exp(-C / T).
TEST(Chain, DelayedAcceptanceFollowsTheBoltzmannLaw) {
    test::SceneBuilder b;
    b.lightingWeight(0.5).sampler("s", planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 0, 100);
    b.entity("e")
        .region({0, 0}, {0, 0}, {0, 90})
        .region({5, 0}, {5, 0}, {0})
        .region({10, 0}, {10, 0}, {0, 90, 180, 270})
        .end();  // first, so that threeSlotsState reads it
    b.entity("anchor", {12, 0, 0}).end();
    b.constraint(distanceConstraint({0, 1, 20.0}), "e", "anchor");
    Scene s = b.build();
    auto light = [](int state) { return 0.2 + 0.04 * state; };
    FunctionLighting lighting([&](const std::vector<Transform>& world) { return light(threeSlotsState(world)); });
    // G of each state, from the evaluator itself.
    std::vector<double> geometry;
    for (int st = 0; st < 7; ++st) {
        Layout l = initialLayout(s);
        Placement& p = l.placements[size_t(s.findEntity("e"))];
        p.region = st < 2 ? 0 : st == 2 ? 1 : 2;
        p.position = {p.region * 5.0, 0, 0};
        p.rotationDeg = st < 2 ? 90.0 * st : st == 2 ? 0 : 90.0 * (st - 3);
        GeometryResult g = GeometryEvaluator(s).evaluate(worldTransforms(s, l));
        ASSERT_FALSE(g.rejected) << st;
        geometry.push_back(g.cost);
    }
    EXPECT_GT(geometry[0] - geometry[3], 0.1);  // the rule matters as much as the light
    for (bool delayed : {true, false}) {
        ChainSetup setup;
        setup.delayedAcceptance = delayed;
        std::vector<double> weights;
        for (int st = 0; st < 7; ++st) weights.push_back(std::exp(-(0.5 * light(st) + 0.5 * geometry[size_t(st)]) / setup.temperature));
        auto r = sampleChain(s, lighting, setup, [](const Layout&, const std::vector<Transform>& w) { return threeSlotsState(w); },
                             weights);
        EXPECT_GT(r.pValue, 1e-3) << (delayed ? "delayed" : "single") << "\n" << r.table;
    }
}

// The discrete target of the test above with noisy estimates of C.
class NoisyChain : public ::testing::Test {
protected:
    static constexpr double kSigma = 0.12;
    static int stateOf(const std::vector<Transform>& world) { return threeSlotsState(world); }
    static double cost(int state) { return 0.6 + 0.04 * state; }  // 5 sigma above 0
    test::Chi2Result run(NoisyLighting& lighting, bool noiseAware, const std::vector<double>& weights) {
        Scene s = threeSlots(noisyChainScene());
        ChainSetup setup;
        setup.noiseAware = noiseAware;
        return sampleChain(s, lighting, setup, [](const Layout&, const std::vector<Transform>& w) { return stateOf(w); },
                           weights);
    }
    std::vector<double> trueLaw() const {
        std::vector<double> w;
        for (int st = 0; st < 7; ++st) w.push_back(std::exp(-cost(st) / ChainSetup().temperature));
        return w;
    }
};

// Fresh noise: the penalty method (Ceperley and Dewing 1999) samples the true costs'
// law, the plain test on the estimates does not (the test has the power to tell).
TEST_F(NoisyChain, NoiseAwareAcceptanceFollowsTheTrueLawUnderFreshNoise) {
    NoisyLighting lighting([](const std::vector<Transform>& w) { return cost(stateOf(w)); }, kSigma, true);
    auto r = run(lighting, true, trueLaw());
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

TEST_F(NoisyChain, PlainAcceptanceIsBiasedByFreshNoise) {
    NoisyLighting lighting([](const std::vector<Transform>& w) { return cost(stateOf(w)); }, kSigma, true);
    auto r = run(lighting, false, trueLaw());
    EXPECT_LT(r.pValue, 1e-6) << r.table;
}

// Frozen noise (common random numbers): the noise-aware chain keeps detailed balance
// for the estimates it sees, exp(-C_estimated / T) (the penalty would break it, so it
// is not applied); only an independent measurement removes that noise (the run's
// result, Optimizer::run).
TEST_F(NoisyChain, FrozenNoiseIsSampledAsItsEstimates) {
    NoisyLighting lighting([](const std::vector<Transform>& w) { return cost(stateOf(w)); }, kSigma, false);
    // The estimate of each state, read back through the evaluator.
    std::vector<double> weights;
    const double xs[7] = {0, 0, 5, 10, 10, 10, 10}, rots[7] = {0, 90, 0, 0, 90, 180, 270};
    for (int st = 0; st < 7; ++st) {
        Transform t = Transform::placement({xs[st], 0, 0}, rots[st]);
        ASSERT_EQ(stateOf({t}), st);
        weights.push_back(std::exp(-lighting.evaluate(Layout{}, {t}, nullptr) / ChainSetup().temperature));
    }
    auto r = run(lighting, true, weights);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

// A geometric schedule ends at 0.001, far below the estimates' noise (0.05): the
// noise-aware chain's temperature stops at the noise, the plain one's does not.
TEST_F(NoisyChain, TheTemperatureDoesNotFallBelowTheNoise) {
    Scene s = noisyChainScene().entity("e").region({0, 0}, {10, 0}).end().build();
    for (bool aware : {true, false}) {
        NoisyLighting lighting([](const std::vector<Transform>& w) { return 0.6 + 0.01 * w[0].t.x; }, 0.05, false);
        OptimizerOptions o;
        o.iterations = 2000;
        o.noiseAware = aware;
        o.start = StartFrom::Scene;
        o.polishShare = 0;  // the schedule's own end, not the polish's zero
        Optimizer chain(s, o, &lighting);
        chain.initialize();
        EXPECT_NEAR(chain.temperature(), 0.1, 1e-12);  // the schedule's start is above the noise
        for (int i = 0; i < o.iterations; ++i) chain.step();
        // The noise of a decision: the difference of two estimates of C with an error of
        // 0.05 each, every path traced afresh (this evaluator reports no path cache).
        if (aware) EXPECT_NEAR(chain.temperature(), 0.05 * std::sqrt(2.0), 1e-9);
        else EXPECT_NEAR(chain.temperature(), 0.001, 1e-6);
    }
}

// Continuous target on two rails of lengths 1 and 2 (translate + jump): the density is
// exp(-x / 2) over the union, so the longer rail holds its share only with the
// Hastings factor, and the border bins are right only with refused (not redrawn)
// out-of-range translations.
class ContinuousChain : public ::testing::Test {
protected:
    void SetUp() override {
        scene = chainScene().entity("e", {0.5, 0, 0}).region({0, 0}, {1, 0}).region({3, 0}, {5, 0}).end().build();
        for (int i = 0; i < 5; ++i) edges.push_back({0.2 * i, 0.2 * (i + 1)});
        for (int i = 0; i < 10; ++i) edges.push_back({3 + 0.2 * i, 3 + 0.2 * (i + 1)});
        for (auto [a, b] : edges) weights.push_back(std::exp(-a / 2) - std::exp(-b / 2));
    }
    test::Chi2Result run(bool hastings) {
        FunctionLighting lighting([](const std::vector<Transform>& world) { return 0.1 * world[0].t.x; });
        ChainSetup setup;
        setup.thin = 25;
        setup.hastings = hastings;
        auto bin = [&](const Layout& l, const std::vector<Transform>&) {
            double x = l.placements[0].position.x;
            for (size_t i = 0; i < edges.size(); ++i)
                if (x >= edges[i].first && x <= edges[i].second) return int(i);
            return -1;
        };
        return sampleChain(scene, lighting, setup, bin, weights);
    }
    Scene scene;
    std::vector<std::pair<double, double>> edges;
    std::vector<double> weights;
};

TEST_F(ContinuousChain, FollowsTheBoltzmannLaw) {
    auto r = run(true);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

TEST_F(ContinuousChain, WithoutTheHastingsFactorJumpsAreBiased) {
    auto r = run(false);
    EXPECT_LT(r.pValue, 1e-6) << r.table;  // the test has the power to see a missing factor
}

// The guided move (light_map.h) on a rail 5 m long, beside translate: its map learns
// for the first 2000 lit layouts, then stands still, and the chain follows the
// Boltzmann law with its Hastings factor, not without it. The sampler's penalty is its
// value (0.1 x), so the map is far from uniform: most draws go to the low end.
class GuidedChain : public ::testing::Test {
protected:
    test::Chi2Result run(bool hastings) {
        // The sampler rides on the entity: the map holds the entity's own samplers.
        test::SceneBuilder b;
        b.lightingWeight(1).entity("e", {0.5, 0, 0}).region({0, 0}, {5, 0})
            .sampler("s", planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 0, 0, 1.0).end();
        Scene scene = b.build();
        std::vector<std::pair<double, double>> edges;
        std::vector<double> weights;
        for (int i = 0; i < 10; ++i) edges.push_back({0.5 * i, 0.5 * (i + 1)});
        // C = penalty = value = 0.1 x: weights exp(-0.1 x / 0.2) = exp(-x / 2) per bin.
        for (auto [a, b] : edges) weights.push_back(std::exp(-a / 2) - std::exp(-b / 2));
        FunctionLighting lighting([](const std::vector<Transform>& world) { return 0.1 * world[0].t.x; });
        ChainSetup setup;
        setup.thin = 25;
        setup.hastings = hastings;
        setup.guided = true;
        setup.burnIn = 400;
        auto bin = [&](const Layout& l, const std::vector<Transform>&) {
            double x = l.placements[0].position.x;
            for (size_t i = 0; i < edges.size(); ++i)
                if (x >= edges[i].first && x <= edges[i].second) return int(i);
            return -1;
        };
        test::Chi2Result r = sampleChain(scene, lighting, setup, bin, weights, &guided);
        return r;
    }
    int64_t guided = 0;  // guided proposals made
};

TEST_F(GuidedChain, FollowsTheBoltzmannLawWithItsHastingsFactor) {
    auto r = run(true);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
    EXPECT_GT(guided, 200000);  // half of the proposals
}

TEST_F(GuidedChain, WithoutItsHastingsFactorIsBiased) {
    auto r = run(false);
    EXPECT_LT(r.pValue, 1e-6) << r.table;
}

// Two siblings on three shared point slots (swap + jump).
TEST(Chain, SwapsAndJumpsBetweenSlots) {
    Scene s = chainScene()
                  .entity("p").region({0, 0}, {0, 0}).region({5, 0}, {5, 0}).region({10, 0}, {10, 0}).end()
                  .entity("q", {5, 0, 0}).region({0, 0}, {0, 0}).region({5, 0}, {5, 0}).region({10, 0}, {10, 0}).end()
                  .build();
    auto slot = [](double x) { return int(std::lround(x / 5)); };
    auto cost = [](int sp, int sq) { return 0.1 + 0.05 * sp + 0.12 * sq; };
    FunctionLighting lighting([&](const std::vector<Transform>& w) { return cost(slot(w[0].t.x), slot(w[1].t.x)); });
    ChainSetup setup;
    std::vector<double> weights;
    for (int sp = 0; sp < 3; ++sp)
        for (int sq = 0; sq < 3; ++sq) weights.push_back(std::exp(-cost(sp, sq) / setup.temperature));
    auto r = sampleChain(s, lighting, setup,
                         [&](const Layout& l, const std::vector<Transform>&) {
                             return 3 * slot(l.placements[0].position.x) + slot(l.placements[1].position.x);
                         },
                         weights);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

// A group on two slots and its child on three local slots: the group level and the
// object level alternate (hierarchical) or mix (flat); both keep the target law.
struct TwoLevels {
    Hierarchy hierarchy;
    bool nested;
    int innerIterations;
    const char* name;
};
class TwoLevelChain : public ::testing::TestWithParam<TwoLevels> {};

TEST_P(TwoLevelChain, FollowsTheBoltzmannLaw) {
    Scene s = chainScene()
                  .entity("g").region({0, 0}, {0, 0}).region({5, 0}, {5, 0})
                  .entity("c").region({0, 0}, {0, 0}).region({1, 0}, {1, 0}).region({2, 0}, {2, 0}).end()
                  .end()
                  .build();
    // World x of the child: 0, 1, 2, 5, 6, 7.
    auto state = [](double x) { return x < 3 ? int(std::lround(x)) : 3 + int(std::lround(x - 5)); };
    auto cost = [](int st) { return 0.1 + 0.06 * st; };
    FunctionLighting lighting([&](const std::vector<Transform>& w) { return cost(state(w[1].t.x)); });
    ChainSetup setup;
    setup.hierarchy = GetParam().hierarchy;
    setup.nested = GetParam().nested;
    setup.innerIterations = GetParam().innerIterations;
    std::vector<double> weights;
    for (int st = 0; st < 6; ++st) weights.push_back(std::exp(-cost(st) / setup.temperature));
    auto r = sampleChain(s, lighting, setup,
                         [&](const Layout&, const std::vector<Transform>& w) { return state(w[1].t.x); }, weights);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

INSTANTIATE_TEST_SUITE_P(Chain, TwoLevelChain,
                         ::testing::Values(TwoLevels{Hierarchy::Hierarchical, false, 4, "Hierarchical"},
                                           TwoLevels{Hierarchy::Flat, false, 4, "Flat"},
                                           TwoLevels{Hierarchy::Hierarchical, false, 0, "CycleByDegreesOfFreedom"},
                                           TwoLevels{Hierarchy::Hierarchical, true, 0, "Nested"}),
                         [](const auto& info) { return std::string(info.param.name); });

// Nested: after a group-level proposal, the object-level ones move that group's
// members only; a group without movable members is followed by none.
TEST(Nesting, ObjectProposalsMoveTheMembersOfTheGroupJustProposed) {
    Scene s = chainScene()
                  .entity("a").region({0, 0}, {4, 0})
                  .entity("a1").region({0, 0}, {1, 1}).end()
                  .entity("a2").region({0, 0}, {1, 1}).end()
                  .end()
                  .entity("b", {0, 5, 0}).region({0, 5}, {4, 5})
                  .entity("b1").region({0, 0}, {1, 1}).end()
                  .end()
                  .entity("lone", {0, 9, 0}).region({0, 9}, {4, 9}).end()
                  .build();
    FunctionLighting lighting([](const std::vector<Transform>&) { return 0.5; });
    OptimizerOptions o;
    o.iterations = 3000;
    o.focusInner = true;
    o.innerIterations = 0;  // a: 4 DOF of members over 1 (x only) = 4 steps; b: 2 over 1
    o.start = StartFrom::Scene;
    o.stopAtZeroCost = false;
    o.polishShare = 0;  // the levels' proposals only (a polish moves any entity)
    Optimizer chain(s, o, &lighting);
    chain.initialize();
    const int a = s.findEntity("a"), b = s.findEntity("b"), lone = s.findEntity("lone");
    const int a1 = s.findEntity("a.a1"), a2 = s.findEntity("a.a2"), b1 = s.findEntity("b.b1");
    ASSERT_TRUE(a1 >= 0 && a2 >= 0 && b1 >= 0);
    auto groupProposals = [&] {
        int64_t n = 0;
        for (const MoveStats& m : chain.levels()[0].moves) n += m.proposed;
        return n;
    };
    // The cost is constant, so every proposal inside the regions is accepted and the
    // group a group-level proposal chose is the one that moved (-1: it was refused).
    int group = -1, objectSteps = 0, checked = 0;
    auto expectedSteps = [&](int g) { return g == a ? 4 : g == b ? 2 : 0; };
    for (int i = 0; i < o.iterations; ++i) {
        const Layout before = chain.current();
        const int64_t proposals = groupProposals();
        chain.step();
        const Layout& now = chain.current();
        auto moved = [&](int e) {
            const Placement &p = now.placements[size_t(e)], &q = before.placements[size_t(e)];
            return p.position != q.position || p.rotationDeg != q.rotationDeg;
        };
        if (groupProposals() > proposals) {
            if (group >= 0) {
                EXPECT_EQ(objectSteps, expectedSteps(group));
                ++checked;
            }
            group = moved(a) ? a : moved(b) ? b : moved(lone) ? lone : -1;
            objectSteps = 0;
            continue;
        }
        ++objectSteps;
        if (group == a) {
            EXPECT_FALSE(moved(b1));
        } else if (group == b) {
            EXPECT_FALSE(moved(a1) || moved(a2));
        }
    }
    EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace luxplan
