// What the loader makes of a sampler's "statistics" goals and of the planar type's
// EN 12464-1 grid with its wall band, and every problem with them, as
// FILE: /json/path: message.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

// A 6 x 5 m room and a world sampler `sampler` (merged over a planar default).
json roomWith(const json& sampler) {
    json scene = json::parse(R"({"luxplan": 1,
      "materials": {"w": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [6, 5, 3]},
                    "materials": {"floor": "w", "walls": "w", "ceiling": "w"}}],
      "samplers": [{"name": "work", "type": "planar", "center": [3, 2.5, 0.8], "size": [6, 5], "target": [500, null]}]})");
    scene["samplers"][0].update(sampler);
    for (auto it = sampler.begin(); it != sampler.end(); ++it)
        if (it.value().is_null()) scene["samplers"][0].erase(it.key());
    return scene;
}

Scene load(const json& scene) {
    test::TempDir dir;
    return io::loadScene(dir.write("scene.json", scene.dump()));
}

using test::problems;

TEST(StatisticsLoader, GoalsInTheOrderMinMaxU0WithTheirDefaults) {
    const Scene s = load(roomWith(json::parse(R"({"statistics": {
        "u0": {"target": [0.6, 1], "tolerance": 0.2}, "min": {"target": [200, 1e9]}, "max": {"target": [null, 2000]}}})")));
    const auto& goals = s.samplers[0].statistics;
    ASSERT_EQ(goals.size(), 3u);
    EXPECT_EQ(goals[0].statistic, Statistic::Min);
    EXPECT_EQ(goals[0].targetMin, 200);
    EXPECT_EQ(goals[0].targetMax, 1e9);
    EXPECT_EQ(goals[0].tolerance, 100);  // half the floor it guards
    EXPECT_EQ(goals[0].jsonPath, "/samplers/0/statistics/min");
    EXPECT_EQ(goals[1].statistic, Statistic::Max);
    EXPECT_EQ(goals[1].targetMin, 0);
    EXPECT_EQ(goals[1].tolerance, 1000);  // no floor: half the ceiling
    EXPECT_EQ(goals[2].statistic, Statistic::U0);
    EXPECT_EQ(goals[2].tolerance, 0.2);
    EXPECT_EQ(s.samplers[0].tolerance, 250);  // the mean's own default is untouched
    EXPECT_TRUE(load(roomWith(json::object())).samplers[0].statistics.empty());
}

TEST(StatisticsLoader, VolumeSamplersTakeGoalsToo) {
    const Scene s = load(roomWith(json::parse(R"({"type": "volume", "size": null, "axes": [[1,0,0],[0,1,0],[0,0,1]],
        "points": 10, "statistics": {"u0": {"target": [0.5, null]}}})")));
    ASSERT_EQ(s.samplers[0].statistics.size(), 1u);
    EXPECT_EQ(s.samplers[0].statistics[0].tolerance, 0.25);
}

TEST(StatisticsLoader, ProblemsNameTheirPath) {
    auto only = [](const json& sampler) {
        const std::vector<std::string> p = problems(roomWith(sampler));
        EXPECT_EQ(p.size(), 1u) << testing::PrintToString(p);
        return p.empty() ? std::string() : p[0];
    };
    EXPECT_EQ(only(json::parse(R"({"statistics": {"u1": {"target": [0.6, 1]}}})")),
              "/samplers/0/statistics/u1: unknown statistic \"u1\" (did you mean \"u0\"?) (min, max or u0)");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"mean": {"target": [300, 500]}}})")),
              "/samplers/0/statistics/mean: unknown statistic \"mean\" (min, max or u0); the mean's goal is the "
              "sampler's \"target\"");
    EXPECT_EQ(only(json::parse(R"({"statistics": [0.6, 1]})")),
              "/samplers/0/statistics: expected an object of goals such as {\"u0\": {\"target\": [0.6, 1]}}, got an array");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"u0": 0.6}})")),
              "/samplers/0/statistics/u0: expected a statistics goal object, got a number");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"u0": {"tolerance": 0.1}}})")),
              "/samplers/0/statistics/u0: missing required key \"target\"");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"min": {"target": [300, 200]}}})")),
              "/samplers/0/statistics/min/target: target range is reversed: max 200 < min 300 lx");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"min": {"target": ["a", null]}}})")),
              "/samplers/0/statistics/min/target/0: expected a number or null, got a string");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"u0": {"target": [1.2, null]}}})")),
              "/samplers/0/statistics/u0/target: U0 = min / mean is at most 1: a target min of 1.2 cannot be met");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"u0": {"target": [0.6, 1], "tolerance": 0}}})")),
              "/samplers/0/statistics/u0/tolerance: value 0 outside >= 1e-06");
    EXPECT_EQ(only(json::parse(R"({"statistics": {"u0": {"target": [0.6, 1], "weight": 2}}})")),
              "/samplers/0/statistics/u0/weight: unknown key \"weight\" (known keys: target, tolerance)");
    EXPECT_EQ(only(json::parse(R"({"type": "directional", "center": null, "size": null, "origin": [3, 1, 1.2],
                                   "direction": [0, 1, 0], "statistics": {"u0": {"target": [0.6, 1]}}})")),
              "/samplers/0/statistics: statistics are over the points of a planar or volume sampler, whose value is "
              "their mean; a directional sampler has none");
    EXPECT_EQ(only(json::parse(R"({"type": "cylindrical", "size": null, "statistics": {"min": {"target": [100, null]}}})")),
              "/samplers/0/statistics: statistics are over the points of a planar or volume sampler, whose value is "
              "their mean; a cylindrical sampler has none");
}

