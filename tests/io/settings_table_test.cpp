// The settings' one key table (io/settings_table.h): every key read from the scene's
// "optimizer" object and from --set (LoadOptions::settings), --set over the file, each
// problem in words with its place, and docs/scene-format.md's table in step with it.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/io/scene_loader.h>
#include <luxplan/io/settings_table.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace settings_table_test {

using nlohmann::json;

json minimalScene() { return json{{"luxplan", 1}}; }

// A value for every key, none of them its default, that holds together (no two keys
// that exclude each other both on).
json everyKey() {
    return json{{"iterations", 123},
                {"seed", 18446744073709551615ull},
                {"paths_per_point", 32},
                {"report_paths_per_point", 500},
                {"selection_paths_per_point", 200},
                {"inner_iterations", 7},
                {"nested", true},
                {"polish_share", 0.3},
                {"restart_share", 0.4},
                {"guided", false},
                {"plan_iterations", 321},
                {"plans", 3},
                {"suggestions", 3},
                {"margin", 1.5},
                {"adaptive_share", false},
                {"hierarchy", "flat"},
                {"start", "scene"},
                {"temperature", {{"start", 0.5}, {"end", 0.01}}},
                {"sampling", "random"},
                {"sun_patches", "off"},
                {"exterior_sun", "off"},
                {"light_roulette", 0.7},
                {"adaptive", true},
                {"fixed_paths", true},
                {"full_evaluation", true},
                {"check_cache", false},
                {"fresh_noise", true},
                {"noise_blind", true},
                {"single_test", true},
                {"cycle", false},
                {"flat", true},
                {"snapshots", 9}};
}

void expectEveryKeySet(const OptimizerSettings& s) {
    EXPECT_EQ(s.iterations, 123);
    EXPECT_EQ(s.seed, 18446744073709551615ull);
    EXPECT_EQ(s.searchPathsPerPoint, 32);
    EXPECT_EQ(s.reportPathsPerPoint, 500);
    EXPECT_EQ(s.selectionPathsPerPoint, 200);
    EXPECT_EQ(s.innerIterations, 7);
    EXPECT_TRUE(s.nested);
    EXPECT_EQ(s.polishShare, 0.3);
    EXPECT_EQ(s.restartShare, 0.4);
    EXPECT_FALSE(s.guided);
    EXPECT_EQ(s.planIterations, 321);
    EXPECT_EQ(s.suggestions, 3);
    EXPECT_EQ(s.margin, 1.5);
    EXPECT_FALSE(s.adaptiveShare);
    EXPECT_TRUE(s.flat);
    EXPECT_TRUE(s.startFromScene);
    EXPECT_FALSE(s.constantTemperature);
    EXPECT_EQ(s.temperatureStart, 0.5);
    EXPECT_EQ(s.temperatureEnd, 0.01);
    EXPECT_FALSE(s.lowDiscrepancy);
    EXPECT_EQ(s.sunPatches, SunPatchUse::Off);
    EXPECT_FALSE(s.exteriorSun);
    EXPECT_EQ(s.lightRoulette, 0.7);
    EXPECT_TRUE(s.adaptive);
    EXPECT_TRUE(s.fixedPaths);
    EXPECT_TRUE(s.fullEvaluation);
    EXPECT_FALSE(s.checkCache);
    EXPECT_TRUE(s.freshNoise);
    EXPECT_TRUE(s.noiseBlind);
    EXPECT_TRUE(s.singleTest);
    EXPECT_FALSE(s.cycle);
    EXPECT_TRUE(s.flatScene);
    EXPECT_EQ(s.snapshots, 9);
}

Scene load(const json& scene, const std::vector<std::string>& set = {}) {
    test::TempDir dir;
    io::LoadOptions options;
    for (const std::string& text : set) options.settings.push_back(io::parseSetting(text));
    return io::loadScene(dir.write("scene.json", scene.dump()), options);
}

// The problems of a load with --set settings, as "path: message" lines.
std::vector<std::string> setProblems(const json& scene, const std::vector<std::string>& set) {
    try {
        load(scene, set);
    } catch (const SceneError& e) {
        std::vector<std::string> out;
        for (const Diagnostic& d : e.diagnostics()) out.push_back(d.jsonPath + ": " + d.message);
        return out;
    }
    return {};
}

TEST(SettingsTable, EveryKeyHasARowAndTheTestSetsEveryOne) {
    std::set<std::string> keys;
    for (const io::SettingKey& row : io::settingKeys()) {
        EXPECT_TRUE(keys.insert(row.key).second) << "twice: " << row.key;
        EXPECT_NE(std::string(row.doc), "") << row.key;
        EXPECT_NE(std::string(row.fallback), "") << row.key;
        EXPECT_NE(std::string(row.commands), "") << row.key;
    }
    std::set<std::string> tested;
    const json every = everyKey();
    for (const auto& [key, value] : every.items()) tested.insert(key);
    EXPECT_EQ(tested, keys);
}

