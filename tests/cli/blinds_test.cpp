// Blinds: a deployed translucent blind in front of an open window, in a black room
// under a uniform sky over a black ground. The blind's outer face sees the upper half
// of the sky: E = pi L / 2. A Lambertian transmitter then glows with radiance
// t E / pi = t L / 2 towards the room, so a floor point that sees only sky through
// the opening gets exactly t / 2 of its light without the blind.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

nlohmann::json room() {
    return nlohmann::json::parse(R"({
      "luxplan": 1,
      "daylight": {"sky": {"model": "uniform", "luminance_nits": 1000}, "sun": false, "ground_reflectance": 0,
                   "from": "2026-06-21T12:00+00:00"},
      "materials": {"black": {"type": "diffuse", "reflectance": 0},
                    "blind": {"type": "translucent", "reflectance": 0, "transmittance": 0.5}},
      "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [4, 4, 3]},
                    "materials": {"floor": "black", "walls": "black", "ceiling": "black"},
                    "openings": [{"wall": "south", "offset": 1, "width": 2, "sill": 0.6, "height": 2,
                                  "blind": {"material": "blind"}}]}],
      "samplers": [{"name": "floor", "type": "planar", "center": [2, 0.8, 0.01], "size": [0.4, 0.4], "grid": [2, 2],
                    "target": [0, null]}]
    })");
}

struct FloorReading {
    double value = 0, error = 0;
};

FloorReading measureFloor(const nlohmann::json& scene) {
    test::TempDir dir;
    const auto file = dir.write("blind.json", scene.dump());
    test::CliResult r = test::runCli("measure " + file.string() + " --json --paths 20000 --seed 4 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    if (r.exitCode != 0) return {};
    const auto m = nlohmann::json::parse(r.output);
    return {m["samplers"][0]["value"].get<double>(), m["samplers"][0]["std_error"].get<double>()};
}

TEST(Blinds, ADeployedTranslucentBlindPassesHalfItsTransmittance) {
    nlohmann::json scene = room();
    const FloorReading with = measureFloor(scene);
    scene["geometry"][0]["openings"][0]["blind"]["deployed"] = false;
    const FloorReading open = measureFloor(scene);
    ASSERT_GT(open.value, 0);
    const double ratio = with.value / open.value;
    const double sigma = ratio * std::hypot(with.error / with.value, open.error / open.value);
    // The blind hangs 5 mm inside the wall: near its edges the back of the (black) wall
    // hides a little of the sky from it, about perimeter x inset / (2 area) = 0.4%.
    EXPECT_NEAR(ratio, 0.25, 4 * sigma + 0.005 * 0.25) << with.value << " +- " << with.error << " lx with the blind, "
                                                        << open.value << " +- " << open.error << " without";
}

TEST(Blinds, RefusedWithTheirPath) {
    nlohmann::json scene = room();
    auto problems = [&] {
        test::TempDir dir;
        return test::loadProblems(scene.dump(), dir);
    };
    scene["geometry"][0]["openings"][0]["blind"] = {{"material", "velvet"}};
    auto p = problems();
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/geometry/0/openings/0/blind/material: unknown material \"velvet\"", 0), 0u) << p[0];
    scene["geometry"][0]["openings"][0]["blind"] = {{"material", "blind"}, {"deployed", "yes"}};
    EXPECT_EQ(problems(), std::vector<std::string>{"/geometry/0/openings/0/blind/deployed: expected true or false, got a string"});
    scene["geometry"][0]["openings"][0]["blind"] = "closed";
    EXPECT_EQ(problems(), std::vector<std::string>{"/geometry/0/openings/0/blind: expected a blind object, got a string"});
    scene["geometry"][0]["openings"][0]["blind"] = {{"deployed", true}};
    EXPECT_EQ(problems(), std::vector<std::string>{"/geometry/0/openings/0/blind: missing required key \"material\""});
}

}  // namespace
}  // namespace luxplan
