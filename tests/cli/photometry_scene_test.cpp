// The bundled photometric example (scenes/photometry/): it validates, `info` lists
// its luminaires as photometric with the file's flux, and `measure --json` lights
// both samplers; a broken photometric file fails validation with FILE:LINE.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

const std::string kDownlightsScene = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/photometry/downlights.json";

TEST(PhotometryScene, ValidatesMeasuresAndDescribesItsLuminaires) {
    auto v = test::runCli("validate " + kDownlightsScene);
    EXPECT_EQ(v.exitCode, 0) << v.output;
    auto info = test::runCli("info " + kDownlightsScene);
    EXPECT_NE(info.output.find("dl4 (disk): disk of radius 0.075 m, photometric (downlight.ies), 1200 lm"), std::string::npos)
        << info.output;
    auto m = test::runCli("measure " + kDownlightsScene + " --paths 32 --threads 2 --json");
    ASSERT_EQ(m.exitCode, 0) << m.output;
    auto j = nlohmann::json::parse(m.output);
    for (const auto& s : j["samplers"]) EXPECT_GT(s["value"].get<double>(), 100) << s["name"];
}

TEST(PhotometryScene, ABrokenFileFailsValidationWithItsLine) {
    test::TempDir dir;
    dir.write("bad.ldt", "company\n1\n7\n");
    auto scene = dir.write("s.json", R"({"luxplan": 1, "luminaires": [{"name": "l", "shape": "disk", "center": [0,0,3],
        "radius": 0.1, "photometry": "bad.ldt"}]})");
    auto v = test::runCli("validate " + scene.string());
    EXPECT_NE(v.exitCode, 0);
    EXPECT_NE(v.output.find(scene.string() + ": /luminaires/0/photometry: " + (dir.path() / "bad.ldt").string() +
                            ":3: the symmetry indicator Isym must be an integer in [0, 4], got 7"),
              std::string::npos)
        << v.output;
}

}  // namespace
}  // namespace luxplan
