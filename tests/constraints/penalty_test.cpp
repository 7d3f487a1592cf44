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

}  // namespace
}  // namespace luxplan