// report.json's "settings": every key written back as the file holds it, so that the
// object read again gives the same settings.
TEST(SettingsTable, WritesEveryKeyBackAsTheFileHoldsIt) {
    json scene = minimalScene();
    scene["optimizer"] = everyKey();
    const OptimizerSettings s = load(scene).optimizer;
    EXPECT_EQ(io::settingsJson(s), everyKey());

    scene["optimizer"] = {{"temperature", 0.05}};  // a constant temperature: a number
    const OptimizerSettings constant = load(scene).optimizer;
    EXPECT_EQ(io::settingsJson(constant)["temperature"], 0.05);
    scene["optimizer"] = io::settingsJson(constant);
    EXPECT_EQ(io::settingsJson(load(scene).optimizer), io::settingsJson(constant));
}

TEST(SettingsTable, WritesTheDefaultsWithOptionalsLeftToTheCommand) {
    const json defaults = io::settingsJson(OptimizerSettings{});
    EXPECT_EQ(defaults["iterations"], 10000);
    EXPECT_EQ(defaults["paths_per_point"], 64);
    EXPECT_EQ(defaults["report_paths_per_point"], kDefaultReportPaths);
    EXPECT_EQ(defaults["temperature"], json({{"start", 0.1}, {"end", 0.001}}));
    EXPECT_EQ(defaults["hierarchy"], "hierarchical");
    EXPECT_FALSE(defaults.contains("sun_patches"));  // each command's own default
    EXPECT_FALSE(defaults.contains("light_roulette"));
    EXPECT_EQ(defaults.size(), io::settingKeys().size() - 2);
}

TEST(SettingsTable, EveryKeyThroughTheSceneFile) {
    json scene = minimalScene();
    scene["optimizer"] = everyKey();
    expectEveryKeySet(load(scene).optimizer);
}

TEST(SettingsTable, EveryKeyThroughSet) {
    std::vector<std::string> set;
    const json every = everyKey();
    for (const auto& [key, value] : every.items())
        set.push_back(key + "=" + (value.is_string() ? value.get<std::string>() : value.dump()));
    expectEveryKeySet(load(minimalScene(), set).optimizer);
}

TEST(SettingsTable, SetWinsOverTheFileAndLeavesItsOtherKeys) {
    json scene = minimalScene();
    scene["optimizer"] = {{"iterations", 50}, {"seed", 4}, {"sampling", "random"}};
    const OptimizerSettings s = load(scene, {"seed=9", "sampling=sobol", "temperature=0.05"}).optimizer;
    EXPECT_EQ(s.iterations, 50);
    EXPECT_EQ(s.seed, 9u);
    EXPECT_TRUE(s.lowDiscrepancy);
    EXPECT_TRUE(s.constantTemperature);
    EXPECT_EQ(s.temperatureStart, 0.05);
    // The later of two --set of one key.
    EXPECT_EQ(load(scene, {"seed=2", "seed=3"}).optimizer.seed, 3u);
}

// The defaults the commands rely on, and the counts that follow paths_per_point.
TEST(SettingsTable, DefaultsAndTheCountsThatFollowPaths) {
    const OptimizerSettings none = load(minimalScene()).optimizer;
    EXPECT_EQ(none.searchPathsPerPoint, 64);
    EXPECT_EQ(none.reportPathsPerPoint, kDefaultReportPaths);
    EXPECT_EQ(none.selectionPathsPerPoint, kDefaultSelectionPaths);
    EXPECT_FALSE(none.sunPatches.has_value());
    EXPECT_FALSE(none.lightRoulette.has_value());
    EXPECT_TRUE(none.samplesSunPatches(SunPatchUse::On, true));
    EXPECT_FALSE(none.samplesSunPatches(SunPatchUse::Report, true));
    EXPECT_TRUE(none.samplesSunPatches(SunPatchUse::Report, false));
    // Given through --set as through the file: the report's and the selection's follow.
    const OptimizerSettings many = load(minimalScene(), {"paths_per_point=40000"}).optimizer;
    EXPECT_EQ(many.searchPathsPerPoint, 40000);
    EXPECT_EQ(many.reportPathsPerPoint, 40000);
    EXPECT_EQ(many.selectionPathsPerPoint, 40000);
    const OptimizerSettings report = load(minimalScene(), {"report_paths_per_point=256"}).optimizer;
    EXPECT_EQ(report.reportPathsPerPoint, 256);
    EXPECT_EQ(report.selectionPathsPerPoint, 256);
}

