// The command line contract: exit codes and FILE: /json/path: message lines.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <tiny_gltf.h>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using Result = test::CliResult;
Result run(const std::string& args) { return test::runCli(args); }

const std::string kDemo = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json";

TEST(Cli, ValidateAcceptsTheBundledScene) {
    Result r = run("validate " + kDemo);
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(Cli, ValidateReportsEveryErrorAndFails) {
    test::TempDir dir;
    auto file = dir.write("bad.json", R"({"luxplan": 1, "materials": {"m": {"type": "diffuse", "reflectance": 2}},
        "luminaires": [{"name": "l", "shape": "rect", "center": [0,0,3], "size": [1,1], "flux_lm": -1}]})");
    Result r = run("validate " + file.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(file.string() + ": /materials/m/reflectance: value 2 outside [0, 1]"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /luminaires/0/flux_lm: value -1 outside >= 0"), std::string::npos)
        << r.output;
}

TEST(Cli, MalformedJsonAndMissingFile) {
    test::TempDir dir;
    auto file = dir.write("broken.json", "{\"luxplan\": 1,,}");
    Result r = run("validate " + file.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(file.string() + ": /: malformed JSON at line 1, column 15"), std::string::npos) << r.output;
    r = run("validate " + (dir.path() / "none.json").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("none.json: /: cannot open the file"), std::string::npos) << r.output;
}

TEST(Cli, InfoSummarizesTheScene) {
    Result r = run("info " + kDemo);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* part : {"rooms: 1, openings: 3", "luminaires: 6 fixed", "entities: 24", "samplers: 12", "constraints: 27",
                             "overlap rule: tolerance 0.05", "points on", "strata over", " lm\n"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
}

TEST(Cli, UnknownCommandFails) {
    EXPECT_EQ(run("frobnicate").exitCode, 2);
    EXPECT_EQ(run("validate").exitCode, 2);
    EXPECT_EQ(run("--help").exitCode, 0);
}

// Each option's mistake in words, exit 2; a seed up to 2^64 - 1 read exactly (CLI11's
// int64 once turned 18446744073709551615 into 9223372036854775807 silently).
TEST(Cli, OptionValuesAreCheckedAndSeedsReadExactly) {
    auto expectRefused = [](const std::string& args, const std::string& message) {
        Result r = run("measure " + kDemo + " " + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    };
    expectRefused("--paths 0", "--paths: must be at least 1, got 0");
    expectRefused("--paths abc", "--paths: expected a whole number, got abc (at least 1)");
    expectRefused("--paths 3000000000", "--paths: must be at most 2147483647, got 3000000000");
    expectRefused("--threads -1", "--threads: expected a whole number, got -1 (at least 0)");
    expectRefused("--seed 18446744073709551616", "--seed: expected a whole number up to 18446744073709551615, got 18446744073709551616");
    expectRefused("--seed 1e3", "--seed: expected a whole number, got 1e3");
    expectRefused("--set light_roulette=-1", "--set: light_roulette=-1: value -1 outside [0, 10]");
    expectRefused("--set light_roulette=nan", "--set: light_roulette=nan: expected a number, got a string");
    expectRefused("--set light_roulette=11", "--set: light_roulette=11: value 11 outside [0, 10]");
    Result r = run("render " + kDemo + " --cell 0 -o x");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--cell: must be a finite number > 0, got 0"), std::string::npos) << r.output;
    r = run("render " + kDemo + " --camera \"\" -o x");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--camera: expected a camera's name, got \"\""), std::string::npos) << r.output;
    test::TempDir dir;
    auto file = dir.write("lit.json", R"({"luxplan": 1, "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
        "luminaires": [{"name": "l", "shape": "rect", "center": [0,0,3], "normal": [0,0,-1], "size": [1,1], "flux_lm": 1000}],
        "samplers": [{"name": "p", "type": "planar", "center": [0,0,1], "size": [1,1], "target": [10, 500]}]})");
    r = run("measure " + file.string() + " --paths 2 --seed 18446744073709551615 --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(nlohmann::json::parse(r.output)["seed"].get<uint64_t>(), 18446744073709551615ull);
    Result other = run("measure " + file.string() + " --paths 2 --seed 9223372036854775807 --json");
    EXPECT_NE(nlohmann::json::parse(other.output)["samplers"][0]["value"], nlohmann::json::parse(r.output)["samplers"][0]["value"]);
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

TEST(Cli, MeasureJsonFollowsTheContract) {
    test::TempDir dir;
    auto file = dir.write("lit.json", R"({"luxplan": 1, "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
        "luminaires": [{"name": "l", "shape": "rect", "center": [0,0,3], "normal": [0,0,-1], "size": [1,1], "flux_lm": 1000}],
        "samplers": [{"name": "p", "type": "planar", "center": [0,0,1], "size": [1,1], "grid": [2,3], "target": [10, 500]},
                     {"name": "d", "type": "directional", "origin": [0,0,1], "direction": [0,0,1], "strata": 2, "target": [0, null]}]})");
    Result r = run("measure " + file.string() + " --paths 32 --seed 3 --threads 2 --json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto json = nlohmann::json::parse(r.output);
    ASSERT_EQ(json["samplers"].size(), 2u);
    const auto& p = json["samplers"][0];
    EXPECT_EQ(p["name"], "p");
    EXPECT_EQ(p["type"], "planar");
    EXPECT_EQ(p["unit"], "lx");
    EXPECT_EQ(p["points"].size(), 6u);
    EXPECT_EQ(p["target"][0], 10.0);
    EXPECT_GT(p["value"].get<double>(), 0);
    EXPECT_EQ(p["penalty"], 0.0);
    const auto& d = json["samplers"][1];
    EXPECT_EQ(d["unit"], "cd/m2");
    EXPECT_EQ(d["points"].size(), 4u);
    EXPECT_TRUE(d["target"][1].is_null());
    // Same seed and thread count: the same numbers.
    Result again = run("measure " + file.string() + " --paths 32 --seed 3 --threads 1 --json");
    EXPECT_EQ(nlohmann::json::parse(again.output)["samplers"], json["samplers"]);
    EXPECT_EQ(json["light_roulette"], 0.0);
    EXPECT_FALSE(p.contains("light_floor"));
    // The light samples' roulette: each sampler's floor from its pilot, the same at
    // any thread count (here with no surface for a path to meet, the same values too).
    Result rouletted = run("measure " + file.string() + " --paths 32 --seed 3 --threads 2 --set light_roulette=2 --json");
    ASSERT_EQ(rouletted.exitCode, 0) << rouletted.output;
    auto withFloors = nlohmann::json::parse(rouletted.output);
    EXPECT_EQ(withFloors["light_roulette"], 2.0);
    EXPECT_GT(withFloors["samplers"][0]["light_floor"].get<double>(), 0);
    EXPECT_EQ(withFloors["samplers"][0]["points"], p["points"]);
    Result oneThread = run("measure " + file.string() + " --paths 32 --seed 3 --threads 1 --set light_roulette=2 --json");
    EXPECT_EQ(nlohmann::json::parse(oneThread.output)["samplers"], withFloors["samplers"]);
}

// A long daylight period (five days at five-minute steps, about 700 with the sun up)
// takes seconds to bake: measure says how far it is, and how long it took.
TEST(Cli, ALongDaylightBakeReportsItsProgress) {
    test::TempDir dir;
    auto file = dir.write("days.json", R"({"luxplan": 1, "site": {"latitude": 37.98, "longitude": 23.73},
        "daylight": {"sky": {"model": "preetham", "turbidity": 3}, "sun": true,
                     "from": "2026-06-21T00:00+03:00", "to": "2026-06-26T00:00+03:00", "step_minutes": 5},
        "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
        "samplers": [{"name": "p", "type": "planar", "center": [0,0,1], "size": [1,1], "grid": [1,1], "target": [10, null]}]})");
    Result r = run("measure " + file.string() + " --paths 2 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(daylight: the sky of \d+ of \d+ time steps baked \(\d+s left\))")))
        << r.output;
    EXPECT_NE(r.output.find("daylight: baked in "), std::string::npos) << r.output;
}

// One path per point can estimate no error, and a directional sampler cannot hold a
// fold out to choose its brightest stratum: a warning, and n/a in the table.
TEST(Cli, OnePathPerPointWarnsThatItHasNoErrorAndNoCrossFittedMax) {
    test::TempDir dir;
    const std::string lit = R"({"luxplan": 1, "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
        "luminaires": [{"name": "l", "shape": "rect", "center": [0,0,3], "normal": [0,0,-1], "size": [1,1], "flux_lm": 1000}],
        "samplers": [{"name": "p", "type": "planar", "center": [0,0,1], "size": [1,1], "grid": [2,3], "target": [10, 500]})";
    auto planar = dir.write("planar.json", lit + "]}");
    auto both = dir.write("both.json", lit + R"(,
        {"name": "d", "type": "directional", "origin": [0,0,1], "direction": [0,0,1], "strata": 2, "target": [0, null]}]})");
    auto fromFile = dir.write("file.json", lit + R"(], "optimizer": {"paths_per_point": 1, "report_paths_per_point": 1}})");

    Result r = run("measure " + planar.string() + " --paths 1 --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: --paths 1: one path per point gives no standard error"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("directional"), std::string::npos) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(\np +planar +[0-9.]+ +n/a )"))) << r.output;

    r = run("measure " + both.string() + " --paths 1 --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("directional sampler \"d\" reads the plain max of its strata, which errs high"), std::string::npos)
        << r.output;

    r = run("measure " + fromFile.string() + " --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(fromFile.string() + ": /optimizer/report_paths_per_point: 1: one path per point"), std::string::npos)
        << r.output;

    r = run("optimize " + both.string() + " -o " + (dir.path() / "out").string() + " --paths 1 --iterations 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: --paths 1: one path per point"), std::string::npos) << r.output;
    // The setting that gave the count, as it was given: --set, or its path in the file
    // (optimize's search reads paths_per_point, measure report_paths_per_point).
    r = run("measure " + planar.string() + " --set report_paths_per_point=1 --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: --set report_paths_per_point=1: one path per point"), std::string::npos) << r.output;
    r = run("optimize " + fromFile.string() + " -o " + (dir.path() / "out2").string() + " --iterations 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(fromFile.string() + ": /optimizer/paths_per_point: 1: one path per point"), std::string::npos)
        << r.output;
    r = run("optimize " + planar.string() + " -o " + (dir.path() / "out3").string() +
            " --set paths_per_point=1 --iterations 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: --set paths_per_point=1: one path per point"), std::string::npos) << r.output;

    // From 2 paths on: errors, and no warning.
    r = run("measure " + both.string() + " --paths 2 --threads 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("n/a"), std::string::npos) << r.output;
}

