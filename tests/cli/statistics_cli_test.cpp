// What measure, report and optimize say of the statistics over a sampler's points:
// Em, Emin, Emax and U0 with the grid (EN 12464-1), and one term of Eq. 3 per goal.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using Result = test::CliResult;

// A 2000 lm bulb 2 m above a 5 x 4 m plane in a black void; the plane's EN 12464-1
// grid (9 x 7) carries a U0 and a min goal; a volume and a directional sampler.
const char* kStatisticsScene = R"({"luxplan": 1,
  "luminaires": [{"name": "bulb", "shape": "sphere", "center": [0, 0, 2.8], "radius": 0.01, "flux_lm": 2000}],
  "samplers": [
    {"name": "work", "type": "planar", "center": [0, 0, 0.8], "size": [5, 4], "grid": "en12464", "target": [10, null],
     "statistics": {"u0": {"target": [0.6, 1], "tolerance": 0.2}, "min": {"target": [200, 1e9]}}},
    {"name": "air", "type": "volume", "center": [0, 0, 1.2], "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "points": 8,
     "target": [0, null], "statistics": {"max": {"target": [0, 1000]}}},
    {"name": "view", "type": "directional", "origin": [0, -2, 1.2], "direction": [0, 1, 0], "strata": 2, "target": [0, null]}]})";

TEST(StatisticsCli, MeasureJsonGivesStatsTermsAndTheGrid) {
    test::TempDir dir;
    auto file = dir.write("scene.json", kStatisticsScene);
    Result r = test::runCli("measure " + file.string() + " --paths 16 --threads 2 --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto samplers = nlohmann::json::parse(r.output)["samplers"];
    const auto& work = samplers[0];
    EXPECT_EQ(work["grid"], nlohmann::json::parse("[9, 7]"));
    EXPECT_EQ(work["points"].size(), 63u);
    const auto& stats = work["stats"];
    EXPECT_EQ(stats["mean"].get<double>(), work["value"].get<double>());
    EXPECT_DOUBLE_EQ(stats["u0"].get<double>(), stats["min"].get<double>() / stats["mean"].get<double>());
    EXPECT_LT(stats["min"].get<double>(), stats["max"].get<double>());
    EXPECT_GT(work["stats_std_error"]["u0"].get<double>(), 0);
    const auto& terms = work["terms"];
    ASSERT_EQ(terms.size(), 3u);
    EXPECT_EQ(terms[0]["statistic"], "mean");
    EXPECT_EQ(terms[0]["penalty"], work["penalty"]);
    EXPECT_EQ(terms[1]["statistic"], "min");
    EXPECT_EQ(terms[1]["value"], stats["min"]);
    EXPECT_EQ(terms[1]["target"], nlohmann::json::parse("[200.0, 1e9]"));
    EXPECT_NEAR(terms[1]["penalty"].get<double>(), (200 - stats["min"].get<double>()) / 100, 1e-12);
    EXPECT_EQ(terms[2]["statistic"], "u0");
    EXPECT_EQ(terms[2]["tolerance"], 0.2);
    EXPECT_GE(terms[2]["penalty"].get<double>(), 0);
    EXPECT_EQ(samplers[1]["terms"].size(), 2u);
    EXPECT_TRUE(samplers[1].contains("stats"));
    EXPECT_FALSE(samplers[1].contains("grid"));
    // A directional sampler has no point statistics, only its value's term.
    EXPECT_FALSE(samplers[2].contains("stats"));
    ASSERT_EQ(samplers[2]["terms"].size(), 1u);
    EXPECT_EQ(samplers[2]["terms"][0]["statistic"], "mean");
}

TEST(StatisticsCli, MeasureTableListsEmEminEmaxU0AndEachGoal) {
    test::TempDir dir;
    auto file = dir.write("scene.json", kStatisticsScene);
    Result r = test::runCli("measure " + file.string() + " --paths 16 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("    Em "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" lx, Emin "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(", U0 0."), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(", 9 x 7 grid"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("    Lm "), std::string::npos) << r.output;  // the volume's luminance
    EXPECT_NE(r.output.find("    u0 "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("[0.6, 1]"), std::string::npos) << r.output;
}

TEST(StatisticsCli, ReportJsonAndHtmlListTheStatistics) {
    test::TempDir dir;
    auto file = dir.write("scene.json", kStatisticsScene);
    auto out = dir.path() / "out";
    Result r = test::runCli("optimize " + file.string() + " -o " + out.string() + " --iterations 2 --paths 8 --threads 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = nlohmann::json::parse(std::ifstream(out / "report.json"));
    const auto& work = report["samplers"][0];
    EXPECT_EQ(work["grid"], nlohmann::json::parse("[9, 7]"));
    for (const char* s : {"mean", "min", "max", "u0"}) EXPECT_TRUE(work["stats"].contains(s)) << s;
    EXPECT_EQ(work["terms"].size(), 3u);
    // report.html, from the report command (pictures as small as they come).
    auto shown = dir.path() / "shown";
    r = test::runCli("report " + file.string() + " -o " + shown.string() +
                     " --threads 2 --spp 1 --width 48 --height 32 --paths 8 --cell 0.5 --cell-paths 4");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(shown / "report.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("Statistics over the points (EN 12464-1"), std::string::npos);
    EXPECT_NE(html.find("<td>9 &times; 7</td>"), std::string::npos);
    EXPECT_NE(html.find("<h3>Statistics goals</h3>"), std::string::npos);
}

TEST(StatisticsCli, ValidateNamesTheFileAndPathOfABadGoal) {
    test::TempDir dir;
    auto file = dir.write("scene.json", R"({"luxplan": 1,
      "samplers": [{"name": "view", "type": "directional", "origin": [0, 0, 1], "direction": [0, 1, 0], "target": [0, null],
                    "statistics": {"u0": {"target": [0.6, 1]}}},
                   {"name": "desk", "type": "planar", "center": [0, 0, 1], "size": [1, 1], "target": [0, null],
                    "statistics": {"uo": {"target": [0.6, 1]}}}]})");
    Result r = test::runCli("validate " + file.string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find(file.string() + ": /samplers/0/statistics: statistics are over the points of a planar or volume "
                                            "sampler"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /samplers/1/statistics/uo: unknown statistic \"uo\" (did you mean \"u0\"?) "
                                            "(min, max or u0)"),
              std::string::npos)
        << r.output;
}

// The DIALux-style example of docs/light-transport.md: its grid, and its figures
// (measured there with 1000 paths per point) within 5 combined standard errors.
TEST(StatisticsCli, TheDocumentedOfficeExample) {
    const std::string file = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/checks/en12464-office.json";
    Result r = test::runCli("measure " + file + " --paths 64 --threads 2 --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto work = nlohmann::json::parse(r.output)["samplers"][0];
    EXPECT_EQ(work["grid"], nlohmann::json::parse("[9, 7]"));
    const struct { const char* statistic; double value, error; } documented[] = {
        {"mean", 519.2, 0.69}, {"min", 441.6, 5.71}, {"max", 568.0, 6.66}, {"u0", 0.851, 0.0109}};
    for (const auto& d : documented) {
        const double error = work["stats_std_error"][d.statistic].get<double>();
        EXPECT_NEAR(work["stats"][d.statistic].get<double>(), d.value, 5 * std::hypot(error, d.error)) << d.statistic;
    }
    for (const auto& t : work["terms"]) EXPECT_EQ(t["penalty"], 0.0) << t.dump();
}

}  // namespace
}  // namespace luxplan
