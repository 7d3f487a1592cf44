// Group composition of transforms and region membership.
#include <gtest/gtest.h>

#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {

TEST(Layout, GroupTransformsCompose) {
    Scene s;
    auto named = [](std::string name, std::string path) {
        Entity e;
        e.name = std::move(name);
        e.path = std::move(path);
        return e;
    };
    Entity group = named("g", "g"), child = named("c", "g.c"), grandchild = named("d", "g.c.d");
    child.parent = 0, child.position = {1, 0, 0.75}, child.rotationDeg = 90;
    grandchild.parent = 1, grandchild.position = {0.5, 0, 0};
    group.children = {1};
    child.children = {2};
    s.entities = {group, child, grandchild};
    Layout layout = initialLayout(s);
    layout.placements[0].position = {2, 3, 0};
    layout.placements[0].rotationDeg = 90;
    auto world = worldTransforms(s, layout);
    // Child at (1, 0) in the group frame, which is turned 90 degrees: (2, 4) in the world.
    Vec3 c = world[1].applyPoint({0, 0, 0});
    EXPECT_NEAR(c.x, 2, 1e-12);
    EXPECT_NEAR(c.y, 4, 1e-12);
    EXPECT_NEAR(c.z, 0.75, 1e-12);
    // The grandchild is 0.5 along the child's x, which points to world -x after 180 degrees.
    Vec3 d = world[2].applyPoint({0, 0, 0});
    EXPECT_NEAR(d.x, 1.5, 1e-12);
    EXPECT_NEAR(d.y, 4, 1e-12);
    Vec3 front = world[2].applyVector({0, -1, 0});
    EXPECT_NEAR(front.y, 1, 1e-12);
}

TEST(Layout, RegionMembership) {
    Region discrete;
    discrete.lo = {0, 0}, discrete.hi = {2, 1}, discrete.rotationsDeg = {0, 90};
    EXPECT_TRUE(regionContains(discrete, {1, 0.5}, 90));
    EXPECT_TRUE(regionContains(discrete, {1, 0.5}, 450));
    EXPECT_FALSE(regionContains(discrete, {1, 0.5}, 45));
    EXPECT_FALSE(regionContains(discrete, {2.1, 0.5}, 0));
    Region interval;
    interval.lo = {0, 0}, interval.hi = {0, 5}, interval.continuousRotation = true;
    interval.rotationMinDeg = -30, interval.rotationMaxDeg = 30;
    EXPECT_TRUE(regionContains(interval, {0, 2}, 350));
    EXPECT_TRUE(regionContains(interval, {0, 2}, 30));
    EXPECT_FALSE(regionContains(interval, {0, 2}, 31));
    EXPECT_FALSE(regionContains(interval, {0.1, 2}, 0));
}

}  // namespace
}  // namespace luxplan
