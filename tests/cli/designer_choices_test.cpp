// The designer's choices and control: optimize --suggestions K (distinct layouts, each
// measured again) and --start LAYOUT (the designer's own layout as the start), their
// bad inputs, report.json's goal count, and points covered by furniture
// (measure --json's "covered").
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan::designer {
namespace {

using Result = test::CliResult;
Result run(const std::string& args) { return test::runCli(args); }
nlohmann::json readJson(const std::filesystem::path& file) { return nlohmann::json::parse(std::ifstream(file)); }
nlohmann::json jsonOf(const Result& r) { return nlohmann::json::parse(r.output.substr(r.output.find('{'))); }

// Two tables, each with a reading sampler, in a room lit at its east end; a fixed
// cabinet. Many layouts meet the targets, so the search has several to suggest.
const char* kTwoTables = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.5}, "wood": {"type": "diffuse", "reflectance": 0.4}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [8,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}}],
  "luminaires": [{"name": "lamp", "shape": "rect", "center": [6,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 6000}],
  "entities": [
    {"name": "a", "position": [1.5, 1.5],
     "placement": {"regions": [{"min": [1,1], "max": [7,3], "rotations": [0, 90]}]},
     "parts": [{"preset": "table", "size": [1.0, 0.8, 0.75], "material": "wood"}],
     "samplers": [{"name": "reading", "type": "planar", "center": [0,0,0.76], "size": [0.8,0.6],
                   "grid": [2,2], "target": [150, null], "tolerance": 100}]},
    {"name": "b", "position": [3.5, 1.5],
     "placement": {"regions": [{"min": [1,1], "max": [7,3], "rotations": [0, 90]}]},
     "parts": [{"preset": "table", "size": [1.0, 0.8, 0.75], "material": "wood"}],
     "samplers": [{"name": "reading", "type": "planar", "center": [0,0,0.76], "size": [0.8,0.6],
                   "grid": [2,2], "target": [150, null], "tolerance": 100}]},
    {"name": "cabinet", "position": [0.4, 3.6], "fixed": true,
     "placement": {"regions": [{"min": [0.3,3.5], "max": [0.5,3.7], "rotations": [0]}]},
     "parts": [{"preset": "table", "size": [0.6, 0.4, 1.0], "material": "wood"}]}],
  "constraints": [{"type": "distance", "a": "a", "b": "b", "min": 1.5, "max": null}],
  "objective": {"lighting_weight": 0.5},
  "optimizer": {"iterations": 300, "seed": 3, "paths_per_point": 8, "report_paths_per_point": 32}})";

TEST(DesignerChoices, SuggestionsAreDistinctLayoutsMeasuredAgainAndReadBack) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kTwoTables);
    auto out = dir.path() / "out";
    Result r = run("optimize " + scene.string() + " -o " + out.string() + " --threads 1 -q --no-pictures --suggestions 3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto report = readJson(out / "report.json");
    ASSERT_TRUE(report.contains("suggestions")) << report.dump(1);
    const auto& list = report["suggestions"];
    ASSERT_GE(list.size(), 2u) << report.dump(1);
    ASSERT_LE(list.size(), 3u);
    std::vector<nlohmann::json> layouts;
    double previous = -1;
    EXPECT_DOUBLE_EQ(list[0]["C"].get<double>(), report["C"].get<double>());  // the result first
    for (size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(list[i]["file"], "suggestions/" + std::to_string(i + 1) + ".json");
        const double c = list[i]["C"].get<double>();
        if (i > 0) {
            EXPECT_GE(c, previous);  // then the others, best first
        }
        if (i > 0) previous = c;
        EXPECT_GE(list[i]["C_std_error"].get<double>(), 0);
        ASSERT_TRUE(std::filesystem::exists(out / list[i]["file"].get<std::string>()));
        layouts.push_back(readJson(out / list[i]["file"].get<std::string>()));
        // Each reads back, and its C is the measurement the report gives (the report's seed).
        Result m = run("measure " + scene.string() + " --layout " + (out / list[i]["file"].get<std::string>()).string() +
                       " --threads 1 --json --paths 32 --seed " + std::to_string(report["report_measurement"]["seed"].get<uint64_t>()));
        ASSERT_EQ(m.exitCode, 0) << m.output;
        EXPECT_NEAR(jsonOf(m)["C"].get<double>(), c, 1e-9) << m.output;
    }
    // Mutually distinct: some movable entity more than 0.5 m or 45 degrees apart.
    for (size_t i = 0; i < layouts.size(); ++i)
        for (size_t j = i + 1; j < layouts.size(); ++j) {
            bool distinct = false;
            for (const char* e : {"a", "b"}) {
                const auto &p = layouts[i]["entities"][e], &q = layouts[j]["entities"][e];
                const double dx = p["position"][0].get<double>() - q["position"][0].get<double>();
                const double dy = p["position"][1].get<double>() - q["position"][1].get<double>();
                const double turn = std::fmod(std::abs(p["rotation"].get<double>() - q["rotation"].get<double>()), 360.0);
                distinct = distinct || std::hypot(dx, dy) > 0.5 || std::min(turn, 360 - turn) > 45 || p["region"] != q["region"];
            }
            EXPECT_TRUE(distinct) << layouts[i].dump() << "\n" << layouts[j].dump();
        }
    EXPECT_EQ(layouts[0], readJson(out / "layout.json"));
    // The goal count.
    EXPECT_EQ(report["goals"]["lighting"], 2);
    EXPECT_EQ(report["goals"]["rules"], 2);  // the distance rule and overlap
    EXPECT_NE(r.output.find("lighting goals met"), std::string::npos) << r.output;
}

