// A 6 x 4 x 3 m room lit through a south window (glazed) and an east one (open), with
// a door closed by an opaque panel on the west wall (not an entrance for the sun):
// the shell that the tests of pathtracer/sun_patches.h and open_sun_disks.h shade with.
#pragma once

#include "support/scene_builder.h"

namespace luxplan::test {

inline Scene twoWindowRoom() {
    return SceneBuilder()
        .material("wall", diffuse(0.5))
        .material("glass", glass(0.8))
        .room({0, 0, 0}, {6, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 1, 2, 1, 1, "glass")
        .window(Wall::East, 1, 1.5, 0.8, 1.2)
        .window(Wall::West, 1, 1, 0, 2.1, "wall")
        .build();
}

}  // namespace luxplan::test
