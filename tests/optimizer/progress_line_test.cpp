// The progress line in words.
#include <gtest/gtest.h>

#include <luxplan/optimizer/progress_line.h>

namespace luxplan {
namespace {

Progress running() {
    Progress p;
    p.iteration = 1400, p.iterations = 3000;
    p.current = 0.01612, p.best = 0.01491;
    p.feasible = p.lightingMeasured = true;
    p.acceptance = {0.52, 0.74, 0.0, 0.0, 0.0};
    p.proposed = {700, 500, 0, 0, 0};
    p.temperature = 0.0123, p.recentAcceptance = 0.31;
    p.seconds = 37, p.etaSeconds = 42.4;
    return p;
}

TEST(ProgressLine, SaysWhereTheSearchIsInWords) {
    EXPECT_EQ(progressLine(running()),
              "iteration 1400 of 3000 | cost 0.0161, best 0.0149 (light and rules) | accepted: translate 52%, rotate 74% | "
              "temperature 0.012, 31% accepted lately | 37s, about 42s left");
    Progress cold = running();
    cold.temperature = 0.00042;
    EXPECT_NE(progressLine(cold).find("| temperature 4.2e-04, 31% accepted lately |"), std::string::npos);
    Progress polish = running();
    polish.polishing = true;
    polish.temperature = 0;
    polish.proposed[4] = 30, polish.acceptance[4] = 0.2;
    EXPECT_EQ(progressLine(polish),
              "iteration 1400 of 3000 | cost 0.0161, best 0.0149 (light and rules) | accepted: translate 52%, rotate 74%, "
              "snap 20% | polishing the best (zero temperature), 31% kept lately | 37s, about 42s left");
}

TEST(ProgressLine, NamesTheArrangingPhase) {
    Progress p = running();
    p.feasible = p.lightingMeasured = false;
    p.current = 0.84;
    p.best = kInf;
    p.proposed[3] = 10, p.acceptance[3] = 0.1;
    EXPECT_EQ(progressLine(p),
              "iteration 1400 of 3000 | arranging: no layout keeps every rule within its limit yet (rules' cost 0.8400, "
              "light not measured) | accepted: translate 52%, rotate 74%, jump 10% | temperature 0.012, 31% accepted lately | "
              "37s, about 42s left");
    p.feasible = true;
    EXPECT_EQ(lightingStartsLine(p), "by iteration 1400: a layout keeps every rule within its limit");
    p.lightingMeasured = true;
    EXPECT_EQ(lightingStartsLine(p), "by iteration 1400: a layout keeps every rule within its limit; from here the "
                                     "cost includes the light, so it may rise");
}

TEST(ProgressLine, TheLastLineHasNoTimeLeftAndDurationsReadAsTime) {
    Progress p = running();
    p.iteration = 3000;
    p.seconds = 3725;
    EXPECT_EQ(progressLine(p).substr(progressLine(p).rfind('|')), "| 1h02m");
    EXPECT_EQ(durationText(185), "3m05s");
    EXPECT_EQ(durationText(-1), "0s");
}

}  // namespace

// Issue 58: a large measurement says its size before it starts, and its progress.
namespace measurement_size_lines {

TEST(MeasurementSize, WarnsAboveTheThresholdOnly) {
    EXPECT_EQ(largeMeasurementWarning("measuring", 1000000, 100, 1000),
              "warning: measuring 1000000 points (100 samplers) x 1000 paths per point = 1e+09 paths, more than 2e+07: "
              "it may run for minutes (fewer paths per point or coarser grids take less)");
    EXPECT_EQ(largeMeasurementWarning("measuring", 20000, 1, 1000), "");  // 2e7: not more
    EXPECT_EQ(largeMeasurementWarning("measuring", 20001, 1, 1000).rfind(
                  "warning: measuring 20001 points (1 sampler) x 1000 paths per point = 2e+07 paths, more than 2e+07", 0),
              0u);
}

TEST(MeasurementSize, ProgressInSharesAndTimeLeft) {
    EXPECT_EQ(measureProgressLine(250, 1000, 10), "measuring: 25% of 1e+03 paths (10s, about 30s left)");
    EXPECT_EQ(measureProgressLine(0, 1000000000ull, 3, true), "measuring: 0% of at most 1e+09 paths (3s)");
    EXPECT_EQ(measureProgressLine(1000, 1000, 62), "measuring: 100% of 1e+03 paths (1m02s)");
}

}  // namespace measurement_size_lines
}  // namespace luxplan