TEST(Cli, MeasureRejectsABadLayout) {
    test::TempDir dir;
    auto scene = dir.write("s.json", R"({"luxplan": 1, "entities": [{"name": "a", "placement": {"regions": [{"min": [0,0], "max": [1,1]}]}}]})");
    auto layout = dir.write("layout.json", R"({"entities": {"b": {"position": [0,0,0]}}})");
    Result r = run("measure " + scene.string() + " --layout " + layout.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(layout.string() + ": /entities/b: unknown entity \"b\""), std::string::npos) << r.output;
}

TEST(Cli, SunPrintsTheNrelExample) {
    Result r = run("sun --lat 39.742476 --lon -105.1786 --time 2003-10-17T12:30:30-07:00");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto json = nlohmann::json::parse(r.output);
    // NREL's example is computed at 1830 m, 820 mbar and 11 C; at sea level and standard
    // refraction the position differs by a few thousandths of a degree.
    EXPECT_NEAR(json["altitude_deg"].get<double>(), 90 - 50.111622, 0.02);
    EXPECT_NEAR(json["azimuth_deg"].get<double>(), 194.340241, 0.02);
    EXPECT_NE(run("sun --lat 95 --lon 0 --time 2003-10-17T12:30:30-07:00").exitCode, 0);
    EXPECT_NE(run("sun --lat 0 --lon 0 --time 2003-10-17T12:30:30").exitCode, 0);
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// A table with a reading sampler and two disjoint regions; only the one under the
// luminaire gives the 300 lx the sampler asks for.
const char* kLightSeeking = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.5}, "wood": {"type": "diffuse", "reflectance": 0.4}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [8,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}}],
  "luminaires": [{"name": "lamp", "shape": "rect", "center": [6.5,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 6000}],
  "entities": [{"name": "table", "position": [1.5, 2],
                "placement": {"regions": [{"min": [1,1], "max": [2.5,3], "rotations": [0, 90]},
                                          {"min": [5.5,1], "max": [7,3], "rotations": [0, 90]}]},
                "parts": [{"preset": "table", "size": [1.0, 0.8, 0.75], "material": "wood"}],
                "samplers": [{"name": "reading", "type": "planar", "center": [0,0,0.76], "size": [0.8,0.6],
                              "grid": [2,2], "target": [300, null], "tolerance": 100}]}],
  "objective": {"lighting_weight": 0.8},
  "optimizer": {"iterations": 150, "seed": 2, "paths_per_point": 16, "report_paths_per_point": 64}})";

