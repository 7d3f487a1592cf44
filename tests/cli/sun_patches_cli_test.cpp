// The setting sun_patches: measure's choice of estimator, and optimize's (the search's and the
// report's apart).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "compare_estimators.h"
#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

const std::string kOffice = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json";

nlohmann::json measure(const std::string& extra) {
    test::CliResult r = test::runCli("measure " + kOffice + " --json --paths 400 --seed 3 --threads 2 " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.exitCode == 0 ? nlohmann::json::parse(r.output) : nlohmann::json();
}

// The same values either way (within their errors), with less noise in all over the
// sunlit office.
TEST(SunPatchesCli, MeasureGivesTheSameValuesWithLessNoise) {
    nlohmann::json on = measure(""), off = measure("--set sun_patches=off");
    ASSERT_FALSE(on.is_null());
    ASSERT_FALSE(off.is_null());
    EXPECT_EQ(on["sun_patches"], true);
    EXPECT_EQ(off["sun_patches"], false);
    EXPECT_LT(test::planarVarianceRatio(on, off), 0.9);
}

TEST(SunPatchesCli, AnUnknownChoiceIsAnError) {
    test::CliResult r = test::runCli("measure " + kOffice + " --paths 4 --set sun_patches=maybe");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("sun_patches=maybe: unknown sun_patches \"maybe\""), std::string::npos) << r.output;
    r = test::runCli("optimize " + kOffice + " -o /nonexistent --set sun_patches=sometimes");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("(on, off or report)"), std::string::npos) << r.output;
}

// optimize's default samples the patches in the report but not in the search: the search
// (its start and its chain, trace.csv) is the one of `off`, the report's measurement is
// not. (Nor is the choice among the best layouts, nor among the plans: they measure them
// again as the report does; so the start here is drawn, not planned.)
TEST(SunPatchesCli, OptimizeSamplesThemForTheReportOnly) {
    test::TempDir dir;
    auto run = [&](const std::string& name, const std::string& extra) {
        const auto out = dir.path() / name;
        test::CliResult r = test::runCli("optimize " + kOffice + " -o " + out.string() +
                                         " --iterations 60 --paths 16 --seed 2 --threads 2 -q --no-pictures --set plan_iterations=0 " + extra);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        std::ifstream trace(out / "trace.csv"), report(out / "report.json");
        std::stringstream chain;
        chain << trace.rdbuf();
        return std::make_pair(chain.str(), nlohmann::json::parse(report));
    };
    const auto standard = run("report", ""), off = run("off", "--set sun_patches=off"), on = run("on", "--set sun_patches=on");
    EXPECT_FALSE(standard.first.empty());
    EXPECT_EQ(standard.first, off.first);
    EXPECT_EQ(standard.second["start"], off.second["start"]);
    EXPECT_NE(standard.second["C"], off.second["C"]);
    EXPECT_NE(on.first, off.first);
}

}  // namespace
}  // namespace luxplan
