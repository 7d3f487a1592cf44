// Overlap (Eq. 6): shared voxel volume between boxes with known intersections,
// against the walls and static blockers, which pairs count, and the cache.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/constraints/overlap.h>
#include <luxplan/core/rng.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

Scene overlapScene() {
    return test::SceneBuilder()
        .material("m", test::diffuse(0.5))
        .room({0, 0, 0}, {6, 6, 3}, "m", "m", "m")
        .blocker("walkway", {4, 4, 0}, {5, 5, 1})
        .box("pillar", {0.2, 5.2, 0}, {0.8, 5.8, 3}, "m")
        .entity("a", {1.5, 1.5, 0}).region({0, 0}, {6, 6}).part({1, 1, 1}, "m").end()
        .entity("b", {3.5, 1.5, 0}).region({0, 0}, {6, 6}).part({1, 1, 1}, "m").end()
        .entity("set", {1.5, 4.5, 0}).region({0, 0}, {6, 6}).part({0.5, 0.5, 0.5}, "m")
        .entity("desk", {1, 0, 0}).region({-1, -1}, {1, 1}).part({0.6, 0.4, 0.7}, "m").end()
        .entity("chair", {1, -0.5, 0}).region({-1, -1}, {1, 1}).part({0.4, 0.4, 0.9}, "m").end()
        .end()
        .entity("fixed1", {5.5, 0.5, 0}).part({0.2, 0.2, 0.2}, "m").end()
        .entity("fixed2", {5.5, 0.5, 0}).part({0.2, 0.2, 0.2}, "m").end()
        .build();
}

class Overlap : public ::testing::Test {
protected:
    void SetUp() override {
        scene = overlapScene();
        layout = initialLayout(scene);
    }
    int id(const char* name) { return scene.findEntity(name); }
    void place(const char* name, double x, double y, double rotation = 0) {
        Placement& p = layout.placements[id(name)];
        p.position.x = x, p.position.y = y, p.rotationDeg = rotation;
    }
    const OverlapEvaluator::Pair* find(const OverlapEvaluator& o, OverlapTarget target, int a, int b) {
        for (const auto& p : o.pairs())
            if (p.target == target && ((p.a == a && p.b == b) || (target == OverlapTarget::Entity && p.a == b && p.b == a)))
                return &p;
        return nullptr;
    }
    // The overlap term of a pair after evaluating the layout (volume 0 when absent).
    PenaltyTerm overlapTerm(OverlapTarget target, int a, int b) {
        GeometryEvaluator g(scene);
        GeometryResult r = g.evaluate(worldTransforms(scene, layout), true);
        for (const auto& t : r.terms)
            if (t.overlap() && t.target == target &&
                ((t.a == a && t.b == b) || (target == OverlapTarget::Entity && t.a == b && t.b == a)))
                return t;
        return {};
    }
    Scene scene;
    Layout layout;
};

TEST_F(Overlap, InitialLayoutIsFree) {
    GeometryEvaluator g(scene);
    GeometryResult r = g.evaluate(worldTransforms(scene, layout), true);
    EXPECT_EQ(r.overlapPenalty, 0);
    EXPECT_FALSE(r.rejected) << r.rejectedBy;
    EXPECT_EQ(r.cost, 0);
}

TEST_F(Overlap, WhichPairsCount) {
    EntityInfo info(scene);
    OverlapEvaluator o(scene, info);
    EXPECT_TRUE(find(o, OverlapTarget::Entity, id("a"), id("b")));
    EXPECT_TRUE(find(o, OverlapTarget::Entity, id("set.desk"), id("set.chair")));  // members of one group
    EXPECT_TRUE(find(o, OverlapTarget::Entity, id("a"), id("set.desk")));      // across levels
    EXPECT_TRUE(find(o, OverlapTarget::Entity, id("a"), id("fixed1")));    // movable against fixed
    EXPECT_FALSE(find(o, OverlapTarget::Entity, id("set"), id("set.desk")));   // ancestor and descendant
    EXPECT_FALSE(find(o, OverlapTarget::Entity, id("fixed1"), id("fixed2")));  // can never change
    EXPECT_TRUE(find(o, OverlapTarget::Static, id("a"), 1));
    EXPECT_TRUE(find(o, OverlapTarget::Static, id("set.chair"), 2));
    EXPECT_FALSE(find(o, OverlapTarget::Static, id("fixed1"), 1));
    EXPECT_FALSE(find(o, OverlapTarget::Static, id("a"), 0));  // the room shell is the walls pair
    EXPECT_TRUE(find(o, OverlapTarget::Walls, id("a"), -1));
    EXPECT_FALSE(find(o, OverlapTarget::Walls, id("fixed1"), -1));
    // V_ref: 5% of the smaller volume between entities; the hard limit (1 litre) against
    // the walls and static items.
    EXPECT_NEAR(find(o, OverlapTarget::Entity, id("a"), id("set.desk"))->reference, 0.05 * 0.6 * 0.4 * 0.7, 1e-9);
    EXPECT_FALSE(find(o, OverlapTarget::Entity, id("a"), id("set.desk"))->hard());
    EXPECT_EQ(find(o, OverlapTarget::Walls, id("a"), -1)->reference, 0.001);
    EXPECT_TRUE(find(o, OverlapTarget::Walls, id("a"), -1)->hard());
    EXPECT_EQ(find(o, OverlapTarget::Static, id("a"), 1)->reference, 0.001);
    EXPECT_TRUE(find(o, OverlapTarget::Static, id("a"), 1)->hard());
}

