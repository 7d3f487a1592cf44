// Alignment (Eq. 4), distance (Eq. 5), focus (Eq. 7) and conversation (Eq. 8) on
// hand-built layouts with known values.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/constraints/relational.h>
#include <luxplan/constraints/constraint_type.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

// desk and chair are the same height, so centre distances are horizontal.
Scene relationalScene() {
    return test::SceneBuilder()
        .material("m", test::diffuse(0.5))
        .entity("desk", {2, 2, 0}).part({1.0, 0.5, 0.75}, "m").end()
        .entity("chair", {2, 1, 0}).part({0.4, 0.4, 0.75}, "m").end()
        .entity("shelf", {0, 0, 0}).fronts({{1, 1}, {0, -1}}).part({0.8, 0.3, 0.75}, "m", Vec3(0.3, 0, 0.375)).end()
        .entity("set", {5, 5, 0}, 90)
        .entity("big", {-1, 0, 0}).part({1, 1, 1}, "m").end()
        .entity("small", {1.5, 0, 0}).part({0.5, 0.5, 1}, "m").end()
        .end()
        .entity("marker", {7, 1, 0}).end()
        .constraint(alignmentConstraint(10), "desk", "room")
        .constraint(alignmentConstraint(10), "desk", "chair")
        .constraint(distanceConstraint({1, 2, std::nullopt}), "desk", "chair")
        .constraint(focusConstraint(16), "chair", "desk")
        .constraint(conversationConstraint({0.5, 1.5, std::nullopt}, 16), "desk", "chair")
        .constraint(alignmentConstraint(10), "shelf", "room")
        .build();
}

class Relational : public ::testing::Test {
protected:
    void SetUp() override {
        scene = relationalScene();
        layout = initialLayout(scene);
        desk = scene.findEntity("desk"), chair = scene.findEntity("chair");
    }
    PenaltyTerm term(int constraint) {
        EntityInfo info(scene);
        return evaluateRelational(scene, info, worldTransforms(scene, layout), constraint);
    }
    void place(int e, double x, double y, double rotation) {
        layout.placements[e].position.x = x, layout.placements[e].position.y = y;
        layout.placements[e].rotationDeg = rotation;
    }
    Scene scene;
    Layout layout;
    int desk = -1, chair = -1;
};

TEST_F(Relational, AlignmentWithTheRoom) {
    // Eq. 4 in angle space: zero up to the tolerance (10 deg), 1 at 10 + 10/8 deg.
    for (double rotation : {0.0, 5.0, -5.0, 90.0, 180.0, 270.0, 355.0}) {
        place(desk, 2, 2, rotation);
        PenaltyTerm t = term(0);
        EXPECT_EQ(t.penalty, 0) << rotation;
        EXPECT_FALSE(t.rejects);
    }
    place(desk, 2, 2, 10.5);
    EXPECT_NEAR(degrees(term(0).value), 10.5, 1e-9);
    EXPECT_NEAR(term(0).penalty, std::pow(0.5 / 1.25, 2), 1e-9);
    place(desk, 2, 2, 90 + 11.25 - 1e-6);
    EXPECT_NEAR(term(0).penalty, 1.0, 1e-5);
    EXPECT_FALSE(term(0).rejects);
    place(desk, 2, 2, 45);
    EXPECT_NEAR(degrees(term(0).value), 45, 1e-9);
    EXPECT_GT(term(0).penalty, 1);
    EXPECT_TRUE(term(0).rejects);
}

TEST_F(Relational, AlignmentBetweenObjectsIsAxial) {
    place(desk, 2, 2, 30);
    for (double rotation : {30.0, 210.0, 35.0}) {
        place(chair, 2, 1, rotation);
        EXPECT_EQ(term(1).penalty, 0) << rotation;
    }
    place(chair, 2, 1, 30 + 11);
    EXPECT_NEAR(term(1).penalty, std::pow(1 / 1.25, 2), 1e-9);
    place(chair, 2, 1, 30 + 90);  // perpendicular
    EXPECT_NEAR(degrees(term(1).value), 90, 1e-9);
    EXPECT_TRUE(term(1).rejects);
}

TEST_F(Relational, AlignmentTakesTheBestFront) {
    // shelf fronts (1,1)/sqrt2 and (0,-1): at 45 deg the first one points along +y.
    int shelf = scene.findEntity("shelf");
    place(shelf, 1, 1, 45);
    EXPECT_NEAR(term(5).value, 0, 1e-9);
    place(shelf, 1, 1, 0);  // (0,-1) is aligned
    EXPECT_NEAR(term(5).value, 0, 1e-9);
    place(shelf, 1, 1, 22.5);  // both fronts 22.5 deg off an axis
    EXPECT_NEAR(degrees(term(5).value), 22.5, 1e-9);
}

TEST_F(Relational, DistanceBetweenCentres) {
    // Range [1, 2], elastic limit 5% of the width = 0.05 m.
    place(chair, 2, 0.5, 0);
    EXPECT_NEAR(term(2).value, 1.5, 1e-12);
    EXPECT_EQ(term(2).penalty, 0);
    place(chair, 2, 2 - 2.025, 0);
    EXPECT_NEAR(term(2).penalty, 0.25, 1e-9);
    place(chair, 2, 2 - 0.98, 0);
    EXPECT_NEAR(term(2).penalty, std::pow(0.02 / 0.05, 2), 1e-9);
    place(chair, 2 + 2.06, 2, 0);
    EXPECT_NEAR(term(2).penalty, std::pow(0.06 / 0.05, 2), 1e-9);
    EXPECT_TRUE(term(2).rejects);
}

