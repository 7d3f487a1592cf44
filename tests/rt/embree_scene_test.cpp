// Rays against the Embree scene: openings let rays out, instances move with the layout.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/rt/embree_scene.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::diffuse;

Scene makeScene() {
    return test::SceneBuilder()
        .material("floor", diffuse(0.3))
        .material("wall", diffuse(0.7))
        .material("glass", test::glass(0.8))
        .material("wood", diffuse(0.5))
        .room({0, 0, 0}, {6, 4, 3}, "floor", "wall", "wall")
        .window(Wall::South, 1.0, 1.0, 1.0, 1.0)
        .window(Wall::South, 4.0, 1.0, 1.0, 1.0, "glass")
        .blocker("walkway", {2, 2, 0}, {3, 3, 2})
        .emitter("disk", diskEmitter({5, 3, 2.9}, {0, 0, -1}, 0.2), 1000)
        .entity("table", {3, 2, 0})
        .region({1, 1}, {5, 3}, {0, 90})
        .part({1, 0.6, 0.75}, "wood")
        .end()
        .build();
}

struct Fixture : ::testing::Test {
    Scene scene = makeScene();
};

TEST_F(Fixture, RayThroughAnOpenOpeningEscapes) {
    EmbreeScene rt(scene, initialLayout(scene));
    EXPECT_FALSE(rt.intersect({{1.5, 2, 1.5}, {0, -1, 0}}).has_value());
    EXPECT_FALSE(rt.occluded({{1.5, 2, 1.5}, {0, -1, 0}}));
    // Beside the opening the wall is hit, 2 m away, facing into the room.
    auto hit = rt.intersect({{2.5, 2, 1.5}, {0, -1, 0}});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 2.0, 1e-5);
    EXPECT_EQ(hit->kind, HitKind::Static);
    EXPECT_EQ(hit->material, scene.materialIndex.at("wall"));
    EXPECT_NEAR(hit->geometricNormal.y, 1.0, 1e-9);
}

TEST_F(Fixture, GlazedOpeningHoldsAPane) {
    EmbreeScene rt(scene, initialLayout(scene));
    auto hit = rt.intersect({{4.5, 2, 1.5}, {0, -1, 0}});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->material, scene.materialIndex.at("glass"));
}

TEST_F(Fixture, InvisibleBlockersTakeNoPartInLight) {
    EmbreeScene rt(scene, initialLayout(scene));
    auto hit = rt.intersect({{2.5, 2.5, 2.5}, {0, 0, -1}});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->material, scene.materialIndex.at("floor"));  // straight through the walkway box
}

TEST_F(Fixture, EmittersAreHit) {
    EmbreeScene rt(scene, initialLayout(scene));
    auto hit = rt.intersect({{5.1, 3, 1}, {0, 0, 1}});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->kind, HitKind::Emitter);
    EXPECT_EQ(hit->index, 0);
    EXPECT_NEAR(hit->t, 1.9, 1e-5);
}

TEST_F(Fixture, MovingAnInstanceChangesWhatARayHits) {
    Layout layout = initialLayout(scene);
    EmbreeScene rt(scene, layout);
    Ray down{{3, 2, 2}, {0, 0, -1}};
    auto hit = rt.intersect(down);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->kind, HitKind::Entity);
    EXPECT_EQ(hit->index, 0);
    EXPECT_NEAR(hit->t, 2 - 0.75, 1e-5);

    layout.placements[0].position = {1.5, 1.5, 0};
    rt.setLayout(layout);
    hit = rt.intersect(down);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->material, scene.materialIndex.at("floor"));
    EXPECT_NEAR(hit->t, 2.0, 1e-5);
    // The table is now under (1.5, 1.5); rotated by 90 degrees its 1 m side runs along y.
    layout.placements[0].rotationDeg = 90;
    rt.setLayout(layout);
    auto side = rt.intersect({{1.5, 1.5 + 0.45, 2}, {0, 0, -1}});
    ASSERT_TRUE(side.has_value());
    EXPECT_EQ(side->kind, HitKind::Entity);
    auto offSide = rt.intersect({{1.5 + 0.45, 1.5, 2}, {0, 0, -1}});
    ASSERT_TRUE(offSide.has_value());
    EXPECT_EQ(offSide->kind, HitKind::Static);
    EXPECT_NEAR(side->geometricNormal.z, 1.0, 1e-9);
}

}  // namespace
}  // namespace luxplan
