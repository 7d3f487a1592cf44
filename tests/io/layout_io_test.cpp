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

    // The rotation is written to 0.01 degree.
    EXPECT_EQ(json["entities"]["set"]["rotation"].dump(), "123.46");
    layout.placements[0].rotationDeg = 123.46;

    Layout back = io::readLayout(file, s);
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        EXPECT_EQ(back.placements[i].region, layout.placements[i].region);
        EXPECT_DOUBLE_EQ(back.placements[i].position.x, layout.placements[i].position.x);
        EXPECT_DOUBLE_EQ(back.placements[i].position.y, layout.placements[i].position.y);
        EXPECT_DOUBLE_EQ(back.placements[i].rotationDeg, layout.placements[i].rotationDeg);
    }
}

// layout.json holds x and y to 0.1 mm and rotations to 0.01 degree, inside each
// entity's region; a rounded layout is written as it is and reads back bit for bit.
TEST(LayoutIo, PositionsAreWrittenTo01MmAndRotationsTo001Degree) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", kLayoutScene));
    Layout layout = initialLayout(s);
    layout.placements[0] = {1, Vec3(5.123456789, 1.98765432, 0), 271.23456};
    layout.placements[2] = {0, Vec3(0.499996, -0.499996, 0), 0};  // rounds onto the region's edge
    auto file = dir.path() / "layout.json";
    io::writeLayout(file, s, layout);
    auto json = nlohmann::json::parse(std::ifstream(file));
    EXPECT_EQ(json["entities"]["set"]["position"].dump(), "[5.1235,1.9877,0.0]");
    EXPECT_EQ(json["entities"]["set"]["rotation"].dump(), "271.23");
    EXPECT_EQ(json["entities"]["set.lamp"]["position"].dump(), "[0.5,-0.5,0.0]");

    const Layout rounded = roundedLayout(s, layout);
    const Layout back = io::readLayout(file, s);
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        EXPECT_EQ(back.placements[i].position, rounded.placements[i].position) << i;
        EXPECT_EQ(back.placements[i].rotationDeg, rounded.placements[i].rotationDeg) << i;
        EXPECT_EQ(back.placements[i].region, rounded.placements[i].region) << i;
    }
    // Rounding twice is rounding once.
    EXPECT_EQ(io::layoutToJson(s, rounded), io::layoutToJson(s, back));
}

TEST(LayoutIo, RoundingStaysInsideTheRegion) {
    Entity e;
    Region r;
    r.lo = {1, 1};
    r.hi = {1.23456, 1};  // x up to a value off the grid; y fixed at 1
    r.continuousRotation = true;
    r.rotationMinDeg = 0, r.rotationMaxDeg = 90.005;
    e.regions = {r};
    Region discrete = r;
    discrete.continuousRotation = false;
    discrete.rotationsDeg = {33.333333};
    e.regions.push_back(discrete);

    // The nearest step (1.2346) is past the region's edge: the step below.
    Placement p{0, Vec3(1.23455, 1, 0.7), 90.004};
    Placement q = roundedPlacement(e, p);
    EXPECT_EQ(q.position.x, 1.2345);
    EXPECT_EQ(q.position.y, 1.0);
    EXPECT_EQ(q.position.z, 0.7);  // the plane it moves on, as it is
    EXPECT_EQ(q.rotationDeg, 90.0);
    // Asked to go up, it still stays inside; a value on the grid stays, whichever way.
    EXPECT_EQ(roundedPlacement(e, p, RoundTowards::Up).position.x, 1.2345);
    EXPECT_EQ(roundedPlacement(e, q, RoundTowards::Up, RoundTowards::Up, RoundTowards::Up).position.x, 1.2345);
    EXPECT_EQ(roundedPlacement(e, q, RoundTowards::Down, RoundTowards::Down, RoundTowards::Down).rotationDeg, 90.0);
    // A region narrower than a step: the value as it is.
    Entity narrow = e;
    narrow.regions[0].lo.x = narrow.regions[0].hi.x = 1.23456;
    EXPECT_EQ(roundedPlacement(narrow, {0, Vec3(1.23456, 1, 0), 45}).position.x, 1.23456);
    // A discrete rotation off the grid stays as it is.
    EXPECT_EQ(roundedPlacement(e, {1, Vec3(1.1, 1, 0), 33.333333}).rotationDeg, 33.333333);
    // Outside every region: the nearest step.
    EXPECT_EQ(roundedPlacement(e, {-1, Vec3(7.77777, 1, 0), 1.005}).position.x, 7.7778);
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
