// Settings on the command line: --set KEY=VALUE on measure, optimize, render and report
// over the scene's "optimizer" object, its mistakes (exit 2), the short --help a
// designer reads and --help-all and `luxplan settings` with every key.
#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace settings_cli_test {

const std::string kDemoScene = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json";

// One luminaire over one plane: a measurement takes milliseconds.
const char* kLitPlane = R"({"luxplan": 1, "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
    "luminaires": [{"name": "l", "shape": "rect", "center": [0,0,3], "normal": [0,0,-1], "size": [1,1], "flux_lm": 1000}],
    "samplers": [{"name": "p", "type": "planar", "center": [0,0,1], "size": [1,1], "target": [10, 500]}],
    "optimizer": {"seed": 5, "sampling": "random"}})";

// The options a --help lists (the lines of its options' sections that start with one).
std::vector<std::string> helpOptions(const std::string& help) {
    std::vector<std::string> options;
    std::istringstream lines(help);
    std::string line;
    bool inOptions = false;
    while (std::getline(lines, line)) {
        // A section's heading: "Options:", "Advanced options:", "Positionals:".
        if (!line.empty() && line[0] != ' ') inOptions = line.find("ptions:") != std::string::npos;
        if (inOptions && line.rfind("  -", 0) == 0) options.push_back(line.substr(2, line.find(' ', 2) - 2));
    }
    return options;
}

bool lists(const std::vector<std::string>& options, const std::string& name) {
    for (const std::string& o : options)
        if (o == name || o.rfind(name + ",", 0) == 0 || o.find("," + name) != std::string::npos) return true;
    return false;
}

TEST(SettingsCli, TheDefaultHelpShowsWhatADesignerUses) {
    const auto optimize = helpOptions(test::runCli("optimize --help").output);
    EXPECT_LE(optimize.size(), 12u);
    for (const char* o : {"-h", "-o", "--iterations", "--seed", "--threads", "--suggestions", "--start", "--set"})
        EXPECT_TRUE(lists(optimize, o)) << o;
    const auto measure = helpOptions(test::runCli("measure --help").output);
    EXPECT_LE(measure.size(), 10u);
    for (const char* o : {"--layout", "--paths", "--seed", "--threads", "--json", "--at", "--daylight-factor", "--set"})
        EXPECT_TRUE(lists(measure, o)) << o;
    for (const char* command : {"render", "report"}) {
        const auto options = helpOptions(test::runCli(std::string(command) + " --help").output);
        for (const char* o : {"--layout", "--paths", "--seed", "--threads", "--set", "--camera", "--eye", "--target", "--fov"})
            EXPECT_TRUE(lists(options, o)) << command << " " << o;
    }
    // No former switch is an option any more.
    for (const char* old : {"--light-roulette", "--sun-patches", "--check-cache", "--flat", "--nested", "--snapshots"})
        EXPECT_FALSE(lists(optimize, old)) << old;
}

TEST(SettingsCli, HelpAllAndSettingsListTheRest) {
    test::CliResult all = test::runCli("optimize --help-all");
    EXPECT_EQ(all.exitCode, 0);
    EXPECT_TRUE(lists(helpOptions(all.output), "--spp")) << all.output;
    EXPECT_NE(all.output.find("  check_cache = true or false (default false; optimize)"), std::string::npos) << all.output;
    test::CliResult settings = test::runCli("settings");
    EXPECT_EQ(settings.exitCode, 0);
    for (const char* key : {"iterations", "light_roulette", "sun_patches", "fresh_noise", "snapshots", "temperature"})
        EXPECT_NE(settings.output.find(std::string("\n  ") + key + " = "), std::string::npos) << key;
    EXPECT_NE(settings.output.find("(default measure, render, report: on; optimize: report; measure, optimize, render, report)"),
              std::string::npos)
        << settings.output;
}

// --set wins over the scene file, --seed over both; a measurement reads its settings.
TEST(SettingsCli, SetOverridesTheSceneOnMeasure) {
    test::TempDir dir;
    const auto scene = dir.write("lit.json", kLitPlane).string();
    auto measure = [&](const std::string& extra) {
        test::CliResult r = test::runCli("measure " + scene + " --paths 70 --threads 1 --json " + extra);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return r.exitCode == 0 ? nlohmann::json::parse(r.output) : nlohmann::json();
    };
    const auto file = measure("");
    EXPECT_EQ(file["seed"], 5);
    EXPECT_EQ(file["sampling"], "random");
    EXPECT_EQ(file["adaptive"], false);
    EXPECT_EQ(file["light_roulette"], 0.0);
    const auto set = measure("--set seed=9 --set sampling=sobol --set adaptive=true --set light_roulette=0.5");
    EXPECT_EQ(set["seed"], 9);
    EXPECT_EQ(set["sampling"], "sobol");
    EXPECT_EQ(set["adaptive"], true);
    EXPECT_EQ(set["light_roulette"], 0.5);
    EXPECT_TRUE(set["samplers"][0].contains("light_floor"));
    EXPECT_EQ(measure("--set seed=9 --seed 11")["seed"], 11);
}

