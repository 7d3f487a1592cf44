// `measure --daylight-factor`: each planar sampler's mean daylight factor (%) under the
// CIE overcast sky, the luminaires off; the scene's own daylight is not used.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace daylight_factor_cli_test {

using Json = nlohmann::json;

// A 5 x 4 x 3 m room with a glazed south window, a panel, a work plane, a desk's plane
// (carried) and a cylindrical sampler, under a sunny sky the daylight factor ignores.
Json windowedRoom() {
    return Json::parse(R"({"luxplan": 1,
      "site": {"latitude": 45, "longitude": 7},
      "daylight": {"sky": {"model": "preetham", "turbidity": 3}, "from": "2026-06-21T12:00+02:00", "ground_reflectance": 0.3},
      "materials": {"wall": {"type": "diffuse", "reflectance": 0.6}, "floor": {"type": "diffuse", "reflectance": 0.3},
                    "glass": {"type": "glass", "transmittance": 0.8}, "wood": {"type": "diffuse", "reflectance": 0.4}},
      "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [5, 4, 3]},
                    "materials": {"floor": "floor", "walls": "wall", "ceiling": "wall"},
                    "openings": [{"wall": "south", "offset": 1, "width": 3, "sill": 0.9, "height": 1.6, "material": "glass"}]}],
      "luminaires": [{"name": "panel", "shape": "rect", "center": [2.5, 2, 2.99], "normal": [0, 0, -1], "size": [0.6, 0.6],
                      "flux_lm": 4000}],
      "entities": [{"name": "desk", "position": [2.5, 2.5], "placement": {"regions": [{"min": [1, 1], "max": [4, 3]}]},
                    "parts": [{"preset": "desk", "material": "wood"}],
                    "samplers": [{"name": "task", "type": "planar", "center": [0, 0, 0.76], "size": [1.2, 0.6], "grid": [2, 2],
                                  "target": [300, null]}]}],
      "samplers": [
        {"name": "face", "type": "cylindrical", "center": [2.5, 1.5, 1.2], "target": [50, null]},
        {"name": "work", "type": "planar", "center": [2.5, 2, 0.8], "size": [4, 3], "grid": [4, 3], "target": [300, null]}]})");
}

test::CliResult run(const test::TempDir& dir, const Json& scene, const std::string& options) {
    const auto file = dir.write("scene.json", scene.dump());
    return test::runCli("measure " + file.string() + " --daylight-factor --threads 2 " + options);
}

