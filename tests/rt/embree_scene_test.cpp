// Rays against the Embree scene: openings let rays out, entities move with the layout,
// those flat in the top level and those of a sub-scene of their own alike.
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

// A plate at height z of w x d metres, centred on the origin, made of 202 ny
// triangles: 20200, more than kFlatTriangles, by default (so it is instanced).
TriangleMesh finePlate(double w, double d, double z, uint32_t material, int ny = 100) {
    TriangleMesh m;
    const int nx = 101;  // 2 * 101 * ny triangles
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) m.positions.push_back({w * (double(i) / nx - 0.5), d * (double(j) / ny - 0.5), z});
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const uint32_t a = uint32_t(j * (nx + 1) + i), b = a + 1, c = a + uint32_t(nx + 1), e = c + 1;
            m.addTriangle(a, b, e, material);
            m.addTriangle(a, e, c, material);
        }
    return m;
}

TEST(EmbreeScene, FlatAndInstancedEntitiesMoveAlike) {
    Scene scene = test::SceneBuilder()
                      .material("wood", diffuse(0.5))
                      .room({0, 0, 0}, {6, 4, 3}, "wood", "wood", "wood")
                      .entity("stool", {1, 1, 0}).region({0.5, 0.5}, {5.5, 3.5})
                      .part({0.4, 0.4, 0.5}, "wood")
                      .emitter("bulb", sphereEmitter({0, 0, 1.0}, 0.1), 500)
                      .end()
                      .entity("bench", {4, 2, 0}).region({0.5, 0.5}, {5.5, 3.5})
                      .emitter("spot", diskEmitter({0, 0, 1.5}, {0, 0, -1}, 0.1), 500)
                      .end()
                      .build();
    scene.entities[1].mesh = finePlate(1.0, 0.6, 0.75, scene.materialIndex.at("wood"));
    // A large static item too (a shelf at 2 m over (3, 1)): a sub-scene of its own.
    StaticItem shelf;
    shelf.name = "shelf", shelf.kind = StaticKind::Mesh;
    shelf.mesh.append(finePlate(0.5, 0.5, 2.0, scene.materialIndex.at("wood")), Transform::translate({3, 1, 0}));
    scene.geometry.push_back(shelf);
    ASSERT_LE(scene.entities[0].mesh.triangleCount(), EmbreeScene::kFlatTriangles);
    ASSERT_GT(scene.entities[1].mesh.triangleCount(), EmbreeScene::kFlatTriangles);
    Layout layout = initialLayout(scene);
    EmbreeScene rt(scene, layout);
    EXPECT_EQ(rt.entityCount(), 2u);
    auto down = [&](double x, double y) { return rt.intersect({{x, y, 2.9}, {0, 0, -1}}); };
    auto up = [&](double x, double y) { return rt.intersect({{x, y, 1.0}, {0, 0, 1}}); };
    // Where the scene puts them: the stool's bulb over its top, the bench's spot over it.
    auto bulb = down(1, 1), top = down(1.15, 1), spot = up(4, 2), plate = down(4.45, 2.25);
    ASSERT_TRUE(bulb && top && spot && plate);
    EXPECT_EQ(bulb->kind, HitKind::Emitter);
    EXPECT_NEAR(bulb->t, 2.9 - 1.1, 1e-5);
    EXPECT_NEAR(bulb->geometricNormal.z, 1, 1e-5);
    EXPECT_EQ(top->kind, HitKind::Entity);
    EXPECT_EQ(top->index, 0);
    EXPECT_NEAR(top->t, 2.9 - 0.5, 1e-5);
    EXPECT_EQ(spot->kind, HitKind::Emitter);
    EXPECT_EQ(spot->index, 1);
    EXPECT_NEAR(spot->t, 1.5 - 1.0, 1e-5);
    EXPECT_EQ(plate->kind, HitKind::Entity);
    EXPECT_EQ(plate->index, 1);
    EXPECT_NEAR(plate->t, 2.9 - 0.75, 1e-5);
    auto onShelf = down(3.1, 1.1);
    ASSERT_TRUE(onShelf);
    EXPECT_EQ(onShelf->kind, HitKind::Static);
    EXPECT_EQ(onShelf->index, int(scene.geometry.size()) - 1);
    EXPECT_NEAR(onShelf->t, 0.9, 1e-5);

    // Both moved and turned a quarter: the hits follow, the old places are empty.
    layout.placements[0].position = {2, 3, 0}, layout.placements[0].rotationDeg = 90;
    layout.placements[1].position = {1.5, 1.5, 0}, layout.placements[1].rotationDeg = 90;
    rt.setLayout(layout);
    EXPECT_EQ(down(1, 1)->kind, HitKind::Static);
    EXPECT_EQ(up(4, 2)->kind, HitKind::Static);
    bulb = down(2, 3);
    ASSERT_TRUE(bulb);
    EXPECT_EQ(bulb->kind, HitKind::Emitter);
    EXPECT_NEAR(bulb->t, 2.9 - 1.1, 1e-5);
    // A ray from the side meets the bulb's side: its normal faces the ray, in the world.
    auto side = rt.intersect({{1, 3, 1}, {1, 0, 0}});
    ASSERT_TRUE(side);
    EXPECT_EQ(side->kind, HitKind::Emitter);
    EXPECT_NEAR(side->geometricNormal.x, -1, 1e-5);
    spot = up(1.5, 1.5);
    ASSERT_TRUE(spot);
    EXPECT_EQ(spot->kind, HitKind::Emitter);
    // The plate's 1 m side now runs along y: 0.45 m off along y it is met, along x not.
    plate = down(1.5, 1.5 + 0.45);
    ASSERT_TRUE(plate);
    EXPECT_EQ(plate->kind, HitKind::Entity);
    EXPECT_NEAR(plate->geometricNormal.z, 1, 1e-9);
    EXPECT_EQ(down(1.5 + 0.45, 1.5)->kind, HitKind::Static);
    top = down(2.15, 3);
    ASSERT_TRUE(top);
    EXPECT_EQ(top->kind, HitKind::Entity);
    EXPECT_NEAR(top->t, 2.9 - 0.5, 1e-5);
    EXPECT_NEAR(top->geometricNormal.z, 1, 1e-9);
}