// A dining set as a group without parts: a table and two chairs that may shift a
// little around it; one luminaire.
const char* kDiningSet = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.5}, "wood": {"type": "diffuse", "reflectance": 0.4}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}}],
  "luminaires": [{"name": "lamp", "shape": "rect", "center": [4.5,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 4000}],
  "entities": [{"name": "set", "position": [2, 2],
                "placement": {"regions": [{"min": [1.2,1.2], "max": [4.8,2.8], "rotations": [0, 90, 180, 270]}]},
                "samplers": [{"name": "table_top", "type": "planar", "center": [0,0,0.76], "size": [0.8,0.6],
                              "grid": [2,2], "target": [300, 600], "tolerance": 100}],
                "children": [
                  {"name": "table", "parts": [{"preset": "table", "size": [1.0, 0.8, 0.75], "material": "wood"}]},
                  {"name": "chair1", "position": [0, -0.6], "rotation": 180,
                   "placement": {"regions": [{"min": [-0.2,-0.7], "max": [0.2,-0.5], "rotations": [180]}]},
                   "parts": [{"preset": "chair", "material": "wood"}]},
                  {"name": "chair2", "position": [0, 0.6],
                   "placement": {"regions": [{"min": [-0.2,0.5], "max": [0.2,0.7], "rotations": [0]}]},
                   "parts": [{"preset": "chair", "material": "wood"}]}]}],
  "constraints": [{"type": "alignment", "a": "set", "b": "room", "tolerance_deg": 10}],
  "objective": {"lighting_weight": 0.5},
  "optimizer": {"iterations": 300, "seed": 4, "paths_per_point": 8, "report_paths_per_point": 64}})";

