// `measure --at TIME`: one instant of the daylight instead of the scene's period.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

const std::string kOffice = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json";

nlohmann::json measure(const std::string& scene, const std::string& extra) {
    test::CliResult r = test::runCli("measure " + scene + " --json --paths 16 --seed 3 --threads 2 " + extra);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.exitCode == 0 ? nlohmann::json::parse(r.output) : nlohmann::json();
}

// --at T measures exactly what a scene whose period is the one instant T measures.
TEST(MeasureAt, IsTheSceneWithThatInstantAsItsPeriod) {
    const std::string at = "2026-03-20T16:30+02:00";
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(kOffice));
    scene["daylight"]["from"] = at;
    scene["daylight"].erase("to");
    scene["daylight"].erase("step_minutes");
    test::TempDir dir;
    const auto instant = dir.write("instant.json", scene.dump());
    nlohmann::json a = measure(kOffice, "--at " + at), b = measure(instant.string(), ""), period = measure(kOffice, "");
    ASSERT_EQ(a["samplers"].size(), b["samplers"].size());
    EXPECT_EQ(a["at"], at);
    bool differsFromThePeriod = false;
    for (size_t k = 0; k < a["samplers"].size(); ++k) {
        EXPECT_EQ(a["samplers"][k]["value"], b["samplers"][k]["value"]) << a["samplers"][k]["name"];
        differsFromThePeriod |= a["samplers"][k]["value"] != period["samplers"][k]["value"];
    }
    EXPECT_TRUE(differsFromThePeriod);
}

TEST(MeasureAt, RefusesABadTimeAndASceneWithoutDaylight) {
    test::CliResult r = test::runCli("measure " + kOffice + " --paths 4 --at 2026-03-20T25:00+02:00");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(kOffice + ": /: --at \"2026-03-20T25:00+02:00\": hour 25 outside [0, 23]"), std::string::npos) << r.output;
    test::TempDir dir;
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(kOffice));
    scene.erase("daylight");
    const auto night = dir.write("night.json", scene.dump());
    r = test::runCli("measure " + night.string() + " --paths 4 --at 2026-03-20T12:00+02:00");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(night.string() + ": /: --at 2026-03-20T12:00+02:00: the scene has no \"daylight\" to evaluate at an instant"),
              std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace luxplan
