// The flat baseline (optimizer/flatten.h): structure of the flattened scene, equal
// cost for every layout the hierarchy allows, layouts converted both ways, and a
// flat move that breaks a group paying for it (tests/roundtrip writes that layout to
// layout.json).
#include <gtest/gtest.h>

#include <algorithm>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/placement.h>
#include "support/scene_builder.h"
#include "support/shared_scenes.h"

namespace luxplan {
namespace {

// The mean of a sampler's measurement points: a planar grid's centre.
Vec3 pointsCenter(const std::vector<Vec3>& points) {
    Vec3 sum;
    for (const Vec3& p : points) sum = sum + p;
    return sum * (1.0 / double(points.size()));
}

// Whether a flat constraint is one of the cohesion rules flattening added.
bool isCohesion(const FlatScene& flat, int constraint) {
    const auto* kind = dynamic_cast<const FlatConstraint*>(flat.scene.constraints[size_t(constraint)].kind.get());
    return kind && kind->cohesion();
}

void expectSameTransform(const Transform& a, const Transform& b, const std::string& what) {
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(a.m[size_t(i)], b.m[size_t(i)], 1e-9) << what;
    EXPECT_NEAR(length(a.t - b.t), 0.0, 1e-9) << what;
}

class FlattenTest : public ::testing::Test {
protected:
    int flatEntity(const std::string& path) const { return flat.scene.findEntity(path); }
    Scene scene = test::flattenOffice();  // support/shared_scenes.h
    FlatScene flat = flattenScene(scene);
};

TEST_F(FlattenTest, EveryObjectAtTheTopLevelWithWorldRegions) {
    const Scene& f = flat.scene;
    ASSERT_EQ(f.entities.size(), 5u);  // the partless workstation is gone
    EXPECT_EQ(flatEntity("workstation"), -1);
    for (const Entity& e : f.entities) {
        EXPECT_EQ(e.parent, -1) << e.path;
        EXPECT_TRUE(e.children.empty()) << e.path;
        EXPECT_EQ(e.name, e.path);
        EXPECT_TRUE(e.movable()) << e.path;  // the desk was fixed inside a movable group
    }
    EXPECT_EQ(flat.representative[size_t(scene.findEntity("workstation"))], flatEntity("workstation.desk"));
    // Four group rotations, each giving one region per member.
    EXPECT_EQ(f.entities[size_t(flatEntity("workstation.desk"))].regions.size(), 4u);
    EXPECT_EQ(f.entities[size_t(flatEntity("workstation.desk.monitor"))].regions.size(), 4u);
    EXPECT_EQ(f.entities[size_t(flatEntity("workstation.chair"))].regions.size(), 4u);
    EXPECT_EQ(f.entities[size_t(flatEntity("shelf"))].regions.size(), 2u);
    // The desk's world regions: the group's box shifted by its offset turned 0/90/180/270.
    const Region& turned = f.entities[size_t(flatEntity("workstation.desk"))].regions[1];
    EXPECT_NEAR(turned.lo.x, 1 - 0.2, 1e-12);
    EXPECT_NEAR(turned.hi.y, 3, 1e-12);
    ASSERT_EQ(turned.rotationsDeg.size(), 1u);
    EXPECT_NEAR(turned.rotationsDeg[0], 90, 1e-12);
    // The chair keeps its interval, turned with the group.
    const Region& chair = f.entities[size_t(flatEntity("workstation.chair"))].regions[2];
    EXPECT_TRUE(chair.continuousRotation);
    EXPECT_NEAR(chair.rotationMinDeg, 340, 1e-9);
    EXPECT_NEAR(chair.rotationMaxDeg, 380, 1e-9);

    // The sampler and the lamp move to the desk, in its frame (0.2 m behind the group origin).
    const LightSamplerSpec& s = f.samplers[0];
    EXPECT_EQ(s.entity, flatEntity("workstation.desk"));
    EXPECT_NEAR(length(pointsCenter(s.type->place(Transform())->drawing().dots) - Vec3(0.1, 0.0, 0.75)), 0.0, 1e-12);
    const Entity& desk = f.entities[size_t(flatEntity("workstation.desk"))];
    EXPECT_EQ(desk.samplers, std::vector<int>{0});
    EXPECT_EQ(desk.emitters.size(), 1u);

    // A constraint on the workstation keeps the group's centre and fronts.
    const ConstraintSpec& onGroup = f.constraints[3];
    EXPECT_EQ(onGroup.a, flatEntity("workstation.desk"));
    const auto* groupKind = dynamic_cast<const FlatConstraint*>(onGroup.kind.get());
    ASSERT_NE(groupKind, nullptr);
    EXPECT_STREQ(groupKind->name(), "focus");
    ASSERT_TRUE(groupKind->groupA().has_value());
    EXPECT_EQ(groupKind->groupA()->members.size(), 3u);
    EXPECT_FALSE(groupKind->groupB().has_value());
    EXPECT_FALSE(groupKind->cohesion());
    EXPECT_TRUE(groupKind->countsInNormalizer());
    const auto* onGroupB = dynamic_cast<const FlatConstraint*>(f.constraints[4].kind.get());
    ASSERT_NE(onGroupB, nullptr);  // the conversation with the workstation
    EXPECT_FALSE(onGroupB->groupA().has_value());
    ASSERT_TRUE(onGroupB->groupB().has_value());
    EXPECT_EQ(onGroupB->groupB()->members.size(), 3u);
    EXPECT_EQ(f.constraints[1].kind, scene.constraints[1].kind);  // monitor and chair: no group, kind kept

    // Cohesion: the chair and the monitor towards the desk (the anchor), not counted
    // in G's normalizer; the constraints on objects are kept.
    int chairDistance = 0, chairFocus = 0, monitorDistance = 0, monitorTurn = 0;
    for (size_t i = 0; i < f.constraints.size(); ++i) {
        const ConstraintSpec& c = f.constraints[i];
        EXPECT_EQ(c.kind->countsInNormalizer(), !isCohesion(flat, int(i))) << c.jsonPath;
        if (!isCohesion(flat, int(i))) continue;
        EXPECT_EQ(c.b, flatEntity("workstation.desk"));
        bool isChair = c.a == flatEntity("workstation.chair");
        ASSERT_TRUE(isChair || c.a == flatEntity("workstation.desk.monitor"));
        if (auto range = c.kind->distanceRange()) {
            (isChair ? chairDistance : monitorDistance)++;
            EXPECT_STREQ(c.kind->name(), "distance");
            EXPECT_EQ(range->tolerance, 0.25);
            EXPECT_LT(range->min, range->max);
        } else {
            (isChair ? chairFocus : monitorTurn)++;
        }
    }
    EXPECT_EQ(chairDistance, 1);
    EXPECT_EQ(chairFocus, 1);  // the chair faces the desk from everywhere in its region
    EXPECT_EQ(monitorDistance, 1);
    EXPECT_EQ(monitorTurn, 1);
    EXPECT_EQ(flat.cohesionConstraints, 4);
    EXPECT_EQ(f.constraints.size(), scene.constraints.size() + 4);
    // The desk and its monitor were parent and child: they may still overlap.
    EXPECT_NE(std::find(f.overlap.exempt.begin(), f.overlap.exempt.end(),
                        std::make_pair(flatEntity("workstation.desk"), flatEntity("workstation.desk.monitor"))),
              f.overlap.exempt.end());
}

TEST_F(FlattenTest, EveryHierarchicalLayoutCostsTheSameFlat) {
    GeometryEvaluator hierarchical(scene), flatG(flat.scene);
    Rng rng(hashValues({7}));
    const Layout base = initialLayout(scene);
    int rejected = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Layout layout = sampleLayout(scene, base, rng);
        Layout flatLayout = flatLayoutOf(scene, flat, layout);
        std::vector<Transform> world = worldTransforms(scene, layout);
        std::vector<Transform> flatWorld = worldTransforms(flat.scene, flatLayout);
        for (size_t f = 0; f < flat.scene.entities.size(); ++f) {
            ASSERT_GE(flatLayout.placements[f].region, 0) << flat.scene.entities[f].path << " outside its world regions";
            expectSameTransform(flatWorld[f], world[size_t(flat.originalOf[f])], flat.scene.entities[f].path);
        }
        const LightSamplerSpec& s = scene.samplers[0];
        const LightSamplerSpec& fs = flat.scene.samplers[0];
        std::vector<Vec3> points = s.type->place(world[size_t(s.entity)])->drawing().dots;
        std::vector<Vec3> flatPoints = fs.type->place(flatWorld[size_t(fs.entity)])->drawing().dots;
        ASSERT_EQ(points.size(), flatPoints.size());
        for (size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(length(points[i] - flatPoints[i]), 0.0, 1e-9);
        const Emitter& m = scene.emitters[0];
        const Emitter& fm = flat.scene.emitters[0];
        EXPECT_NEAR(length(world[size_t(m.entity)].applyPoint(m.shape->center()) - flatWorld[size_t(fm.entity)].applyPoint(fm.shape->center())),
                    0.0, 1e-9);

        GeometryResult g = hierarchical.evaluate(world);
        GeometryResult gf = flatG.evaluate(flatWorld, true);
        hierarchical.commit(), flatG.commit();
        EXPECT_NEAR(gf.cost, g.cost, 1e-9);

        EXPECT_EQ(gf.rejected, g.rejected);
        rejected += g.rejected;
        for (const PenaltyTerm& t : gf.terms)
            if (t.constraint >= 0 && isCohesion(flat, t.constraint)) {
                EXPECT_EQ(t.penalty, 0.0) << describe(flat.scene, t);
            }
    }
    EXPECT_GT(rejected, 0);  // both kinds of layout were drawn
    EXPECT_LT(rejected, 300);
}

TEST_F(FlattenTest, LayoutsConvertBothWays) {
    Rng rng(hashValues({8}));
    for (int trial = 0; trial < 50; ++trial) {
        Layout layout = sampleLayout(scene, initialLayout(scene), rng);
        Layout back = hierarchicalLayoutOf(scene, flat, flatLayoutOf(scene, flat, layout));
        for (size_t k = 0; k < scene.entities.size(); ++k) {
            if (!scene.entities[k].movable()) continue;
            const Placement &a = layout.placements[k], &b = back.placements[k];
            EXPECT_NEAR(length(a.position - b.position), 0.0, 1e-9) << scene.entities[k].path;
            EXPECT_TRUE(sameRotation(a.rotationDeg, b.rotationDeg)) << a.rotationDeg << " vs " << b.rotationDeg;
            EXPECT_EQ(a.region, b.region) << scene.entities[k].path;
        }
    }
}

// A movable group inside a fixed, partless wrapper: the wrapper's anchor is the group's
// desk, which moves, but the wrapper stays where the scene puts it. The group's
// placement was once taken relative to a wrapper moved with its desk, so layout.json
// kept the group at its scene placement and its members relative to the moved one.
TEST(FlattenWrapped, AFixedWrapperStaysAndItsGroupConvertsBothWays) {
    Scene scene = test::SceneBuilder()
                      .material("m", test::diffuse(0.5))
                      .room({0, 0, 0}, {8, 6, 3}, "m", "m", "m")
                      .entity("wrap", {1, 0.5, 0}, 10)
                      .entity("ws", {1.5, 1.5, 0}).region({0.5, 0.5}, {5, 4}, {0, 90, 180, 270})
                      .entity("desk").part({1.2, 0.6, 0.75}, "m").end()
                      .entity("chair", {0, -0.7, 0}).rangeRegion({-0.4, -0.9}, {0.4, -0.5}, -30, 30).part({0.5, 0.5, 0.9}, "m").end()
                      .end()
                      .end()
                      .build();
    const FlatScene flat = flattenScene(scene);
    Rng rng(hashValues({9}));
    for (int trial = 0; trial < 20; ++trial) {
        const Layout layout = sampleLayout(scene, initialLayout(scene), rng);
        const Layout back = hierarchicalLayoutOf(scene, flat, flatLayoutOf(scene, flat, layout));
        const std::vector<Transform> a = worldTransforms(scene, layout), b = worldTransforms(scene, back);
        for (size_t k = 0; k < scene.entities.size(); ++k) expectSameTransform(a[k], b[k], scene.entities[k].path);
    }
}

TEST_F(FlattenTest, BreakingAGroupCostsAndLeavesTheMemberOutsideItsRegion) {
    Layout flatLayout = initialLayout(flat.scene);
    const int chair = flatEntity("workstation.chair");
    flatLayout.placements[size_t(chair)].position.y -= 1.0;  // 1 m further from the desk
    GeometryEvaluator g(flat.scene);
    GeometryResult r = g.evaluate(worldTransforms(flat.scene, flatLayout), true);
    double cohesion = 0;
    for (const PenaltyTerm& t : r.terms)
        if (t.constraint >= 0 && isCohesion(flat, t.constraint)) cohesion += t.penalty;
    EXPECT_GT(cohesion, 0);
    EXPECT_TRUE(r.rejected);  // beyond the range by more than the 0.25 m elastic limit

    // In the scene's hierarchy the chair is outside its region: the layout says so by
    // giving no region index (tests/roundtrip writes it to layout.json and reads it back).
    Layout layout = hierarchicalLayoutOf(scene, flat, flatLayout);
    const int original = scene.findEntity("workstation.chair");
    EXPECT_EQ(layout.placements[size_t(original)].region, -1);
}

TEST_F(FlattenTest, TheOptimizerSearchesTheFlatSceneOnOneLevel) {
    OptimizerOptions o = optimizerOptions(flat.scene);
    o.hierarchy = Hierarchy::Flat;
    o.iterations = 3000;
    o.seed = 5;
    OptimizerResult r = Optimizer(flat.scene, o).run();
    ASSERT_GE(r.levels.size(), 1u);
    ASSERT_LE(r.levels.size(), 2u);  // the flat level, and the polish's when it began (or snapped a zero)
    EXPECT_EQ(r.levels[0].name, "flat");
    if (r.levels.size() == 2) {
        EXPECT_EQ(r.levels[1].name, "polish");
    }
    EXPECT_EQ(r.levels[0].entities.size(), 5u);
    EXPECT_TRUE(r.feasible);
    // The best layout keeps the group together (every cohesion rule within its elastic limit).
    for (const PenaltyTerm& t : r.bestGeometry.terms)
        if (t.constraint >= 0 && isCohesion(flat, t.constraint)) {
            EXPECT_LE(t.penalty, 1.0);
        }
}

}  // namespace
}  // namespace luxplan
