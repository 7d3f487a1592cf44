// "maintenance_factor" (EN 12464-1's maintained illuminance): every luminaire's and
// carried emitter's light is scaled by it, the daylight is not. The same paths are
// traced whatever the factor (the emitter choice reads the rated flux), so a factor
// scales the luminaires' share of every estimate exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace maintenance_test {

using Json = nlohmann::json;

// A 5 x 4 x 3 m room lit by a photometric downlight, a Lambertian panel and a bulb a
// movable lamp carries; a window in the south wall for the daylit variant.
Json roomScene() {
    const std::string ies = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/photometry/downlight.ies";
    Json scene = Json::parse(R"({"luxplan": 1,
      "materials": {"wall": {"type": "diffuse", "reflectance": 0.6}, "floor": {"type": "diffuse", "reflectance": 0.3},
                    "glass": {"type": "glass", "transmittance": 0.8}},
      "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [5, 4, 3]},
                    "materials": {"floor": "floor", "walls": "wall", "ceiling": "wall"},
                    "openings": [{"wall": "south", "offset": 1, "width": 2, "sill": 0.9, "height": 1.4, "material": "glass"}]}],
      "luminaires": [
        {"name": "dl", "shape": "disk", "center": [1.5, 2, 2.99], "normal": [0, 0, -1], "radius": 0.075, "flux_lm": 1500},
        {"name": "panel", "shape": "rect", "center": [3.5, 2, 2.99], "normal": [0, 0, -1], "size": [0.6, 0.6], "flux_lm": 3000}],
      "entities": [{"name": "lamp", "position": [4, 3], "placement": {"regions": [{"min": [3, 2.5], "max": [4.5, 3.5]}]},
                    "emitters": [{"name": "bulb", "shape": "sphere", "center": [0, 0, 1.5], "radius": 0.03, "flux_lm": 800}]}],
      "samplers": [
        {"name": "work", "type": "planar", "center": [2.5, 2, 0.8], "size": [3, 2], "grid": [3, 2], "target": [300, null]},
        {"name": "face", "type": "cylindrical", "center": [2.5, 1.5, 1.2], "target": [50, null]},
        {"name": "view", "type": "directional", "origin": [2.5, 0.5, 1.2], "direction": [0, 1, 0], "strata": 2,
         "target": [0, null]}],
      "optimizer": {"seed": 4}})");
    scene["luminaires"][0]["photometry"] = ies;
    return scene;
}

Json withDaylight(Json scene) {
    scene["daylight"] = Json::parse(R"({"sky": {"model": "cie_overcast", "horizontal_illuminance_lx": 10000}})");
    return scene;
}

Json withFactor(Json scene, double factor) {
    scene["maintenance_factor"] = factor;
    return scene;
}

// Every luminaire off (no flux): the daylight alone, on the same paths.
Json luminairesOff(Json scene) {
    for (Json& l : scene["luminaires"]) l["flux_lm"] = 0;
    scene["entities"][0]["emitters"][0]["flux_lm"] = 0;
    return scene;
}

Json measure(const test::TempDir& dir, const std::string& name, const Json& scene) {
    const auto file = dir.write(name, scene.dump());
    test::CliResult r = test::runCli("measure " + file.string() + " --json --paths 32 --seed 9 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.exitCode == 0 ? Json::parse(r.output) : Json();
}

// The samplers' values and points, in one list; `linear`: only the samplers whose value
// is a sum over the paths (not the directional one, whose brightest stratum is chosen by
// the sum of the daylight and the luminaires' light, which the factor weighs anew).
std::vector<double> numbers(const Json& measured, bool linear = false) {
    std::vector<double> out;
    for (const Json& s : measured["samplers"]) {
        if (linear && s["type"] == "directional") continue;
        out.push_back(s["value"].get<double>());
        for (const Json& p : s["points"]) out.push_back(p.get<double>());
    }
    return out;
}

// At night, factor 0.8 reads 0.8 of every value and point the new luminaires give.
TEST(MaintenanceFactor, ScalesEveryLuminairesLightAtNight) {
    test::TempDir dir;
    const Json asNew = measure(dir, "new.json", roomScene());
    const Json maintained = measure(dir, "maintained.json", withFactor(roomScene(), 0.8));
    EXPECT_EQ(asNew["maintenance_factor"], 1.0);
    EXPECT_EQ(maintained["maintenance_factor"], 0.8);
    const std::vector<double> a = numbers(asNew), b = numbers(maintained);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GE(a.size(), 3u + 6 + 4);  // the values, the plane's points, the view's strata
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_GT(a[i], 0) << i;
        EXPECT_NEAR(b[i], 0.8 * a[i], 1e-9 * a[i]) << i;
    }
    // The standard errors of the sums over the paths too (the directional sampler's is a
    // bootstrap whose draws are seeded by the estimates: equal in distribution only).
    for (size_t k = 0; k < 2; ++k)
        EXPECT_NEAR(maintained["samplers"][k]["std_error"].get<double>(), 0.8 * asNew["samplers"][k]["std_error"].get<double>(),
                    1e-9 * asNew["samplers"][k]["std_error"].get<double>())
            << k;
}