TEST(Cli, OptimizeFlatRunsTheGrouplessBaselineAndItsLayoutsReadBack) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kDiningSet);
    auto out = dir.path() / "flat";
    Result r = run("optimize " + scene.string() + " -o " + out.string() + " --set flat=true --threads 1 --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("flat: 3 objects without groups, 4 cohesion constraints"), std::string::npos) << r.output;
    auto report = nlohmann::json::parse(std::ifstream(out / "report.json"));
    ASSERT_TRUE(report["feasible"].get<bool>()) << report.dump(1);
    // The settings as the run used them: the file's, --set's, and optimize's defaults
    // for the optional ones.
    const nlohmann::json& settings = report["settings"];
    EXPECT_EQ(settings["flat"], true) << settings.dump(1);
    EXPECT_EQ(settings["hierarchy"], "hierarchical");
    EXPECT_EQ(settings["seed"], 4);
    EXPECT_EQ(settings["iterations"], 300);
    EXPECT_EQ(settings["paths_per_point"], 8);
    EXPECT_EQ(settings["report_paths_per_point"], 64);
    EXPECT_EQ(settings["selection_paths_per_point"], 64);  // 1000, at most the report's
    EXPECT_EQ(settings["sun_patches"], "report");
    EXPECT_EQ(settings["light_roulette"], 0.2);
    int cohesion = 0;
    for (const auto& c : report["constraints"])
        cohesion += c["json_path"].get<std::string>().find("(cohesion with set.table)") != std::string::npos;
    EXPECT_EQ(cohesion, 4);
    // The scene's constraint on the group names the group, not its anchor the table.
    for (const auto& c : report["constraints"]) {
        if (c["json_path"] == "/constraints/0") {
            EXPECT_EQ(c["a"], "set") << c.dump();
        }
    }
    // layout.json is in the scene's hierarchy and validates against it; layout_flat.json
    // measures (flat=true) exactly as the report did.
    auto layout = nlohmann::json::parse(std::ifstream(out / "layout.json"));
    for (const char* e : {"set", "set.chair1", "set.chair2"}) EXPECT_TRUE(layout["entities"].contains(e)) << e;
    Result v = run("validate " + scene.string() + " --layout " + (out / "layout.json").string());
    EXPECT_EQ(v.exitCode, 0) << v.output;
    // The report's measurement is independent of the search: its seed is in report.json.
    ASSERT_EQ(report["report_measurement"]["paths_per_point"], 64) << report.dump(1);
    const std::string repeat =
        " --paths 64 --json --seed " + std::to_string(report["report_measurement"]["seed"].get<uint64_t>());
    EXPECT_NE(report["report_measurement"]["seed"].get<uint64_t>(), 4u);
    Result m = run("measure " + scene.string() + " --set flat=true --layout " + (out / "layout_flat.json").string() + repeat);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    auto measured = nlohmann::json::parse(m.output.substr(m.output.find('{')));
    EXPECT_DOUBLE_EQ(measured["samplers"][0]["value"].get<double>(), report["samplers"][0]["value"].get<double>());
    // The hierarchical reading of layout.json puts everything in the same place; without
    // --paths, measure traces the report's count (one number per quantity).
    Result h = run("measure " + scene.string() + " --layout " + (out / "layout.json").string() + " --json --seed " +
                   std::to_string(report["report_measurement"]["seed"].get<uint64_t>()));
    ASSERT_EQ(h.exitCode, 0) << h.output;
    auto hier = nlohmann::json::parse(h.output.substr(h.output.find('{')));
    EXPECT_NEAR(hier["samplers"][0]["value"].get<double>(), report["samplers"][0]["value"].get<double>(),
                1e-6 * report["samplers"][0]["value"].get<double>());
}