TEST_F(Overlap, TwoBoxesWithAKnownIntersection) {
    place("b", 2.48, 1.5);  // x overlap 0.02 m over the full 1 x 1 face
    PenaltyTerm t = overlapTerm(OverlapTarget::Entity, id("a"), id("b"));
    EXPECT_NEAR(t.value, 0.02, 1e-9);
    EXPECT_NEAR(t.reference, 0.05, 1e-9);
    EXPECT_NEAR(t.penalty, 0.16, 1e-6);
    EXPECT_FALSE(t.rejects);
    place("b", 2.3, 1.7);  // 0.2 x 0.8 x 1
    t = overlapTerm(OverlapTarget::Entity, id("a"), id("b"));
    EXPECT_NEAR(t.value, 0.16, 0.005);
    EXPECT_TRUE(t.rejects);
}

TEST_F(Overlap, RotatedBoxes) {
    // A unit cube and the same cube turned 45 deg about its vertical axis: the
    // intersection is a regular octagon of area 2 (sqrt 2 - 1), 1 m tall.
    const Entity& a = scene.entities[id("a")];
    Transform ta = Transform::translate({2, 2, 0});
    Transform tb = Transform::placement({2, 2, 0}, 45);
    double expected = 2 * (std::sqrt(2.0) - 1);
    EXPECT_NEAR(sharedVolume(a.voxels, ta, a.voxels, tb), expected, 0.02 * expected);
    EXPECT_NEAR(sharedVolume(a.voxels, tb, a.voxels, ta), expected, 0.02 * expected);
    EXPECT_EQ(sharedVolume(a.voxels, ta, a.voxels, Transform::translate({3.5, 2, 0})), 0);
}

TEST_F(Overlap, BoxAgainstTheWalls) {
    place("a", 0.48, 1.5);  // 2 cm through the west wall: 20 litres, past the hard limit of 1
    PenaltyTerm t = overlapTerm(OverlapTarget::Walls, id("a"), -1);
    EXPECT_NEAR(t.value, 0.02, 1e-9);
    EXPECT_TRUE(t.rejects);
    EXPECT_TRUE(t.hardOverlap());
    EXPECT_EQ(t.walls, wallBit(RoomSide::West));
    EXPECT_NEAR(t.penalty, 1 + std::pow((0.02 - 0.001) / kHardOverlapScale, 2), 1e-6);
    EXPECT_EQ(describe(scene, t), "overlap \"a\" / the west wall: 0.02 m3 shared, hard limit 0.001 m3, P = 362");
    place("a", 0.26, 5.88);  // 0.24 through the west wall, 0.38 through the north one
    t = overlapTerm(OverlapTarget::Walls, id("a"), -1);
    EXPECT_NEAR(t.value, 1 - 0.76 * 0.62, 1e-9);
    EXPECT_TRUE(t.rejects);
    EXPECT_EQ(t.walls, wallBit(RoomSide::West) | wallBit(RoomSide::North));
    EXPECT_NE(describe(scene, t).find("/ the west wall and the north wall:"), std::string::npos) << describe(scene, t);
    EXPECT_NEAR(volumeOutside(scene.entities[id("a")].voxels, Transform::translate({3, 3, 2.6}),
                              {Bounds3({0, 0, 0}, {6, 6, 3})}),
                0.6, 1e-9);  // through the ceiling
}

TEST_F(Overlap, BoxAgainstStaticGeometry) {
    place("a", 3.7, 4.5);  // x [3.2, 4.2] against the invisible walkway [4, 5]
    PenaltyTerm t = overlapTerm(OverlapTarget::Static, id("a"), 1);
    EXPECT_NEAR(t.value, 0.2, 1e-9);
    EXPECT_TRUE(t.rejects);
    EXPECT_EQ(describe(scene, t).rfind("overlap \"a\" / geometry \"walkway\": 0.2 m3 shared, hard limit 0.001 m3", 0), 0u)
        << describe(scene, t);
    place("a", 1.0, 5.4);  // against the pillar: 0.3 x 0.6 x 1
    t = overlapTerm(OverlapTarget::Static, id("a"), 2);
    EXPECT_NEAR(t.value, 0.18, 1e-9);
    EXPECT_TRUE(t.rejects);
}