// Each setting the commands read runs through --set; optimize reads the search's.
TEST(SettingsCli, EverySettingThroughSet) {
    test::TempDir dir;
    const auto scene = dir.write("lit.json", kLitPlane).string();
    for (const char* set : {"iterations=5", "paths_per_point=4", "report_paths_per_point=8", "selection_paths_per_point=4",
                            "inner_iterations=2", "nested=true", "polish_share=0", "guided=false", "suggestions=0",
                            "margin=0", "adaptive_share=false", "hierarchy=flat", "start=scene", "temperature=0.1",
                            "sampling=random", "sun_patches=on", "exterior_sun=off", "light_roulette=1", "adaptive=true",
                            "fixed_paths=true", "full_evaluation=true", "check_cache=true", "fresh_noise=true",
                            "noise_blind=true", "single_test=true", "cycle=true", "flat=true", "snapshots=2"}) {
        test::CliResult m = test::runCli("measure " + scene + " --paths 2 --threads 1 --set " + set);
        EXPECT_EQ(m.exitCode, 0) << set << "\n" << m.output;
    }
    // The optimize-only ones do what they say: snapshots.json, a flat run.
    const auto out = dir.path() / "out";
    test::CliResult r = test::runCli("optimize " + kDemoScene + " -o " + out.string() +
                                     " --threads 1 -q --no-pictures --iterations 10 --paths 2 --set report_paths_per_point=4 "
                                     "--set selection_paths_per_point=2 --set snapshots=2 --set flat=true");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(out / "snapshots.json"));
    EXPECT_TRUE(std::filesystem::exists(out / "layout_flat.json"));
    test::CliResult render = test::runCli("render " + scene + " -o " + (dir.path() / "view").string() +
                                          " --glb-only --threads 1 --set sun_patches=off");
    EXPECT_EQ(render.exitCode, 0) << render.output;
}

TEST(SettingsCli, BadSetsAreUsageErrors) {
    auto expectRefused = [](const std::string& command, const std::string& message) {
        test::CliResult r = test::runCli(command);
        EXPECT_EQ(r.exitCode, 2) << command << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << command << "\n" << r.output;
    };
    const std::string measure = "measure " + kDemoScene + " --paths 2 ";
    expectRefused(measure + "--set seed", "--set: expected KEY=VALUE, got \"seed\" (no \"=\")");
    expectRefused(measure + "--set iteration=5", "--set: unknown setting \"iteration\" (did you mean \"iterations\"?)");
    expectRefused(measure + "--set iterations=many", "--set: iterations=many: expected an integer, got a string");
    expectRefused(measure + "--set margin=6", "--set: margin=6: value 6 outside [0, 5]");
    expectRefused(measure + "--set nested=true --set cycle=true", "\"nested\" and \"cycle\" exclude each other");
    expectRefused("optimize " + kDemoScene + " -o x --set sampling=halton",
                  "--set: sampling=halton: unknown sampling \"halton\" (sobol or random)");
    expectRefused("render " + kDemoScene + " -o x --set exterior_sun=yes", "unknown exterior_sun \"yes\" (on or off)");
    expectRefused("report " + kDemoScene + " -o x --set =1", "no key before \"=\"");
    expectRefused(measure + "--daylight-factor --set adaptive=true", "--daylight-factor: excludes the setting adaptive (true)");
}

// A --set that conflicts with the file's keys is the scene's problem, named by the --set.
TEST(SettingsCli, SetAgainstTheFileNamesTheSet) {
    test::TempDir dir;
    nlohmann::json scene = nlohmann::json::parse(kLitPlane);
    scene["optimizer"]["full_evaluation"] = true;
    const auto file = dir.write("full.json", scene.dump()).string();
    test::CliResult r = test::runCli("measure " + file + " --paths 2 --set check_cache=true");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(file + ": /optimizer/full_evaluation: \"check_cache\" and \"full_evaluation\" exclude each other"),
              std::string::npos)
        << r.output;
}

}  // namespace settings_cli_test
}  // namespace luxplan