TEST(Cli, OptimizeFindsTheLitRegionAndWritesItsOutputs) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kLightSeeking);
    auto out = dir.path() / "out";
    Result r = run("optimize " + scene.string() + " -o " + out.string() + " --threads 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"layout.json", "report.json", "trace.csv"}) EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
    auto layout = nlohmann::json::parse(std::ifstream(out / "layout.json"));
    EXPECT_EQ(layout["entities"]["table"]["region"], 1) << layout.dump();
    auto report = nlohmann::json::parse(std::ifstream(out / "report.json"));
    EXPECT_TRUE(report.contains("C") && report.contains("L") && report.contains("G"));
    EXPECT_EQ(report["samplers"].size(), 1u);
    EXPECT_GT(report["samplers"][0]["value"].get<double>(), 300);
    // The search's light samples' roulette: its floor per sampler (none with it off).
    EXPECT_GT(report["samplers"][0]["search_light_floor"].get<double>(), 0) << report["samplers"][0].dump();
    auto every = dir.path() / "every";
    ASSERT_EQ(run("optimize " + scene.string() + " -o " + every.string() + " --threads 2 -q --no-pictures --iterations 20 --set light_roulette=0").exitCode, 0);
    EXPECT_FALSE(nlohmann::json::parse(std::ifstream(every / "report.json"))["samplers"][0].contains("search_light_floor"));
    // The layout reads back.
    Result m = run("measure " + scene.string() + " --layout " + (out / "layout.json").string() + " --paths 8 --json");
    EXPECT_EQ(m.exitCode, 0) << m.output;
    // Same seed and thread count: the same layout.
    auto again = dir.path() / "again";
    ASSERT_EQ(run("optimize " + scene.string() + " -o " + again.string() + " --threads 2 -q --no-pictures").exitCode, 0);
    EXPECT_EQ(nlohmann::json::parse(std::ifstream(again / "layout.json")), layout);
}