TEST_F(Relational, DistanceElasticLimitFallbacks) {
    DistanceRange c;
    c.min = 1, c.max = 3;
    EXPECT_NEAR(distanceElasticLimit(c), 0.1, 1e-12);
    c.tolerance = 0.3;
    EXPECT_NEAR(distanceElasticLimit(c), 0.3, 1e-12);
    c.tolerance.reset();
    c.min = 2, c.max = kInf;  // at least 2 m apart: 5% of 2
    EXPECT_NEAR(distanceElasticLimit(c), 0.1, 1e-12);
    c.min = 0, c.max = 0.5;
    EXPECT_NEAR(distanceElasticLimit(c), 0.025, 1e-12);
    c.min = 0.8, c.max = 0.8;  // a single value: 5% of it
    EXPECT_NEAR(distanceElasticLimit(c), 0.04, 1e-12);
    c.min = 0, c.max = 0;
    EXPECT_EQ(distanceElasticLimit(c), kMinDistanceElasticLimit);
}

TEST_F(Relational, CentresUseTheGeometryBounds) {
    EntityInfo info(scene);
    auto world = worldTransforms(scene, layout);
    // shelf: a part offset by 0.3 in x.
    Vec3 shelf = entityCenter(info, world, scene.findEntity("shelf"));
    EXPECT_NEAR(shelf.x, 0.3, 1e-12);
    EXPECT_NEAR(shelf.z, 0.375, 1e-12);
    // set: union of [-1.5, -0.5] and [1.25, 1.75] in x is centred at 0.125; the group
    // is rotated by 90 deg, so the centre lies at (5, 5.125).
    Vec3 set = entityCenter(info, world, scene.findEntity("set"));
    EXPECT_NEAR(set.x, 5, 1e-12);
    EXPECT_NEAR(set.y, 5.125, 1e-12);
    EXPECT_NEAR(set.z, 0.5, 1e-12);
    // No geometry: the origin.
    Vec3 marker = entityCenter(info, world, scene.findEntity("marker"));
    EXPECT_EQ(marker, Vec3(7, 1, 0));
}

TEST_F(Relational, Focus) {
    // chair at (2,1) facing -y, desk at (2,2): facing away.
    EXPECT_NEAR(term(3).value, kPi, 1e-12);
    EXPECT_TRUE(term(3).rejects);
    place(chair, 2, 1, 180);  // now facing +y, towards the desk
    EXPECT_NEAR(term(3).value, 0, 1e-12);
    EXPECT_EQ(term(3).penalty, 0);
    // Desk 17 deg off the chair's front: tolerance 16, elastic limit 2 deg.
    place(desk, 2 - std::tan(radians(17)), 2, 0);
    EXPECT_NEAR(degrees(term(3).value), 17, 1e-9);
    EXPECT_NEAR(term(3).penalty, 0.25, 1e-9);
}

TEST_F(Relational, Conversation) {
    place(chair, 2, 1, 180);  // desk faces -y, chair faces +y: facing each other 1 m apart
    PenaltyTerm t = term(4);
    EXPECT_EQ(t.penalty, 0);
    place(chair, 2, 1, 180 + 17);
    t = term(4);
    EXPECT_NEAR(t.parts[0], 0, 1e-12);
    EXPECT_NEAR(t.parts[1], 0.25, 1e-9);
    EXPECT_NEAR(t.parts[2], 0, 1e-12);
    EXPECT_NEAR(t.penalty, 0.25 / 3, 1e-9);
    EXPECT_FALSE(t.rejects);
    place(chair, 2, 1, 180 + 20);  // one focus past its elastic limit rejects
    t = term(4);
    EXPECT_NEAR(t.parts[1], 4, 1e-9);
    EXPECT_NEAR(t.penalty, 4.0 / 3, 1e-9);
    EXPECT_TRUE(t.rejects);
    place(chair, 2, 2 - 1.55, 180);  // 1.55 m: 0.05 past max, l_rej = 0.05
    t = term(4);
    EXPECT_NEAR(t.parts[2], 1, 1e-9);
}

TEST_F(Relational, GeometryCostIsTheWeightedMean) {
    place(chair, 2, 1, 180);
    place(desk, 2, 2, 10.5);  // alignment with room: 0.16; with chair: 0.16 (10.5 deg apart)
    GeometryEvaluator g(scene);
    GeometryResult r = g.evaluate(worldTransforms(scene, layout), true);
    ASSERT_EQ(r.terms.size(), 6u);  // no overlap: the objects are apart
    double sum = 0;
    for (const auto& t : r.terms) sum += t.penalty;
    EXPECT_NEAR(r.cost, sum / 7, 1e-12);  // six constraints and the overlap rule, weight 1 each
    EXPECT_FALSE(r.rejected);
    place(desk, 2, 2, 45);
    r = g.evaluate(worldTransforms(scene, layout));
    EXPECT_TRUE(r.rejected);
    EXPECT_NE(r.rejectedBy.find("/constraints/0"), std::string::npos) << r.rejectedBy;
    EXPECT_GT(r.violation, 0);
}

}  // namespace
}  // namespace luxplan