// Items lie flat only while their triangles add up to kFlatTriangles: of three plates
// of 8080 triangles, the third is instanced; all three are met where they stand.
TEST(EmbreeScene, FlatTrianglesStayWithinTheirBound) {
    test::SceneBuilder b;
    b.material("wood", diffuse(0.5)).room({0, 0, 0}, {6, 4, 3}, "wood", "wood", "wood");
    for (int k = 0; k < 3; ++k) b.entity("plate" + std::to_string(k), {1.0 + 2 * k, 2, 0}).region({0.5, 0.5}, {5.5, 3.5}).end();
    Scene scene = b.build();
    for (int k = 0; k < 3; ++k) scene.entities[size_t(k)].mesh = finePlate(1, 1, 0.7, scene.materialIndex.at("wood"), 40);
    Layout layout = initialLayout(scene);
    EmbreeScene rt(scene, layout);
    const size_t room = scene.geometry[0].mesh.triangleCount();
    EXPECT_EQ(rt.flatTriangleCount(), room + 2 * 8080);
    for (int k = 0; k < 3; ++k) layout.placements[size_t(k)].position.y = 1;
    rt.setLayout(layout);
    for (int k = 0; k < 3; ++k) {
        auto hit = rt.intersect({{1.0 + 2 * k, 1.2, 2}, {0, 0, -1}});
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->kind, HitKind::Entity);
        EXPECT_EQ(hit->index, k);
        EXPECT_NEAR(hit->t, 1.3, 1e-5);
        EXPECT_EQ(rt.intersect({{1.0 + 2 * k, 2.7, 2}, {0, 0, -1}})->kind, HitKind::Static);
    }
}

}  // namespace
}  // namespace luxplan