TEST(En12464Loader, TheGridOfTheArea) {
    const Scene s = load(roomWith(json::parse(R"({"size": [5, 4], "grid": "en12464"})")));
    EXPECT_EQ(s.samplers[0].type->pointGrid(), (std::array<int, 2>{9, 7}));
    EXPECT_EQ(s.samplers[0].type->describe(), "9 x 7 points (EN 12464-1 grid) on 5 x 4 m");
}

TEST(En12464Loader, AWallBandTrimsTheAreaWhereItMeetsTheWalls) {
    // The whole 6 x 5 m floor less 0.5 m at every wall: 5 x 4 m, 9 x 7 points.
    const Scene whole = load(roomWith(json::parse(R"({"grid": "en12464", "wall_band": 0.5})")));
    EXPECT_EQ(whole.samplers[0].type->pointGrid(), (std::array<int, 2>{9, 7}));
    EXPECT_EQ(whole.samplers[0].type->describe(),
              "9 x 7 points (EN 12464-1 grid) on 5 x 4 m (a 0.5 m band at the walls left out)");
    std::vector<Vec3> dots = whole.samplers[0].type->place(Transform())->drawing().dots;
    EXPECT_NEAR(dots.front().x, 0.5 + 2.5 / 9, 1e-12);
    EXPECT_NEAR(dots.front().y, 0.5 + 2.0 / 7, 1e-12);
    EXPECT_NEAR(dots.front().z, 0.8, 1e-12);
    // A 2 x 1 m desk 0.2 m from the west wall loses 0.3 m on that side only; a given grid is kept.
    const Scene desk = load(roomWith(json::parse(R"({"center": [1.2, 2.5, 0.75], "size": [2, 1], "grid": [4, 2], "wall_band": 0.5})")));
    EXPECT_EQ(desk.samplers[0].type->describe(), "4 x 2 points on 1.7 x 1 m (a 0.5 m band at the walls left out)");
    dots = desk.samplers[0].type->place(Transform())->drawing().dots;
    EXPECT_NEAR(dots.front().x, 0.5 + 1.7 / 8, 1e-12);
    // Turned a quarter (up along x): the side along y is the first.
    const Scene turned = load(roomWith(json::parse(R"({"center": [3, 4.6, 0.8], "size": [2, 1], "up": [1, 0, 0], "wall_band": 0.5})")));
    EXPECT_EQ(turned.samplers[0].type->describe(), "4 x 4 points on 0.9 x 1 m (a 0.5 m band at the walls left out)");
    // A desk clear of the band is unchanged.
    const Scene clear = load(roomWith(json::parse(R"({"center": [3, 2.5, 0.75], "size": [2, 1], "grid": "en12464", "wall_band": 0.5})")));
    EXPECT_EQ(clear.samplers[0].type->pointGrid(), en12464Grid({2, 1}));
}

TEST(En12464Loader, ProblemsNameTheirPath) {
    auto only = [](const json& scene) {
        const std::vector<std::string> p = problems(scene);
        EXPECT_EQ(p.size(), 1u) << testing::PrintToString(p);
        return p.empty() ? std::string() : p[0];
    };
    EXPECT_EQ(only(roomWith(json::parse(R"({"grid": "en12646"})"))),
              "/samplers/0/grid: unknown grid \"en12646\": expected [nx, ny] or \"en12464\" (EN 12464-1's grid for the area)");
    EXPECT_EQ(only(roomWith(json::parse(R"({"size": [3000, 3000], "grid": "en12464"})"))),
              "/samplers/0/grid: the EN 12464-1 grid of 300 x 300 points exceeds the limit of 1024 per side and 65536 in all");
    EXPECT_EQ(only(roomWith(json::parse(R"({"wall_band": 3})"))),
              "/samplers/0/wall_band: a wall band of 3 m leaves nothing of the sampler in the room 0..6 x 0..5 m");
    EXPECT_EQ(only(roomWith(json::parse(R"({"wall_band": -0.5})"))), "/samplers/0/wall_band: value -0.5 outside > 0 m");
    EXPECT_EQ(only(roomWith(json::parse(R"({"normal": [0, 1, 1], "wall_band": 0.5})"))),
              "/samplers/0/wall_band: a wall band needs a horizontal sampler (normal [0, 0, 1] or [0, 0, -1]) whose sides "
              "run along the walls (up along x or y)");
    EXPECT_EQ(only(roomWith(json::parse(R"({"up": [1, 1, 0], "wall_band": 0.5})"))),
              "/samplers/0/wall_band: a wall band needs a horizontal sampler (normal [0, 0, 1] or [0, 0, -1]) whose sides "
              "run along the walls (up along x or y)");
    EXPECT_EQ(only(roomWith(json::parse(R"({"center": [8, 2.5, 0.8], "wall_band": 0.5})"))),
              "/samplers/0/wall_band: no room holds the sampler's centre [8, 2.5, 0.8]: a wall band is measured from the "
              "walls of its room");
    json carried = roomWith(json::object());
    carried["entities"] = json::parse(R"([{"name": "desk", "samplers": [{"name": "top", "type": "planar", "center": [0, 0, 0.75],
        "size": [1, 1], "grid": "en12464", "wall_band": 0.5, "target": [500, null]}]}])");
    EXPECT_EQ(only(carried),
              "/entities/0/samplers/0/wall_band: a wall band needs a world-fixed sampler: one carried by an entity moves with it");
    EXPECT_EQ(only(roomWith(json::parse(R"({"type": "volume", "size": null, "axes": [[1,0,0],[0,1,0],[0,0,1]], "wall_band": 0.5})"))),
              "/samplers/0/wall_band: \"wall_band\" does not apply to a volume sampler");
}

}  // namespace
}  // namespace luxplan
