// Issue 58 reported a daylight time with fractional seconds hanging `measure`. It is
// read to the fraction; a time that is not one is refused at its key.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace daylight_time_cli {

const std::string kOfficeScene = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json";

std::string officeFrom(test::TempDir& dir, const std::string& from) {
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(kOfficeScene));
    scene["daylight"]["from"] = from;
    return dir.write("office.json", scene.dump()).string();
}

TEST(DaylightTimeCli, FractionalSecondsAreMeasured) {
    test::TempDir dir;
    const std::string scene = officeFrom(dir, "2026-03-20T08:00:00.5+02:00");
    test::CliResult r = test::runCli("measure " + scene + " --paths 2 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("paths (2 per point)"), std::string::npos) << r.output;
    r = test::runCli("measure " + scene + " --paths 2 --threads 2 --at 2026-03-20T09:30:00.25+02:00");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("daylight at 2026-03-20T09:30:00.25+02:00"), std::string::npos) << r.output;
}

TEST(DaylightTimeCli, ASecondOf60IsRefusedAtItsKey) {
    test::TempDir dir;
    const std::string scene = officeFrom(dir, "2026-03-20T08:00:59.99999999999999999+02:00");
    test::CliResult r = test::runCli("measure " + scene + " --paths 2 --threads 2");
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(scene + ": /daylight/from: \"2026-03-20T08:00:59.99999999999999999+02:00\": second "
                                    "59.99999999999999999 outside [0, 60) (it rounds to 60)"),
              std::string::npos)
        << r.output;
}

}  // namespace daylight_time_cli
}  // namespace luxplan