// check_cache: every path the path cache reads back is traced again and compared;
// the numbers, and so the layout, are those of the run without it (the chairs' moves
// leave the table's paths that miss them to the cache). It needs the cache.
TEST(Cli, OptimizeChecksItsPathCacheAgainstFreshTraces) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kDiningSet);
    auto plain = dir.path() / "plain", checked = dir.path() / "checked";
    const std::string common = " --threads 2 -q --no-pictures --iterations 60";
    ASSERT_EQ(run("optimize " + scene.string() + " -o " + plain.string() + common).exitCode, 0);
    Result r = run("optimize " + scene.string() + " -o " + checked.string() + common + " --set check_cache=true");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("reused paths traced again from scratch gave the same numbers, bit for bit"), std::string::npos)
        << r.output;
    auto report = nlohmann::json::parse(std::ifstream(checked / "report.json"));
    ASSERT_TRUE(report.contains("path_cache_check")) << report.dump();
    EXPECT_GT(report["path_cache_check"]["checked"].get<uint64_t>(), 0u);
    EXPECT_EQ(report["path_cache_check"]["differing"], 0);
    EXPECT_TRUE(report["path_cache_check"]["first"].empty());
    EXPECT_FALSE(nlohmann::json::parse(std::ifstream(plain / "report.json")).contains("path_cache_check"));
    EXPECT_EQ(nlohmann::json::parse(std::ifstream(checked / "layout.json")),
              nlohmann::json::parse(std::ifstream(plain / "layout.json")));
    for (const char* other : {"full_evaluation", "fresh_noise"}) {
        Result bad = run("optimize " + scene.string() + " -o " + (dir.path() / "bad").string() + common +
                         " --set check_cache=true --set " + other + "=true");
        EXPECT_EQ(bad.exitCode, 2) << other;
        EXPECT_NE(bad.output.find(std::string("\"check_cache\" and \"") + other + "\" exclude each other"), std::string::npos)
            << bad.output;
    }
}