TEST(SettingsTable, FileProblemsNameTheirJsonPath) {
    json scene = minimalScene();
    scene["optimizer"] = {{"sun_patches", "sometimes"}};
    EXPECT_EQ(test::onlyProblem(scene), "/optimizer/sun_patches: unknown sun_patches \"sometimes\" (on, off or report)");
    scene["optimizer"] = {{"light_roulette", 11}};
    EXPECT_EQ(test::onlyProblem(scene), "/optimizer/light_roulette: value 11 outside [0, 10]");
    scene["optimizer"] = {{"adaptive", 1}};
    EXPECT_EQ(test::onlyProblem(scene), "/optimizer/adaptive: expected true or false, got a number");
    scene["optimizer"] = {{"check_cache", true}, {"full_evaluation", true}};
    EXPECT_EQ(test::onlyProblem(scene), "/optimizer/full_evaluation: \"check_cache\" and \"full_evaluation\" exclude each other "
                                        "(check_cache checks the path cache, which full_evaluation does without)");
    scene["optimizer"] = {{"nested", true}, {"cycle", true}};
    EXPECT_EQ(test::onlyProblem(scene).rfind("/optimizer/cycle: \"nested\" and \"cycle\" exclude each other", 0), 0u);
    scene["optimizer"] = {{"iteration", 5}};
    EXPECT_EQ(test::onlyProblem(scene).rfind("/optimizer/iteration: unknown key \"iteration\" (did you mean \"iterations\"?)", 0), 0u);
}

TEST(SettingsTable, SetProblemsNameTheSet) {
    json scene = minimalScene();
    scene["optimizer"] = {{"nested", true}};
    const auto problems = setProblems(scene, {"cycle=true"});
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("--set cycle=true: \"nested\" and \"cycle\" exclude each other", 0), 0u) << problems[0];
    // Read alone, as the command line checks them before loading.
    EXPECT_EQ(io::settingProblems({io::parseSetting("iterations=abc")}),
              std::vector<std::string>{"--set iterations=abc: expected an integer, got a string"});
    EXPECT_EQ(io::settingProblems({io::parseSetting("snapshots=1001")}),
              std::vector<std::string>{"--set snapshots=1001: value 1001 outside [0, 1000]"});
    EXPECT_EQ(io::settingProblems({io::parseSetting("fresh_noise=true"), io::parseSetting("check_cache=true")}).size(), 1u);
    EXPECT_TRUE(io::settingProblems({io::parseSetting("temperature={\"start\": 1, \"end\": 0.1}")}).empty());
}

TEST(SettingsTable, MalformedSetIsRefusedInWords) {
    auto refusal = [](const std::string& text) {
        try {
            io::parseSetting(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal("seed"), "expected KEY=VALUE, got \"seed\" (no \"=\")");
    EXPECT_EQ(refusal("=3"), "expected KEY=VALUE, got \"=3\" (no key before \"=\")");
    EXPECT_EQ(refusal("seed="), "no value after \"seed=\"");
    EXPECT_EQ(refusal("lite_roulette=1").rfind("unknown setting \"lite_roulette\" (did you mean \"light_roulette\"?) "
                                               "(luxplan settings lists them: iterations, seed, ",
                                               0),
              0u)
        << refusal("lite_roulette=1");
    EXPECT_EQ(io::parseSetting("sampling=random").value, json("random"));
    EXPECT_EQ(io::parseSetting("adaptive=true").value, json(true));
    EXPECT_EQ(io::parseSetting("margin=1.5").value, json(1.5));
}

// docs/scene-format.md's optimizer table has one row per key, no more.
TEST(SettingsTable, DocumentedInSceneFormat) {
    std::ifstream file(std::string(LUXPLAN_SOURCE_DIR) + "/docs/scene-format.md");
    ASSERT_TRUE(file) << "docs/scene-format.md";
    std::stringstream text;
    text << file.rdbuf();
    const std::string doc = text.str();
    std::set<std::string> documented;
    const std::regex row(R"(\n\| `optimizer\.([a-z_]+)` \|)");
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), row); it != std::sregex_iterator(); ++it)
        documented.insert((*it)[1]);
    std::set<std::string> keys;
    for (const io::SettingKey& k : io::settingKeys()) keys.insert(k.key);
    EXPECT_EQ(documented, keys);
    // And `luxplan settings` lists every key.
    const std::string listed = io::settingsTableText();
    for (const std::string& k : keys) EXPECT_NE(listed.find("\n  " + k + " = "), std::string::npos) << k;
}

}  // namespace settings_table_test
}  // namespace luxplan