// By day the daylight keeps its light: E(0.8) = D + 0.8 (E(1) - D), D the daylight
// alone (the luminaires without flux) on the same paths.
TEST(MaintenanceFactor, LeavesTheDaylightAsItIs) {
    test::TempDir dir;
    const std::vector<double> asNew = numbers(measure(dir, "new.json", withDaylight(roomScene())), true);
    const std::vector<double> maintained =
        numbers(measure(dir, "maintained.json", withFactor(withDaylight(roomScene()), 0.8)), true);
    const std::vector<double> daylight = numbers(measure(dir, "daylight.json", luminairesOff(withDaylight(roomScene()))), true);
    ASSERT_GE(asNew.size(), 2u + 6);
    ASSERT_EQ(asNew.size(), maintained.size());
    ASSERT_EQ(asNew.size(), daylight.size());
    for (size_t i = 0; i < asNew.size(); ++i) {
        EXPECT_GT(daylight[i], 0) << i;
        EXPECT_GT(asNew[i], daylight[i]) << i;
        EXPECT_NEAR(maintained[i], daylight[i] + 0.8 * (asNew[i] - daylight[i]), 1e-9 * asNew[i]) << i;
    }
}

TEST(MaintenanceFactor, TheTableSaysMaintained) {
    test::TempDir dir;
    const auto file = dir.write("scene.json", withFactor(roomScene(), 0.8).dump());
    test::CliResult r = test::runCli("measure " + file.string() + " --paths 4 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("maintained illuminance: the luminaires' light x 0.8 (maintenance factor)\n"), std::string::npos)
        << r.output;
    const auto day = dir.write("day.json", withFactor(withDaylight(roomScene()), 0.8).dump());
    r = test::runCli("measure " + day.string() + " --paths 4 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("maintained illuminance: the luminaires' light x 0.8 (maintenance factor), the daylight as it is\n"),
              std::string::npos)
        << r.output;
    const auto plain = dir.write("plain.json", roomScene().dump());
    r = test::runCli("measure " + plain.string() + " --paths 4 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("maintained"), std::string::npos) << r.output;
}

TEST(MaintenanceFactor, RefusesFactorsOutsideZeroToOne) {
    test::TempDir dir;
    for (double bad : {0.0, -0.5, 1.2}) {
        const auto file = dir.write("scene.json", withFactor(roomScene(), bad).dump());
        test::CliResult r = test::runCli("validate " + file.string());
        EXPECT_EQ(r.exitCode, 1) << bad;
        EXPECT_NE(r.output.find(file.string() + ": /maintenance_factor: maintenance factor "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(" outside (0, 1]: the share of the luminaires' new light left at maintenance, e.g. 0.8"),
                  std::string::npos)
            << r.output;
    }
    // A percentage is taken for one.
    const auto percent = dir.write("percent.json", withFactor(roomScene(), 80).dump());
    test::CliResult r = test::runCli("validate " + percent.string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("(a fraction, not a percentage: 80% is 0.8)"), std::string::npos) << r.output;
    // Not a number.
    Json text = roomScene();
    text["maintenance_factor"] = "0.8";
    const auto string = dir.write("string.json", text.dump());
    r = test::runCli("validate " + string.string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find(string.string() + ": /maintenance_factor: "), std::string::npos) << r.output;
}

// Below 0.5 is valid, with a warning; 0.5 itself and above, none.
TEST(MaintenanceFactor, WarnsBelowOneHalf) {
    test::TempDir dir;
    const auto low = dir.write("low.json", withFactor(roomScene(), 0.2).dump());
    test::CliResult r = test::runCli("validate " + low.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(low.string() + ": /maintenance_factor: warning: maintenance factor 0.2 leaves the luminaires "
                                           "less than half their light as new"),
              std::string::npos)
        << r.output;
    const auto usual = dir.write("usual.json", withFactor(roomScene(), 0.5).dump());
    r = test::runCli("validate " + usual.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("maintenance_factor"), std::string::npos) << r.output;
}

// report.json gives the factor; report.html and optimize's closing lines say maintained.
TEST(MaintenanceFactor, TheReportsSayMaintained) {
    test::TempDir dir;
    const auto file = dir.write("scene.json", withFactor(roomScene(), 0.8).dump());
    const auto out = dir.path() / "out";
    test::CliResult r =
        test::runCli("optimize " + file.string() + " -o " + out.string() + " --iterations 2 --paths 4 --threads 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the illuminances are maintained ones: the luminaires' light x 0.8"), std::string::npos) << r.output;
    const Json report = Json::parse(std::ifstream(out / "report.json"));
    EXPECT_EQ(report["maintenance_factor"], 0.8);
    const auto shown = dir.path() / "shown";
    r = test::runCli("report " + file.string() + " -o " + shown.string() +
                     " --threads 2 --spp 1 --width 24 --height 16 --paths 4 --cell 1 --cell-paths 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(shown / "report.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("<dt>maintenance factor</dt><dd>0.80 (maintained illuminance"), std::string::npos);
    EXPECT_NE(html.find("Maintained illuminance in lx"), std::string::npos);
}

}  // namespace maintenance_test
}  // namespace luxplan
