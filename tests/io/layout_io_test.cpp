// layout.json: written in the contract's form and read back unchanged; bad layouts
// are reported with their JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/core/error.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

const char* kLayoutScene = R"({
  "luxplan": 1,
  "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
  "entities": [
    {"name": "set", "position": [2, 2],
     "placement": {"regions": [{"min": [1,1], "max": [3,3], "rotations": [0, 90, 180, 270]},
                               {"min": [5,1], "max": [6,2], "rotation_range": [0, 360]}]},
     "children": [{"name": "table", "parts": [{"preset": "table", "material": "m"}]},
                  {"name": "lamp", "position": [0.5, 0.5],
                   "placement": {"regions": [{"min": [-0.5,-0.5], "max": [0.5,0.5]}]},
                   "parts": [{"preset": "stand_lamp", "material": "m"}]}]}
  ]})";

TEST(LayoutIo, RoundTrip) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", kLayoutScene));
    Layout layout = initialLayout(s);
    ASSERT_EQ(layout.placements.size(), 3u);
    EXPECT_EQ(layout.placements[0].region, 0);
    layout.placements[0] = {1, Vec3(5.25, 1.5, 0), 123.456789};
    layout.placements[2] = {0, Vec3(-0.25, 0.125, 0), 0};
    auto file = dir.path() / "layout.json";
    io::writeLayout(file, s, layout);

    auto json = nlohmann::json::parse(std::ifstream(file));
    EXPECT_TRUE(json["entities"].contains("set"));
    EXPECT_TRUE(json["entities"].contains("set.lamp"));
    EXPECT_FALSE(json["entities"].contains("set.table"));  // fixed entities are not written
    EXPECT_EQ(json["entities"]["set"]["region"], 1);

    Layout back = io::readLayout(file, s);
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        EXPECT_EQ(back.placements[i].region, layout.placements[i].region);
        EXPECT_DOUBLE_EQ(back.placements[i].position.x, layout.placements[i].position.x);
        EXPECT_DOUBLE_EQ(back.placements[i].position.y, layout.placements[i].position.y);
        EXPECT_DOUBLE_EQ(back.placements[i].rotationDeg, layout.placements[i].rotationDeg);
    }
}

TEST(LayoutIo, ErrorsNameThePath) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", kLayoutScene));
    auto check = [&](const std::string& text, const std::string& expected) {
        auto file = dir.write("layout.json", text);
        try {
            io::readLayout(file, s);
            ADD_FAILURE() << "no error for " << text;
        } catch (const SceneError& e) {
            ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
            EXPECT_EQ(e.diagnostics()[0].str(), file.string() + ": " + expected);
        }
    };
    check(R"({"entities": {"chair": {"position": [1,1,0]}}})",
          "/entities/chair: unknown entity \"chair\" in scene " + (dir.path() / "scene.json").string());
    check(R"({"entities": {"set.table": {"position": [1,1,0]}}})",
          "/entities/set.table: entity \"set.table\" is fixed (it has no placement regions)");
    check(R"({"entities": {"set": {"position": [1,1,0], "rotation": 0, "region": 2}}})",
          "/entities/set/region: value 2 outside [0, 1]");
    check(R"({"entities": {"set": {"position": [9,9,0], "rotation": 0, "region": 0}}})",
          "/entities/set/region: position (9, 9) with rotation 0 lies outside region 0");
    check(R"({"entities": {"set": {"place": [1,1]}}})",
          "/entities/set/place: unknown key \"place\" (known keys: position, rotation, region)");
    // An entity moves on the plane of its scene position's z (a desk at z 2.5 went
    // through the ceiling and read 0 lx).
    check(R"({"entities": {"set": {"position": [2,2,2.5], "rotation": 0, "region": 0}}})",
          "/entities/set/position/2: z 2.5 is not the plane entity \"set\" moves on (z = 0, its position's in the scene)");
    EXPECT_NO_THROW(io::readLayout(dir.write("layout.json", R"({"entities": {"set": {"position": [2,2]}}})"), s));
}

}  // namespace
}  // namespace luxplan
