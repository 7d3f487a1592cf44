// The penalty function of Eq. 2 at its boundaries, and the lighting term (Eq. 3).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <luxplan/core/error.h>

#include <luxplan/constraints/penalty.h>

namespace luxplan {
namespace {

TEST(Penalty, ZeroInsideTheRangeAndAtItsBounds) {
    EXPECT_EQ(penalty(1.5, 1, 2, 0.5, 2), 0);
    EXPECT_EQ(penalty(1.0, 1, 2, 0.5, 2), 0);
    EXPECT_EQ(penalty(2.0, 1, 2, 0.5, 2), 0);
}

TEST(Penalty, ReachesOneAtTheElasticLimit) {
    for (double alpha : {1.0, 2.0}) {
        EXPECT_NEAR(penalty(2.5, 1, 2, 0.5, alpha), 1.0, 1e-12);
        EXPECT_NEAR(penalty(0.5, 1, 2, 0.5, alpha), 1.0, 1e-12);
        EXPECT_FALSE(rejects(penalty(2.5 - 1e-9, 1, 2, 0.5, alpha)));
        EXPECT_TRUE(rejects(penalty(2.5 + 1e-9, 1, 2, 0.5, alpha)));
    }
}

TEST(Penalty, StiffnessShapesTheGrowth) {
    // k = brej^-alpha: half the elastic distance gives 1/2 (linear) or 1/4 (quadratic).
    EXPECT_NEAR(penalty(2.25, 1, 2, 0.5, 1), 0.5, 1e-12);
    EXPECT_NEAR(penalty(2.25, 1, 2, 0.5, 2), 0.25, 1e-12);
    EXPECT_NEAR(penalty(0.75, 1, 2, 0.5, 2), 0.25, 1e-12);
    // Twice the elastic distance: 2 and 4.
    EXPECT_NEAR(penalty(3.0, 1, 2, 0.5, 1), 2.0, 1e-12);
    EXPECT_NEAR(penalty(3.0, 1, 2, 0.5, 2), 4.0, 1e-12);
}

TEST(Penalty, OpenEndsAndPointRanges) {
    EXPECT_EQ(penalty(1e9, 1, kInf, 0.5, 2), 0);
    EXPECT_EQ(penalty(-1e9, -kInf, 1, 0.5, 2), 0);
    EXPECT_NEAR(penalty(0.5, 1, kInf, 0.5, 2), 1.0, 1e-12);
    // Eq. 6 form: P(V, 0, 0, Vref, 2) is (V / Vref)^2 and 0 without overlap.
    EXPECT_EQ(penalty(0, 0, 0, 0.05, 2), 0);
    EXPECT_NEAR(penalty(0.02, 0, 0, 0.05, 2), 0.16, 1e-12);
}

TEST(LightingCost, WeightedMeanOfLinearPenalties) {
    Scene scene;
    LightSamplerSpec a, b;
    a.targetMin = 300, a.targetMax = 500, a.tolerance = 200, a.weight = 1;
    b.targetMin = 0, b.targetMax = 100, b.tolerance = 50, b.weight = 3;
    scene.samplers = {a, b};
    EXPECT_NEAR(lightingPenalty(a, 200), 0.5, 1e-12);
    EXPECT_NEAR(lightingPenalty(a, 800), 1.5, 1e-12);  // lighting terms never reject: P may exceed 1
    EXPECT_NEAR(lightingPenalty(b, 150), 1.0, 1e-12);
    EXPECT_NEAR(lightingCost(scene, {200, 150}), (1 * 0.5 + 3 * 1.0) / 4, 1e-12);
    EXPECT_EQ(lightingCost(scene, {400, 50}), 0);
    EXPECT_THROW(lightingCost(scene, {1}), std::invalid_argument);
    EXPECT_EQ(lightingCost(Scene(), {}), 0);
}

TEST(LightingCostError, SecantOfEachPenaltyAddedInQuadrature) {
    Scene scene;
    LightSamplerSpec a, b;
    a.targetMin = 300, a.targetMax = 500, a.tolerance = 200, a.weight = 1;
    b.targetMin = 0, b.targetMax = 100, b.tolerance = 50, b.weight = 3;
    scene.samplers = {a, b};
    auto result = [](double value, double se) {
        SamplerResult r;
        r.value = value, r.standardError = se;
        return r;
    };
    // Below the band: the linear piece's slope 1/200, times the weight share 1/4.
    EXPECT_NEAR(lightingTermError(scene, 0, result(200, 10)), 0.25 * 10 / 200, 1e-12);
    // Well inside the band: no error reaches L.
    EXPECT_EQ(lightingTermError(scene, 0, result(400, 10)), 0);
    // At the band's edge: half the interval crosses it, so half the slope.
    EXPECT_NEAR(lightingTermError(scene, 0, result(500, 10)), 0.25 * 0.5 * 10 / 200, 1e-12);
    // Above b's band: slope 1/50 with the weight share 3/4.
    const double ea = 0.25 * 10 / 200, eb = 0.75 * 5 / 50.0;
    EXPECT_NEAR(lightingCostError(scene, {result(200, 10), result(150, 5)}), std::hypot(ea, eb), 1e-12);
    EXPECT_EQ(lightingCostError(scene, {result(200, 0), result(50, 5)}), 0);
    EXPECT_THROW(lightingCostError(scene, {result(1, 1)}), std::invalid_argument);
}

TEST(Penalty, NonFiniteValuesAreNeverOnTarget) {
    // A NaN once scored 0: every comparison with it is false.
    EXPECT_EQ(penalty(std::nan(""), 1, 2, 0.5, 1), kInf);
    EXPECT_EQ(penalty(kInf, 1, kInf, 0.5, 1), kInf);
    EXPECT_EQ(penalty(-kInf, -kInf, 1, 0.5, 2), kInf);
}

TEST(LightingPenalty, NonFiniteValueIsAnErrorNamingTheSampler) {
    LightSamplerSpec s;
    s.name = "desk";
    s.jsonPath = "/samplers/2";
    s.file = "office.json";
    s.targetMin = 300, s.targetMax = 500, s.tolerance = 100;
    try {
        lightingPenalty(s, std::nan(""));
        ADD_FAILURE() << "a NaN was scored";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "office.json: /samplers/2: sampler \"desk\" measured nan, not a finite number: it cannot be scored");
    }
    EXPECT_THROW(lightingPenalty(s, kInf), SceneError);
    EXPECT_EQ(lightingPenalty(s, 400), 0);
}

// A sampler measured at five points, 300 lx to 500 lx, and its terms.
SamplerResult fivePoints() {
    SamplerResult r;
    r.points = {400, 300, 500, 450, 350};
    r.pointErrors = {8, 6, 10, 9, 7};
    r.value = 400;
    r.standardError = std::sqrt(330.0) / 5;
    return r;
}

LightSamplerSpec withGoals() {
    LightSamplerSpec s;
    s.name = "desk";
    s.jsonPath = "/samplers/0";
    s.file = "office.json";
    s.targetMin = 300, s.targetMax = kInf, s.tolerance = 150, s.weight = 2;
    s.statistics = {{Statistic::Min, 350, kInf, 100, "/samplers/0/statistics/min"},
                    {Statistic::U0, 0.9, 1, 0.2, "/samplers/0/statistics/u0"}};
    return s;
}

TEST(LightingTerms, TheValueFirstThenEachGoalOverThePoints) {
    const std::vector<LightingTerm> terms = lightingTerms(withGoals(), fivePoints());
    ASSERT_EQ(terms.size(), 3u);
    EXPECT_EQ(terms[0].statistic, Statistic::Mean);
    EXPECT_EQ(terms[0].value, 400);
    EXPECT_EQ(terms[0].penalty, 0);
    EXPECT_EQ(terms[1].statistic, Statistic::Min);
    EXPECT_EQ(terms[1].value, 300);
    EXPECT_EQ(terms[1].standardError, 6);
    EXPECT_NEAR(terms[1].penalty, 0.5, 1e-12);  // 50 lx below its floor, tolerance 100
    EXPECT_EQ(terms[2].statistic, Statistic::U0);
    EXPECT_DOUBLE_EQ(terms[2].value, 0.75);
    EXPECT_NEAR(terms[2].penalty, 0.75, 1e-12);  // (0.9 - 0.75) / 0.2
    for (const LightingTerm& t : terms) EXPECT_EQ(t.weight, 2);
    EXPECT_FALSE(allMet(terms));
    EXPECT_TRUE(allMet({terms[0]}));
}

TEST(LightingCost, StatisticsGoalsAreTermsOfTheWeightedMean) {
    Scene scene;
    LightSamplerSpec plain;
    plain.targetMin = 0, plain.targetMax = 100, plain.tolerance = 50, plain.weight = 1;
    scene.samplers = {withGoals(), plain};
    SamplerResult bright;
    bright.value = 150;
    // (2 (0 + 0.5 + 0.75) + 1 * 1) / (2 * 3 + 1): each goal counts in the denominator.
    EXPECT_NEAR(lightingCostOfResults(scene, {fivePoints(), bright}), (2 * 1.25 + 1) / 7, 1e-12);
    EXPECT_THROW(lightingCostOfResults(scene, {bright}), std::invalid_argument);
    EXPECT_THROW(lightingCostOfResults(scene, {bright, bright}), std::invalid_argument);  // goals need points
    // Values alone cannot score a goal.
    EXPECT_THROW(lightingCost(scene, {400, 150}), std::invalid_argument);
}

TEST(LightingCost, WithoutGoalsTheResultsGiveTheValuesNumbers) {
    Scene scene;
    LightSamplerSpec a, b;
    a.targetMin = 300, a.targetMax = 500, a.tolerance = 200, a.weight = 1;
    b.targetMin = 0, b.targetMax = 100, b.tolerance = 50, b.weight = 3;
    scene.samplers = {a, b};
    SamplerResult x = fivePoints(), y;
    x.value = 237.5, y.value = 151.25;
    EXPECT_EQ(lightingCostOfResults(scene, {x, y}), lightingCost(scene, {237.5, 151.25}));
    EXPECT_EQ(lightingCostOfResults(Scene(), std::vector<SamplerResult>()), 0);
}

TEST(LightingTerms, ANonFiniteStatisticIsAnErrorNamingItsGoal) {
    SamplerResult r = fivePoints();
    r.points[0] = -kInf;
    try {
        lightingTerms(withGoals(), r);
        ADD_FAILURE() << "an infinite min was scored";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), "office.json: /samplers/0/statistics/min: sampler \"desk\" measured its min as an "
                                         "infinite value, not a finite number: it cannot be scored");
    }
}

TEST(LightingCostError, EachGoalAddsItsStatisticsErrorThroughItsPenalty) {
    Scene scene;
    LightSamplerSpec plain;
    plain.targetMin = 0, plain.targetMax = 100, plain.tolerance = 50, plain.weight = 1;
    scene.samplers = {withGoals(), plain};
    SamplerResult bright;
    bright.value = 150;  // exact: no error
    const PointStatistics s = pointStatistics(fivePoints().points, fivePoints().pointErrors);
    // L's denominator 2 * 3 + 1; the mean (400 lx, floor 300) is well inside: 0. The min
    // (300 +- 6 below its floor of 350, tolerance 100) and U0 (0.75 below 0.9, tolerance
    // 0.2) are on linear pieces: slope times error.
    const double min = 2.0 / 7 * 6 / 100, u0 = 2.0 / 7 * s.u0.standardError / 0.2;
    EXPECT_NEAR(lightingTermError(scene, 0, fivePoints()), std::hypot(min, u0), 1e-12);
    EXPECT_NEAR(lightingCostError(scene, {fivePoints(), bright}), std::hypot(min, u0), 1e-12);
    EXPECT_EQ(lightingTermError(scene, 1, bright), 0);
}

}  // namespace
}  // namespace luxplan
