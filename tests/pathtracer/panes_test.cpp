// The windows' panes crossed analytically (pathtracer/panes.h): every pane a segment
// crosses, none it does not, with the thin-glass transmittance of its angle.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/materials/thin_glass.h>
#include <luxplan/pathtracer/panes.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::SceneBuilder;

TEST(OpeningPanes, CrossedPanesMultiplyTheirTransmittances) {
    // Two glazed windows facing each other (south y = 0, north y = 4), an open one east,
    // a closed one (an opaque panel) west.
    const Scene scene = SceneBuilder()
                            .material("wall", test::diffuse(0.5))
                            .material("glass", test::glass(0.8))
                            .room({0, 0, 0}, {4, 4, 3}, "wall", "wall", "wall")
                            .window(Wall::South, 1, 2, 1, 1, "glass")
                            .window(Wall::North, 1, 2, 1, 1, "glass")
                            .window(Wall::East, 1, 2, 1, 1)
                            .window(Wall::West, 1, 2, 1, 1, "wall")
                            .build();
    const OpeningPanes panes(scene);
    const Vec3 inside(2, 2, 1.5);
    const double T0 = thinGlassTransmittance(1, 0.8);
    EXPECT_NEAR(panes.transmittance(inside, {0, -1, 0}, kInf), T0, 1e-12);   // out through the south pane
    EXPECT_DOUBLE_EQ(panes.transmittance(inside, {0, -1, 0}, 1.9), 1.0);     // stops short of it
    EXPECT_DOUBLE_EQ(panes.transmittance(inside, {1, 0, 0}, kInf), 1.0);     // the open window
    EXPECT_DOUBLE_EQ(panes.transmittance(inside, {-1, 0, 0}, kInf), 1.0);    // the closed one: Embree's
    EXPECT_DOUBLE_EQ(panes.transmittance(inside, {0, 0, 1}, kInf), 1.0);     // the ceiling
    // From outside the south window through the room and out of the north one.
    EXPECT_NEAR(panes.transmittance({2, -1, 1.5}, {0, 1, 0}, kInf), T0 * T0, 1e-12);
    // At an angle: the transmittance of the angle.
    const Vec3 w = normalize(Vec3(0.5, -1, 0));
    EXPECT_NEAR(panes.transmittance(inside, w, kInf), thinGlassTransmittance(1 / std::sqrt(1.25), 0.8), 1e-12);
}

}  // namespace
}  // namespace luxplan