TEST_F(Overlap, HardLimitsRejectOnlyBeyondTheirToleranceAndAreNoPartOfG) {
    // Between entities Eq. 6 is soft (0.02 of a 0.05 V_ref: P = 0.16 in G); into a wall or
    // a blocker nothing counts within the limit, and anything beyond it rejects.
    scene.overlap.wallTolerance = 0.025;
    scene.entities[id("a")].inRoom = false;  // the footprint rule apart (footprint_test.cpp)
    place("a", 0.48, 1.5);   // 20 litres into the west wall
    place("b", 3.72, 4.5);   // x [3.22, 4.22]: 220 litres into the walkway [4, 5]
    PenaltyTerm wall = overlapTerm(OverlapTarget::Walls, id("a"), -1);
    EXPECT_NEAR(wall.value, 0.02, 1e-9);
    EXPECT_EQ(wall.reference, 0.025);
    EXPECT_EQ(wall.penalty, 0);
    EXPECT_FALSE(wall.rejects);
    GeometryEvaluator g(scene);
    GeometryResult r = g.evaluate(worldTransforms(scene, layout), true);
    EXPECT_TRUE(r.rejected);
    EXPECT_EQ(r.rejectedBy.rfind("overlap \"b\" / geometry \"walkway\"", 0), 0u) << r.rejectedBy;
    EXPECT_NEAR(r.violation, std::pow((0.22 - 0.025) / kHardOverlapScale, 2), 1e-3);
    EXPECT_EQ(r.overlapPenalty, 0);  // no pair of entities overlaps
    EXPECT_EQ(r.cost, 0);
    place("b", 3.5, 1.5);
    r = g.evaluate(worldTransforms(scene, layout), true);
    EXPECT_FALSE(r.rejected) << r.rejectedBy;
    EXPECT_EQ(r.cost, 0);  // 20 litres in the wall, within its limit, cost nothing
    EXPECT_EQ(r.violation, 0);
}

TEST_F(Overlap, MembersOfAGroupButNotParentAndChild) {
    layout.placements[id("set.chair")].position.y = -0.1;  // chair y [4.2, 4.6], desk y [4.3, 4.7]
    PenaltyTerm t = overlapTerm(OverlapTarget::Entity, id("set.desk"), id("set.chair"));
    EXPECT_NEAR(t.value, 0.4 * 0.3 * 0.7, 0.002);
    EXPECT_TRUE(t.rejects);
    layout.placements[id("set.desk")].position = Vec3(0, 0, 0);  // inside the group's own box
    GeometryEvaluator g(scene);
    GeometryResult r = g.evaluate(worldTransforms(scene, layout), true);
    for (const auto& term : r.terms)
        EXPECT_FALSE(term.overlap() && (term.a == id("set") || term.b == id("set")))
            << describe(scene, term);
}

TEST_F(Overlap, CacheRecomputesOnlyMovedEntities) {
    EntityInfo info(scene);
    OverlapEvaluator o(scene, info);
    o.update(worldTransforms(scene, layout));
    o.commit();
    EXPECT_EQ(o.recomputed(), o.pairs().size());
    size_t pairsOfB = 0;
    for (const auto& p : o.pairs()) pairsOfB += p.a == id("b") || (p.target == OverlapTarget::Entity && p.b == id("b"));
    place("b", 2.48, 1.5);
    o.update(worldTransforms(scene, layout));
    EXPECT_EQ(o.recomputed(), pairsOfB);
    EXPECT_NEAR(find(o, OverlapTarget::Entity, id("a"), id("b"))->volume, 0.02, 1e-9);
    o.revert();
    EXPECT_EQ(find(o, OverlapTarget::Entity, id("a"), id("b"))->volume, 0);
    // Moving the group recomputes its members' pairs too.
    place("set", 1.5, 4.0);
    o.update(worldTransforms(scene, layout));
    EXPECT_GT(o.recomputed(), 0u);
    o.update(worldTransforms(scene, layout));
    EXPECT_EQ(o.recomputed(), 0u);
}

TEST_F(Overlap, CachedEvaluationsMatchFreshOnes) {
    GeometryEvaluator cached(scene);
    Rng rng(hashValues({7, 1}));
    for (int i = 0; i < 60; ++i) {
        for (const char* name : {"a", "b", "set", "set.desk", "set.chair"}) {
            if (rng.uniform() < 0.5) continue;
            bool nested = std::string(name).rfind("set.", 0) == 0;
            double lo = nested ? -1 : 0.3, hi = nested ? 1 : 5.7;
            place(name, lo + (hi - lo) * rng.uniform(), lo + (hi - lo) * rng.uniform(), 360 * rng.uniform());
        }
        auto world = worldTransforms(scene, layout);
        GeometryResult a = cached.evaluate(world);
        GeometryResult b = GeometryEvaluator(scene).evaluate(world);
        EXPECT_EQ(a.cost, b.cost);
        EXPECT_EQ(a.overlapPenalty, b.overlapPenalty);
        EXPECT_EQ(a.rejected, b.rejected);
        if (rng.uniform() < 0.5) cached.commit();
        else cached.revert();
    }
}

}  // namespace
}  // namespace luxplan
