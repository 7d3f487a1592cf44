// `measure --set exterior_sun=on|off`: the sun's light off the facade across the street in the
// paper's afternoon office, taken where the sky's portal samples meet it or found by
// BSDF sampling alone; off in the morning, when the sun is behind that facade.
#include <gtest/gtest.h>


#include <nlohmann/json.hpp>

#include "compare_estimators.h"
#include "run_cli.h"

namespace luxplan {
namespace {

const std::string kScenes = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/paper/";

nlohmann::json measure(const std::string& scene, int paths, const std::string& extra = "") {
    test::CliResult r = test::runCli("measure " + kScenes + scene + " --json --seed 3 --threads 2 --paths " +
                                     std::to_string(paths) + " " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.exitCode == 0 ? nlohmann::json::parse(r.output) : nlohmann::json();
}

// The desks read the same either way (within their errors), with much less noise.
TEST(ExteriorSunCli, TheAfternoonOfficeReadsTheSameWithLessNoise) {
    nlohmann::json on = measure("fig7-office-afternoon.json", 256),
                   off = measure("fig7-office-afternoon.json", 256, "--set exterior_sun=off");
    ASSERT_FALSE(on.is_null());
    ASSERT_FALSE(off.is_null());
    EXPECT_EQ(on["exterior_sun"], true);
    EXPECT_EQ(off["exterior_sun"], false);
    EXPECT_LT(test::planarVarianceRatio(on, off), 0.5);
}

TEST(ExteriorSunCli, TheMorningSunIsBehindTheFacade) {
    EXPECT_EQ(measure("fig7-office-morning.json", 4)["exterior_sun"], false);
}

TEST(ExteriorSunCli, AnUnknownChoiceIsAnError) {
    test::CliResult r = test::runCli("measure " + kScenes + "fig7-office-afternoon.json --paths 4 --set exterior_sun=maybe");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("exterior_sun=maybe: unknown exterior_sun \"maybe\""), std::string::npos) << r.output;
}

}  // namespace
}  // namespace luxplan
