// `measure --at TIME` with a weather file (sky model perez): the file's hour that contains
// the time, reported at its middle; an open field traced under it gives back the file's
// measured global horizontal illuminance; a missing irradiance is an error naming its line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"
#include "support/test_data.h"

namespace luxplan::perez_at_cli {
namespace {

// A ground box 100 m wide and one horizontal sampler 0.5 m above it.
std::string openField(const std::string& weather) {
    nlohmann::json s = nlohmann::json::parse(R"({
      "luxplan": 1, "name": "open field",
      "materials": {"ground": {"type": "diffuse", "reflectance": 0.2}},
      "geometry": [{"name": "ground", "box": {"min": [-50, -50, -0.1], "max": [50, 50, 0]}, "material": "ground"}],
      "samplers": [{"name": "field", "type": "planar", "center": [0, 0, 0.5], "size": [1, 1], "target": [0, 200000]}],
      "daylight": {"sky": {"model": "perez"}}
    })");
    s["daylight"]["weather"] = weather;
    return s.dump(2);
}

// 21 June, hour 13 of Chicago's TMY3 file (line 4125): 12:00-13:00 CST, global
// horizontal illuminance 96 600 lx (direct normal 734 W/m2, diffuse 205 W/m2).
constexpr double kFileGlobalLx = 96600;

TEST(PerezAtCli, OpenFieldGivesTheFilesGlobalIlluminance) {
    test::TempDir dir;
    const auto scene = dir.write("field.json", openField(test::kChicagoEpw));
    test::CliResult r = test::runCli("measure " + scene.string() +
                                     " --json --paths 256 --seed 3 --threads 2 --at 2026-06-21T12:10-06:00");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json out = nlohmann::json::parse(r.output);
    // The hour containing 12:10 (the year ignored), at its middle in the file's calendar year.
    EXPECT_EQ(out["at"], "2006-06-21T12:30-06:00");
    const double value = out["samplers"][0]["value"], error = out["samplers"][0]["std_error"];
    EXPECT_LT(error, 0.005 * kFileGlobalLx);
    // Noise, plus this hour's difference between the model's open field and the file (0.5 %).
    EXPECT_NEAR(value, kFileGlobalLx, 4 * error + 0.01 * kFileGlobalLx);
}

TEST(PerezAtCli, MissingIrradianceOfTheHourIsAnErrorNamingItsLine) {
    test::TempDir dir;
    std::ifstream in(test::kChicagoEpw);
    std::stringstream text;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (n == 4125) {  // 21 June hour 13: its diffuse horizontal irradiance (field 16) marked missing
            std::stringstream fields(line);
            std::string f, rebuilt;
            for (int k = 1; std::getline(fields, f, ','); ++k) rebuilt += (k > 1 ? "," : "") + (k == 16 ? std::string("9999") : f);
            line = rebuilt;
        }
        text << line << "\n";
    }
    const auto epw = dir.write("broken.epw", text.str());
    const auto scene = dir.write("field.json", openField(epw.string()));
    test::CliResult r = test::runCli("measure " + scene.string() + " --paths 4 --threads 2 --at 2026-06-21T12:10-06:00");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(epw.string() + ":4125: --at 2026-06-21T12:10-06:00: the diffuse horizontal irradiance of that hour "
                                           "(2006-06-21T12:30-06:00) is missing"),
              std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace luxplan::perez_at_cli