TEST(DaylightFactorCli, JsonGivesEachPlanarSamplersDaylightFactor) {
    test::TempDir dir;
    test::CliResult r = run(dir, windowedRoom(), "--json --paths 32 --seed 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Json out = Json::parse(r.output);
    EXPECT_EQ(out["daylight_factor"]["sky"], "cie_overcast");
    EXPECT_NEAR(out["daylight_factor"]["horizontal_illuminance_lx"].get<double>(), 10000, 10);
    EXPECT_EQ(out["daylight_factor"]["ground_reflectance"], 0.3);
    EXPECT_EQ(out["daylight_factor"]["luminaires"], "off");
    EXPECT_EQ(out["paths_per_point"], 32);
    // The planar samplers only, in the scene's order.
    const Json& samplers = out["samplers"];
    ASSERT_EQ(samplers.size(), 2u);
    std::set<std::string> names;
    for (const Json& s : samplers) names.insert(s["name"].get<std::string>());
    EXPECT_EQ(names, (std::set<std::string>{"work", "desk.task"}));
    for (const Json& s : samplers) {
        const double df = s["daylight_factor"].get<double>(), error = s["daylight_factor_std_error"].get<double>();
        EXPECT_GT(df, 0.5) << s;
        EXPECT_LT(df, 30) << s;
        EXPECT_GT(error, 0) << s;
        EXPECT_LT(error, df) << s;
        EXPECT_NEAR(df, 100 * s["illuminance_lx"].get<double>() / out["daylight_factor"]["horizontal_illuminance_lx"].get<double>(),
                    1e-9 * df);
        double mean = 0, least = 1e9;
        for (const Json& p : s["points"]) mean += p.get<double>() / double(s["points"].size()), least = std::min(least, p.get<double>());
        EXPECT_NEAR(mean, df, 1e-9 * df);
        EXPECT_EQ(s["daylight_factor_min"].get<double>(), least);
    }
    for (const Json& s : samplers)
        if (s["name"] == "work") {
            EXPECT_EQ(s["grid"], Json::parse("[4, 3]"));
            EXPECT_EQ(s["points"].size(), 12u);
        }
}

TEST(DaylightFactorCli, TheTableListsThePlanarSamplers) {
    test::TempDir dir;
    test::CliResult r = run(dir, windowedRoom(), "--paths 8");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("daylight factor: CIE standard overcast sky, 10000 lx on the open horizontal plane, ground "
                            "reflectance 0.30, luminaires off"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("DF %"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\nwork "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("\ndesk.task "), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("\nface "), std::string::npos) << r.output;
}

// Open ground: a plane with nothing above it reads 100% (within its error).
TEST(DaylightFactorCli, OpenGroundIs100Percent) {
    test::TempDir dir;
    const Json scene = Json::parse(R"({"luxplan": 1,
      "samplers": [{"name": "lawn", "type": "planar", "center": [0, 0, 0.8], "size": [2, 2], "grid": [2, 2], "target": [0, null]}]})");
    test::CliResult r = run(dir, scene, "--json --paths 4000");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Json lawn = Json::parse(r.output)["samplers"][0];
    const double df = lawn["daylight_factor"].get<double>(), error = lawn["daylight_factor_std_error"].get<double>();
    EXPECT_GT(error, 0);
    EXPECT_NEAR(df, 100, 4 * error) << "std error " << error;
}

// A window walled up (an opaque pane): no daylight enters, the daylight factor is 0.
TEST(DaylightFactorCli, AClosedRoomReadsZero) {
    test::TempDir dir;
    Json scene = windowedRoom();
    scene["geometry"][0]["openings"][0]["material"] = "wall";
    test::CliResult r = run(dir, scene, "--json --paths 64");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const Json& s : Json::parse(r.output)["samplers"]) {
        EXPECT_EQ(s["daylight_factor"].get<double>(), 0) << s;
        EXPECT_EQ(s["daylight_factor_std_error"].get<double>(), 0) << s;
    }
}

TEST(DaylightFactorCli, RefusesScenesWithoutOpeningsOrPlanarSamplers) {
    test::TempDir dir;
    Json closed = windowedRoom();
    closed["geometry"][0].erase("openings");
    const auto closedFile = dir.write("closed.json", closed.dump());
    test::CliResult r = test::runCli("measure " + closedFile.string() + " --daylight-factor --paths 4");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find(closedFile.string() + ": /: --daylight-factor: the room has no openings (windows or rooflights): "
                                                  "no daylight enters it, so every daylight factor would be 0"),
              std::string::npos)
        << r.output;
    Json planeless = windowedRoom();
    planeless["samplers"].erase(1);
    planeless["entities"][0].erase("samplers");
    const auto planelessFile = dir.write("planeless.json", planeless.dump());
    r = test::runCli("measure " + planelessFile.string() + " --daylight-factor --paths 4");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find(planelessFile.string() + ": /: --daylight-factor: the scene has no planar sampler: the daylight "
                                                     "factor is measured at a planar sampler's points (a work plane)"),
              std::string::npos)
        << r.output;
    // Options and settings that mean nothing under the overcast sky are command-line mistakes.
    for (const char* option : {"--at 2026-06-21T12:00+02:00", "--set adaptive=true", "--set light_roulette=0.2"}) {
        r = test::runCli("measure " + closedFile.string() + " --daylight-factor --paths 4 " + option);
        EXPECT_EQ(r.exitCode, 2) << option << ": " << r.output;
        EXPECT_NE(r.output.find("excludes"), std::string::npos) << r.output;
    }
}

}  // namespace daylight_factor_cli_test
}  // namespace luxplan
