// Whether a target can be met (optimizer/reach.h): the verdicts, and the range the
// optimizer keeps over every layout it measured.
#include <gtest/gtest.h>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/reach.h>
#include "support/desk_light.h"
#include "support/shared_scenes.h"

namespace luxplan {
namespace {

LightSamplerSpec desk() {
    LightSamplerSpec s;
    s.name = "desk";
    s.type = planarSampler({0, 0, 0.76}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2});
    s.targetMin = 300, s.targetMax = 500, s.tolerance = 100;
    return s;
}

SamplerRange seen(const LightSamplerSpec& s, std::initializer_list<std::pair<double, double>> estimates) {
    SamplerRange r;
    for (auto [v, e] : estimates) r.add(s, v, e);
    return r;
}

TEST(Reach, Verdicts) {
    const LightSamplerSpec s = desk();
    EXPECT_EQ(reachVerdict(s, seen(s, {{200, 5}}), 400).reach, Reach::Met);
    EXPECT_EQ(reachVerdict(s, SamplerRange(), 100).reach, Reach::NotMeasured);

    ReachVerdict low = reachVerdict(s, seen(s, {{100, 10}, {180, 20}, {150, 5}}), 170);
    EXPECT_EQ(low.reach, Reach::OutOfReach);
    EXPECT_EQ(low.reason, "at most 180 lx over the 3 layouts the search measured, below the target's minimum of 300 lx: "
                          "nowhere the search tried gets enough light; add or move light, or widen the regions");
    // One layout only (nothing moves): no regions to widen.
    EXPECT_EQ(reachVerdict(s, seen(s, {{120, 5}}), 120).reason,
              "at most 120 lx in the one layout the search measured, below the target's minimum of 300 lx: nowhere the "
              "search tried gets enough light; add or move light");
    ReachVerdict high = reachVerdict(s, seen(s, {{900, 10}, {2000, 20}}), 950);
    EXPECT_EQ(high.reach, Reach::OutOfReach);
    EXPECT_NE(high.reason.find("at least 900 lx over the 2 layouts the search measured, above the target's maximum of "
                               "500 lx"), std::string::npos)
        << high.reason;

    // Within two standard errors of the band, never in it: not proven out of reach.
    ReachVerdict close = reachVerdict(s, seen(s, {{280, 15}, {250, 5}}), 280);
    EXPECT_EQ(close.reach, Reach::NeverMet);
    EXPECT_EQ(close.reason, "met in none of the 2 layouts the search measured, though some came within their noise "
                            "(it read 250 lx to 280 lx)");
    ReachVerdict traded = reachVerdict(s, seen(s, {{100, 5}, {400, 5}, {700, 5}}), 700);
    EXPECT_EQ(traded.reach, Reach::Reached);
    EXPECT_EQ(traded.reason, "met in 1 of the 3 layouts the search measured (it read 100 lx to 700 lx): a trade-off, "
                             "or a longer search");
}

// 500.4 +- 16.7 lx against a 500 lx maximum is at the bound within noise, not missed;
// one standard error further out it is.
TEST(Reach, AValueWithinItsNoiseOfABoundIsNotMissed) {
    const LightSamplerSpec s = desk();  // [300, 500] lx
    ReachVerdict at = reachVerdict(s, seen(s, {{480, 15}, {500.4, 16.7}}), 500.4, 16.7);
    EXPECT_EQ(at.reach, Reach::WithinNoise);
    EXPECT_STREQ(reachName(at.reach), "within_noise");
    EXPECT_EQ(at.reason, "at the target's maximum within its noise (500.4 ± 16.7 lx against 500 lx): met or missed by "
                         "less than one standard error; a measurement with more paths decides");
    EXPECT_EQ(reachVerdict(s, seen(s, {{290, 15}}), 290, 10).reach, Reach::WithinNoise);
    EXPECT_EQ(reachVerdict(s, seen(s, {{289, 15}}), 289, 10).reach, Reach::NeverMet);
    EXPECT_EQ(reachVerdict(s, seen(s, {{517.2, 16.7}}), 517.2, 16.7).reach, Reach::NeverMet);
}

// Met in every layout the search measured, missed in the result's own measurement: the
// advice says so, never "a trade-off".
TEST(Reach, MetEverywhereTheSearchLookedSaysSo) {
    const LightSamplerSpec s = desk();
    ReachVerdict v = reachVerdict(s, seen(s, {{400, 5}, {450, 5}, {490, 5}}), 540, 10);
    EXPECT_EQ(v.reach, Reach::Reached);
    EXPECT_EQ(v.reason.find("a trade-off"), std::string::npos) << v.reason;
    EXPECT_EQ(v.reason, "met in all 3 layouts the search measured (it read 400 lx to 490 lx), but not in the result's own "
                        "measurement (540.0 ± 10.0 lx): the search's estimates read it inside its band; a wider "
                        "optimizer.margin or more optimizer.paths_per_point keeps it inside");
}

// A statistics goal past its bound by less than its standard error: within noise.
TEST(Reach, AStatisticsGoalWithinNoiseIsNotMissed) {
    LightSamplerSpec s = desk();
    StatisticGoal u0;
    u0.statistic = Statistic::U0, u0.targetMin = 0.6, u0.targetMax = 1, u0.tolerance = 0.2;
    s.statistics = {u0};
    SamplerResult r;
    r.points = {236, 400, 500, 464};  // mean 400, min 236: u0 = 0.59
    r.pointErrors = {20, 20, 20, 20};
    r.value = 400, r.standardError = 10;
    ReachVerdict v = reachVerdict(s, seen(s, {{400, 10}}), r);
    EXPECT_EQ(v.reach, Reach::WithinNoise) << v.reason;
    EXPECT_NE(v.reason.find("u0 goal is at its bound within noise"), std::string::npos) << v.reason;
}

// A mean on target with a uniformity goal missed: the verdict says which goal.
TEST(Reach, AStatisticsGoalMissedIsNamed) {
    LightSamplerSpec s = desk();
    StatisticGoal u0;
    u0.statistic = Statistic::U0, u0.targetMin = 0.6, u0.targetMax = 1, u0.tolerance = 0.2;
    s.statistics = {u0};
    SamplerResult r;
    r.points = {200, 400, 500, 500};  // mean 400, min 200: u0 = 0.5
    r.pointErrors = {1, 1, 1, 1};
    r.value = 400, r.standardError = 0.5;
    ReachVerdict v = reachVerdict(s, seen(s, {{400, 1}}), r);
    EXPECT_EQ(v.reach, Reach::GoalMissed);
    EXPECT_EQ(v.reason, "its value meets the target, but its u0 goal does not: 0.5 against [0.6, 1]");
    r.points = {350, 400, 420, 430};
    r.value = 400;
    EXPECT_EQ(reachVerdict(s, seen(s, {{400, 1}}), r).reach, Reach::Met);
}

// E = 600 - 100 x lx at the desk (support/desk_light.h): the range covers every
// evaluation, start included.
TEST(Reach, TheOptimizerKeepsEachSamplersRangeOverTheLayoutsItMeasured) {
    const Scene scene = test::optimizerOffice();
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 400;
    o.stopAtZeroCost = false;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    ASSERT_EQ(r.samplerRanges.size(), 1u);
    const SamplerRange& range = r.samplerRanges[0];
    // Every search evaluation, not the independent ones (the report's among them).
    EXPECT_EQ(range.layouts, light.calls - r.independentMeasurements);
    EXPECT_LE(range.lowest, r.bestEvaluation.samplers.samplers[0].value);
    EXPECT_GE(range.highest, r.bestEvaluation.samplers.samplers[0].value);
    EXPECT_LT(range.lowest, range.highest);
}

}  // namespace
}  // namespace luxplan