// snapshots N: snapshots.json holds the best layout at N checkpoints with its wall
// time and lighting evaluations; each layout reads back with measure --layout.
TEST(Cli, OptimizeSnapshotsTheBestLayoutSoFar) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kLightSeeking);
    auto out = dir.path() / "out";
    Result r = run("optimize " + scene.string() + " -o " + out.string() + " --threads 1 -q --no-pictures --set snapshots=3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    auto snapshots = nlohmann::json::parse(std::ifstream(out / "snapshots.json"));
    EXPECT_EQ(snapshots["seed"], 2);
    EXPECT_EQ(snapshots["flat"], false);
    const auto& list = snapshots["snapshots"];
    ASSERT_GE(list.size(), 1u);
    ASSERT_LE(list.size(), 3u);
    if (list.size() == 3u) {
        EXPECT_EQ(list[0]["iteration"], 17);  // ceil(150 / 9)
    }
    EXPECT_EQ(list.back()["iteration"], snapshots["iterations"]);
    for (size_t k = 1; k < list.size(); ++k) {
        EXPECT_GT(list[k]["iteration"].get<int>(), list[k - 1]["iteration"].get<int>());
        EXPECT_GE(list[k]["lighting_evaluations"].get<int>(), list[k - 1]["lighting_evaluations"].get<int>());
        EXPECT_GE(list[k]["seconds"].get<double>(), list[k - 1]["seconds"].get<double>());
    }
    auto first = dir.write("first.json", list[0]["layout"].dump());
    Result m = run("measure " + scene.string() + " --layout " + first.string() + " --paths 8 --json");
    EXPECT_EQ(m.exitCode, 0) << m.output;
    // Without snapshots, no file.
    auto plain = dir.path() / "plain";
    ASSERT_EQ(run("optimize " + scene.string() + " -o " + plain.string() + " --threads 1 -q --no-pictures").exitCode, 0);
    EXPECT_FALSE(std::filesystem::exists(plain / "snapshots.json"));
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// render, report and optimize leave pictures that decode, a .glb that parses and a
// report.html whose every link resolves.
TEST(Cli, RenderReportAndOptimizeWriteTheirPictures) {
    test::TempDir dir;
    auto scene = dir.write("scene.json", kLightSeeking);
    auto layout = dir.write("layout.json", R"({"entities": {"table": {"position": [6.2, 2], "rotation": 90, "region": 1}}})");
    auto expectPng = [](const std::filesystem::path& file) {
        int w = 0, h = 0, n = 0;
        unsigned char* pixels = stbi_load(file.c_str(), &w, &h, &n, 3);
        EXPECT_TRUE(pixels && w > 0 && h > 0) << file;
        stbi_image_free(pixels);
        return std::pair(w, h);
    };
    auto expectGlb = [](const std::filesystem::path& file) {
        tinygltf::TinyGLTF loader;
        tinygltf::Model model;
        std::string err, warn;
        EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, file.string())) << file << ": " << err;
        EXPECT_EQ(model.nodes.size(), 4u) << file;  // room, table, lamp, the default view
        ASSERT_EQ(model.cameras.size(), 1u) << file;  // the scene has no cameras: render.png's view
        EXPECT_GT(model.cameras[0].perspective.zfar, model.cameras[0].perspective.znear) << file;
    };
    // The links to files (each resolves) and the pictures embedded as data: URIs.
    auto expectReport = [](const std::filesystem::path& folder) {
        std::ifstream in(folder / "report.html");
        std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_NE(html.find("</html>"), std::string::npos);
        // Scanned by hand: std::regex recurses per character, and a picture's data: URI
        // is longer than its stack allows.
        int refs = 0;
        for (const char* attr : {"href=\"", "src=\""})
            for (size_t at = html.find(attr); at != std::string::npos; at = html.find(attr, at + 1), ++refs) {
                const size_t begin = at + std::strlen(attr), end = html.find('"', begin);
                const std::string ref = html.substr(begin, end - begin);
                if (ref.rfind("data:image/png;base64,", 0) == 0) continue;
                EXPECT_TRUE(std::filesystem::is_regular_file(folder / ref)) << ref;
            }
        return refs;
    };
    const std::string small = " --threads 2 --spp 1";
    const std::string tiny = small + " --width 48 --height 32 --paths 8 --cell 0.5 --cell-paths 4";

    auto render = dir.path() / "render";
    Result r = run("render " + scene.string() + " --layout " + layout.string() + " -o " + render.string() + tiny + " --raw");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(expectPng(render / "render.png"), std::pair(48, 32));
    EXPECT_EQ(expectPng(render / "render_luminance.png"), std::pair(48 + 90, 140));  // the view and its legend
    EXPECT_NE(r.output.find("pictures: rendering 48 x 32 px at 1 sample per pixel"), std::string::npos) << r.output;
    expectPng(render / "plan.png");
    expectGlb(render / "scene.glb");
    EXPECT_FALSE(std::filesystem::exists(render / "report.html"));

    // --glb-only: scene.glb alone, no light transport.
    auto glbOnly = dir.path() / "glb-only";
    r = run("render " + scene.string() + " --layout " + layout.string() + " -o " + glbOnly.string() + " --glb-only --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    expectGlb(glbOnly / "scene.glb");
    for (const char* png : {"render.png", "render_luminance.png", "plan.png"})
        EXPECT_FALSE(std::filesystem::exists(glbOnly / png)) << png;

    auto report = dir.path() / "report";
    r = run("report " + scene.string() + " --layout " + layout.string() + " -o " + report.string() + tiny);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* png : {"plan.png", "plan_initial_vs_optimized.png", "render.png", "render_luminance.png"})
        expectPng(report / png);
    EXPECT_FALSE(std::filesystem::exists(report / "convergence.png"));
    expectGlb(report / "scene.glb");
    EXPECT_GE(expectReport(report), 6);  // 4 pictures (each an img and a link), scene.glb, layout.json

    auto optimized = dir.path() / "optimized";
    r = run("optimize " + scene.string() + " -o " + optimized.string() + " --iterations 40 -q" + small);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* png : {"plan.png", "plan_initial_vs_optimized.png", "render.png", "convergence.png"})
        expectPng(optimized / png);
    expectGlb(optimized / "scene.glb");
    EXPECT_GE(expectReport(optimized), 12);  // 4 pictures twice, scene.glb, layout.json, report.json, trace.csv
    // report.pdf beside report.html where Chromium is installed (tests/cli/report_pdf_test.cpp).
    if (std::system("command -v chromium > /dev/null") == 0) {
        EXPECT_TRUE(std::filesystem::is_regular_file(optimized / "report.pdf")) << r.output;
    }

    auto bare = dir.path() / "bare";
    r = run("optimize " + scene.string() + " -o " + bare.string() + " --iterations 5 -q --no-pictures" + small);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(bare / "layout.json"));
    EXPECT_FALSE(std::filesystem::exists(bare / "plan.png"));
    EXPECT_FALSE(std::filesystem::exists(bare / "report.html"));
}

}  // namespace
}  // namespace luxplan
