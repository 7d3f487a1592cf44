// The loader's keys for the hard layout rules: the overlap entry's "wall_tolerance_l",
// a region's "bound" and a top-level placement's "in_room", with every refusal.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/io/scene_loader.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

json scene() {
    return json::parse(R"({
      "luxplan": 1,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                    "materials": {"floor": "m", "walls": "m", "ceiling": "m"}}],
      "entities": [{"name": "set", "position": [2, 2],
                    "placement": {"regions": [{"min": [1,1], "max": [5,3]}]},
                    "parts": [{"box": {"size": [1, 1, 1]}, "material": "m"}],
                    "children": [{"name": "chair", "position": [0, -0.8],
                                  "placement": {"regions": [{"min": [-0.5,-1], "max": [0.5,-0.6]}]},
                                  "parts": [{"box": {"size": [0.4, 0.4, 0.9]}, "material": "m"}]}]}],
      "constraints": [{"type": "overlap", "tolerance": 0.05}]
    })");
}

Scene load(const json& s, test::TempDir& dir) { return io::loadScene(dir.write("scene.json", s.dump())); }

using test::problems;

TEST(LayoutRulesLoader, Defaults) {
    test::TempDir dir;
    Scene s = load(scene(), dir);
    EXPECT_EQ(s.overlap.wallTolerance, 0.001);
    EXPECT_EQ(s.entities[0].regions[0].bound, RegionBound::Origin);
    EXPECT_TRUE(s.entities[0].inRoom);
    EXPECT_TRUE(s.entities[1].inRoom);  // a member takes its group's
}

TEST(LayoutRulesLoader, ReadsTheKeys) {
    json j = scene();
    j["constraints"][0]["wall_tolerance_l"] = 2.5;
    j["entities"][0]["placement"]["in_room"] = false;
    j["entities"][0]["placement"]["regions"][0]["bound"] = "footprint";
    j["entities"][0]["children"][0]["placement"]["regions"][0]["bound"] = "origin";
    test::TempDir dir;
    Scene s = load(j, dir);
    EXPECT_NEAR(s.overlap.wallTolerance, 0.0025, 1e-15);
    EXPECT_EQ(s.entities[0].regions[0].bound, RegionBound::Footprint);
    EXPECT_EQ(s.entities[1].regions[0].bound, RegionBound::Origin);
    EXPECT_FALSE(s.entities[0].inRoom);
    EXPECT_FALSE(s.entities[1].inRoom);
    j["constraints"][0]["wall_tolerance_l"] = 0;  // nothing at all may enter a wall
    EXPECT_EQ(load(j, dir).overlap.wallTolerance, 0);
}

TEST(LayoutRulesLoader, RefusesWhatCannotBeMeant) {
    json j = scene();
    j["constraints"][0]["wall_tolerance_l"] = -1;
    EXPECT_EQ(problems(j), std::vector<std::string>{"/constraints/0/wall_tolerance_l: value -1 outside >= 0 l"});
    j = scene();
    j["entities"][0]["placement"]["regions"][0]["bound"] = "footprnt";
    EXPECT_EQ(problems(j), std::vector<std::string>{"/entities/0/placement/regions/0/bound: unknown region bound "
                                                    "\"footprnt\" (did you mean \"footprint\"?) (origin or footprint)"});
    j = scene();
    j["entities"][0]["placement"]["regions"][0]["bound"] = 1;
    EXPECT_EQ(problems(j), std::vector<std::string>{"/entities/0/placement/regions/0/bound: expected a string, got a number"});
    j = scene();
    j["entities"][0]["children"][0]["placement"]["in_room"] = true;
    EXPECT_EQ(problems(j), std::vector<std::string>{"/entities/0/children/0/placement/in_room: \"in_room\" applies to "
                                                    "top-level entities: a member's footprint is part of its group's"});
    j = scene();
    j["entities"][0]["placement"]["in_room"] = "yes";
    EXPECT_EQ(problems(j), std::vector<std::string>{"/entities/0/placement/in_room: expected true or false, got a string"});
    j = scene();
    j["constraints"].push_back({{"type", "distance"}, {"a", "set"}, {"b", "set.chair"}, {"min", 0}, {"max", 1},
                                {"wall_tolerance_l", 1}});
    std::vector<std::string> p = problems(j);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/constraints/1/wall_tolerance_l: ", 0), 0u) << p[0];
}

}  // namespace
}  // namespace luxplan
