// `measure --at TIME`: one instant of the daylight instead of the scene's period.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

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

// report.html's hour by hour: each row is measure --at that hour (64 paths per point).
TEST(MeasureAt, TheReportsHourByHourIsMeasureAtEachHour) {
    test::TempDir dir;
    const auto out = dir.path() / "report";
    test::CliResult r = test::runCli("report " + kOffice + " -o " + out.string() +
                                     " --seed 3 --paths 8 --width 24 --height 16 --spp 1 --cell 2 --cell-paths 1 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(out / "report.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // The office's period is 08:00 to 11:00: four rows.
    for (const char* hour : {"08:00", "09:00", "10:00", "11:00"})
        EXPECT_NE(html.find(std::string("<td>2026-03-20T") + hour + "+02:00</td>"), std::string::npos) << hour;
    const std::string at = "2026-03-20T09:00+02:00";
    const size_t begin = html.find("<tr><td>" + at + "</td>");
    ASSERT_NE(begin, std::string::npos);
    const std::string cells = html.substr(begin, html.find("</tr>", begin) - begin);
    std::vector<double> shown;
    std::regex value(R"re(<td class="num (?:met|missed)">([-0-9.]+)</td>)re");
    for (auto it = std::sregex_iterator(cells.begin(), cells.end(), value); it != std::sregex_iterator(); ++it)
        shown.push_back(std::stod((*it)[1].str()));
    test::CliResult m = test::runCli("measure " + kOffice + " --json --paths 64 --seed 3 --threads 2 --at " + at);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    const nlohmann::json measured = nlohmann::json::parse(m.output);
    ASSERT_EQ(shown.size(), measured["samplers"].size());
    for (size_t k = 0; k < shown.size(); ++k)
        EXPECT_NEAR(shown[k], measured["samplers"][k]["value"].get<double>(), 0.051) << measured["samplers"][k]["name"];
}

// An instant after sunset gets the warning a scene whose period it is gets (none before).
TEST(MeasureAt, WarnsAfterSunset) {
    test::CliResult r = test::runCli("measure " + kOffice + " --paths 2 --threads 2 --at 2026-03-20T23:00+02:00");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(kOffice + ": --at 2026-03-20T23:00+02:00: warning: the sun is below the horizon at "
                                      "2026-03-20T23:00+02:00 (after sunset or before sunrise): the daylight adds no light"),
              std::string::npos)
        << r.output;
    r = test::runCli("measure " + kOffice + " --paths 2 --threads 2 --at 2026-03-20T13:00+02:00");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("below the horizon"), std::string::npos) << r.output;
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
