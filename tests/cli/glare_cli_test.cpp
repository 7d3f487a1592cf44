// What measure says of the glare samplers: the value ("<10" for a UGR below 10 in
// text, the raw number in JSON), the sources found with L, omega and P, and errors in
// their keys with the file and the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

// A 0.1 x 0.1 m panel of 20000 cd/m2 2 m ahead of and 1 m above an eye, under a
// uniform sky; a second eye looks away from it.
const char* kGlareScene = R"({"luxplan": 1,
  "daylight": {"sky": {"model": "uniform", "luminance_nits": 1000}, "ground_reflectance": 0},
  "luminaires": [{"name": "panel", "shape": "rect", "center": [2, 0, 1], "normal": [0, 0, -1], "up": [0, 1, 0],
                  "size": [0.1, 0.1], "flux_lm": 628.3185}],
  "samplers": [
    {"name": "ugr", "type": "ugr", "origin": [0, 0, 0], "direction": [1, 0, 0], "target": [0, 19]},
    {"name": "away", "type": "ugr", "origin": [0, 0, 0], "direction": [-1, 0, 0], "target": [0, 19]},
    {"name": "dgp", "type": "dgp", "origin": [0, 0, 0], "direction": [1, 0, 0], "source_threshold_nits": 2000,
     "target": [0, 0.35]}]})";

TEST(GlareCli, MeasureGivesTheSourcesFound) {
    test::TempDir dir;
    auto file = dir.write("scene.json", kGlareScene);
    test::CliResult r = test::runCli("measure " + file.string() + " --paths 200 --threads 2 --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto samplers = nlohmann::json::parse(r.output)["samplers"];
    ASSERT_EQ(samplers.size(), 3u);
    const auto& sources = samplers[0]["glare"]["sources"];
    ASSERT_EQ(sources.size(), 1u);
    EXPECT_NEAR(sources[0]["luminance"].get<double>(), 20000, 50);
    EXPECT_EQ(sources[0]["kind"], "luminaire");
    EXPECT_EQ(sources[0]["slot"], 0);
    EXPECT_GT(sources[0]["solid_angle"].get<double>(), 0);
    EXPECT_GT(sources[0]["position_index"].get<double>(), 1);
    EXPECT_EQ(samplers[1]["value"].get<double>(), 0);  // raw in JSON
    EXPECT_EQ(samplers[1]["glare"]["sources"].size(), 0u);
    EXPECT_EQ(samplers[2]["glare"]["sources"].size(), 1u);

    test::CliResult text = test::runCli("measure " + file.string() + " --paths 200 --threads 2");
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("<10"), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("1 source; luminaire ["), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("DGP 0."), std::string::npos) << text.output;
}

TEST(GlareCli, BadKeysAreReportedWithTheFileAndPath) {
    test::TempDir dir;
    auto file = dir.write("scene.json", R"({"luxplan": 1,
      "samplers": [{"name": "d", "type": "dgp", "origin": [0, 0, 1.2], "direction": [1, 0, 0],
                    "source_threshold_nits": -5, "target": [0, 0.35]},
                   {"name": "c", "type": "dgp", "origin": [0, 0, 1.2], "direction": [1, 0, 0],
                    "direction_cells": 1, "target": [0, 0.35]},
                   {"name": "u", "type": "ugr", "origin": [0, 0, 1.2], "target": [0, 19]}]})");
    test::CliResult r = test::runCli("validate " + file.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(file.string() + ": /samplers/0/source_threshold_nits"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /samplers/1/direction_cells"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /samplers/2"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("direction"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace luxplan
