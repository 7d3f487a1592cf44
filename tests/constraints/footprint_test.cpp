// The footprint rule (constraints/footprint.h): footprints against the room and
// against footprint-bound regions, with known corner distances.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/constraints/footprint.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

Scene footprintScene() {
    return test::SceneBuilder()
        .material("m", test::diffuse(0.5))
        .room({0, 0, 0}, {6, 6, 3}, "m", "m", "m")
        .entity("a", {1.5, 1.5, 0}).region({0, 0}, {6, 6}, {0, 45, 90}).part({1, 0.4, 1}, "m").end()
        .entity("set", {3, 4, 0}).region({0, 0}, {6, 6}).part({0.5, 0.5, 0.5}, "m")
        .entity("desk", {1, 0, 0}).region({-2, -2}, {2, 2}).part({0.6, 0.4, 0.7}, "m").end()
        .end()
        .entity("shelf", {2, 5.95, 0}).region({1, 5}, {5, 6}).region({0, 0}, {1, 1}).part({0.8, 0.3, 1.8}, "m").end()
        .entity("fixed", {-1, 3, 0}).part({0.2, 0.2, 0.2}, "m").end()
        .build();
}

class Footprint : public ::testing::Test {
protected:
    void SetUp() override {
        scene = footprintScene();
        layout = initialLayout(scene);
    }
    int id(const char* name) { return scene.findEntity(name); }
    void place(const char* name, double x, double y, double rotation = 0) {
        Placement& p = layout.placements[size_t(id(name))];
        p.position.x = x, p.position.y = y, p.rotationDeg = rotation;
    }
    std::vector<FootprintTerm> terms() {
        EntityInfo info(scene);
        return FootprintEvaluator(scene, info).evaluate(worldTransforms(scene, layout));
    }
    Scene scene;
    Layout layout;
};

TEST_F(Footprint, StaysInsideTheRoom) {
    // The shelf starts 0.1 m through the north wall (its origin region allows it).
    std::vector<FootprintTerm> t = terms();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].entity, id("shelf"));
    EXPECT_EQ(t[0].bound, FootprintBound::Room);
    EXPECT_NEAR(t[0].excess, 0.1, 1e-9);
    place("shelf", 2, 5.85);  // its back against the wall
    EXPECT_TRUE(terms().empty());

    place("a", 0.48, 1.5);  // 2 cm through the west wall
    t = terms();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].entity, id("a"));
    EXPECT_NEAR(t[0].excess, 0.02, 1e-9);
    EXPECT_NEAR(t[0].penalty, 1 + std::pow(0.02 / kFootprintScale, 2), 1e-9);
    EXPECT_EQ(describe(scene, t[0]), "footprint \"a\" / room \"room\": 0.02 m outside, P = 5");
    place("a", 0.5, 1.5);  // touching it
    EXPECT_TRUE(terms().empty());
    // Turned 45 deg, the farthest corner lies (0.5 + 0.2) / sqrt 2 from the origin in x:
    // at x = 0.4 it is 0.095 m beyond the wall.
    place("a", 0.4, 1.5, 45);
    t = terms();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_NEAR(t[0].excess, 0.7 / std::sqrt(2.0) - 0.4, 1e-9);
    place("a", 0.7 / std::sqrt(2.0), 1.5, 45);
    EXPECT_TRUE(terms().empty());
    // The corner beyond two walls: the distance to the room's corner.
    place("a", 0.4, 0.1, 0);
    t = terms();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_NEAR(t[0].excess, std::hypot(0.1, 0.1), 1e-9);
}

TEST_F(Footprint, AGroupHoldsItsMembers) {
    place("shelf", 2, 5.85);
    place("set.desk", 2.8, 0);  // world x up to 3 + 2.8 + 0.3 = 6.1: through the east wall
    std::vector<FootprintTerm> t = terms();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].entity, id("set"));  // the top-level entity, its member's footprint included
    EXPECT_NEAR(t[0].excess, 0.1, 1e-9);
    scene.entities[size_t(id("set"))].inRoom = false;
    scene.entities[size_t(id("set.desk"))].inRoom = false;
    EXPECT_TRUE(terms().empty());
}

TEST_F(Footprint, ImmovableEntitiesAreNotHeld) {
    place("shelf", 2, 5.85);
    EXPECT_TRUE(terms().empty());  // "fixed" stands outside the room, and cannot move
}

TEST_F(Footprint, FootprintRegionsBoundTheWholeFootprint) {
    place("shelf", 2, 5.85);
    Entity& shelf = scene.entities[size_t(id("shelf"))];
    const Region original = shelf.regions[1];
    shelf.regions[0].bound = RegionBound::Footprint;
    // Region 0 is [1, 5] x [5, 6]: the shelf at x 1.2 reaches x 0.8.
    place("shelf", 1.2, 5.85);
    std::vector<FootprintTerm> t = terms();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].bound, FootprintBound::Region);
    EXPECT_EQ(t[0].region, 0);
    EXPECT_NEAR(t[0].excess, 0.2, 1e-9);
    EXPECT_EQ(describe(scene, t[0]).rfind("footprint \"shelf\" / region 0 (/entities/2/placement/regions/0): 0.2 m outside", 0),
              0u)
        << describe(scene, t[0]);
    place("shelf", 1.4, 5.85);
    EXPECT_TRUE(terms().empty());
    // Where an origin region holds the placement too, the origin bound is enough.
    shelf.regions[1] = shelf.regions[0];
    shelf.regions[1].bound = RegionBound::Origin;
    place("shelf", 1.2, 5.85);
    EXPECT_TRUE(terms().empty());
    // A placement in no region is not this rule's (a flat run's member out of reach).
    shelf.regions[1] = original;
    place("shelf", 0.5, 3);
    EXPECT_TRUE(terms().empty());
}

TEST_F(Footprint, RejectsThroughTheGeometricTerm) {
    place("a", 0.48, 1.5);
    place("shelf", 2, 5.85);
    GeometryEvaluator g(scene);
    GeometryResult r = g.evaluate(worldTransforms(scene, layout), true);
    EXPECT_TRUE(r.rejected);
    ASSERT_EQ(r.footprints.size(), 1u);
    // 2 cm beyond the wall: the footprint's excess, and 0.4 x 1 x 0.02 m of voxels in the wall.
    EXPECT_NEAR(r.violation, std::pow(0.02 / kFootprintScale, 2) + std::pow((0.008 - 0.001) / kHardOverlapScale, 2), 1e-6);
    EXPECT_EQ(r.rejectedBy.rfind("overlap \"a\" / the west wall", 0), 0u) << r.rejectedBy;
    EXPECT_EQ(r.cost, 0);  // hard limits: no part of G
}

}  // namespace
}  // namespace luxplan