TEST(DesignerChoices, SuggestionsOutOfRangeAreRefused) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kTwoTables);
    for (const char* k : {"0", "51", "-2", "x"}) {
        Result r = run("optimize " + scene.string() + " -o " + (dir.path() / "o").string() + " --suggestions " + k);
        EXPECT_NE(r.exitCode, 0) << k;
        EXPECT_NE(r.output.find("--suggestions"), std::string::npos) << r.output;
    }
}

TEST(DesignerChoices, TheSearchStartsFromTheDesignersLayout) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kTwoTables);
    auto start = dir.write("mine.json", R"({"entities": {"a": {"position": [6.0, 2.0], "rotation": 90, "region": 0},
                                                          "b": {"position": [2.0, 2.5], "rotation": 0, "region": 0}}})");
    auto out = dir.path() / "out";
    Result r = run("optimize " + scene.string() + " -o " + out.string() + " --threads 1 -q --no-pictures --iterations 0 --start " +
                   start.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // No iterations: the result is the start, placed as the file says.
    auto layout = readJson(out / "layout.json");
    EXPECT_DOUBLE_EQ(layout["entities"]["a"]["position"][0].get<double>(), 6.0) << layout.dump();
    EXPECT_DOUBLE_EQ(layout["entities"]["b"]["position"][1].get<double>(), 2.5) << layout.dump();
    EXPECT_DOUBLE_EQ(layout["entities"]["a"]["rotation"].get<double>(), 90) << layout.dump();
    EXPECT_TRUE(readJson(out / "report.json")["start"]["feasible"].get<bool>());
    // From there the search moves on, and the fixed cabinet never moves (it is not in
    // the layout file: only movable entities are).
    auto on = dir.path() / "on";
    ASSERT_EQ(run("optimize " + scene.string() + " -o " + on.string() + " --threads 1 -q --no-pictures --start " + start.string()).exitCode, 0);
    EXPECT_FALSE(readJson(on / "layout.json")["entities"].contains("cabinet"));
}

TEST(DesignerChoices, ABadStartLayoutIsRefusedWithItsFileAndPath) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kTwoTables);
    const std::string out = " -o " + (dir.path() / "o").string() + " --no-pictures";
    auto unknown = dir.write("unknown.json", R"({"entities": {"sofa": {"position": [2, 2], "rotation": 0}}})");
    Result r = run("optimize " + scene.string() + out + " --start " + unknown.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(unknown.string() + ": /entities/sofa"), std::string::npos) << r.output;
    auto fixed = dir.write("fixed.json", R"({"entities": {"cabinet": {"position": [0.3, 3.5], "rotation": 0}}})");
    r = run("optimize " + scene.string() + out + " --start " + fixed.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(fixed.string() + ": /entities/cabinet"), std::string::npos) << r.output;
    auto outside = dir.write("outside.json", R"({"entities": {"a": {"position": [9.5, 2], "rotation": 0, "region": 0}}})");
    r = run("optimize " + scene.string() + out + " --start " + outside.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(outside.string() + ": /entities/a"), std::string::npos) << r.output;
    r = run("optimize " + scene.string() + out + " --start " + (dir.path() / "none.json").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("none.json"), std::string::npos) << r.output;
}

// A desk whose monitor stands on one of its four task points: that point is covered,
// reported in "covered" and as null, and left out of the mean and the statistics.
const char* kMonitorOnDesk = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.5}, "wood": {"type": "diffuse", "reflectance": 0.4},
                "plastic": {"type": "diffuse", "reflectance": 0.1}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [5,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}}],
  "luminaires": [{"name": "lamp", "shape": "rect", "center": [2.5,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 4000}],
  "entities": [{"name": "desk", "position": [2.5, 2],
                "parts": [{"preset": "desk", "material": "wood"}],
                "samplers": [{"name": "task", "type": "planar", "center": [0,0,0.76], "size": [1.0,0.5],
                              "grid": [2,2], "target": [300, 500]}],
                "children": [{"name": "monitor", "position": [0.25, 0.125, 0.75],
                              "parts": [{"preset": "monitor", "material": "plastic"}]}]}]})";

TEST(DesignerChoices, APointUnderFurnitureIsCoveredAndLeftOut) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kMonitorOnDesk);
    Result r = run("measure " + scene.string() + " --paths 64 --threads 1 --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto s = jsonOf(r)["samplers"][0];
    ASSERT_EQ(s["covered"], nlohmann::json::array({3})) << s.dump(1);
    ASSERT_EQ(s["points"].size(), 4u);
    EXPECT_TRUE(s["points"][3].is_null());
    double sum = 0;
    for (int i = 0; i < 3; ++i) sum += s["points"][i].get<double>();
    EXPECT_NEAR(s["value"].get<double>(), sum / 3, 1e-9 * sum);
    EXPECT_GT(s["stats"]["min"].get<double>(), 0);  // the covered point's 0 is not the minimum
}

}  // namespace
}  // namespace luxplan::designer
