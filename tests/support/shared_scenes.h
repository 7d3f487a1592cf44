// Builder scenes (support/scene_builder.h) that more than one test file uses: the
// two offices of tests/optimizer, whose layouts tests/roundtrip writes to
// layout.json, and the rooms of tests/output, whose glTF tests/roundtrip imports.
// tests/io/scene_builder_test.cpp checks each against the JSON it replaced.
#pragma once

#include <luxplan/scene/scene.h>

namespace luxplan::test {

// A partless group (workstation) whose anchor is the desk (fixed in the group, at an
// offset), a desk that is also a group (its monitor), a sampler and a lamp on the
// partless group, and objects at the top level (optimizer/flatten_test.cpp).
Scene flattenOffice();

// A workstation group (a desk with its monitor, a chair), a shelf on two walls and a
// plant in a 6 x 4 m room, a desk sampler and five constraints; 3000 iterations,
// seed 3 (optimizer/optimizer_test.cpp).
Scene optimizerOffice();

// Every kind of material, a glazed window, a pillar and a blocker, three emitter
// shapes (one carried), presets and an empty group (output/gltf_test.cpp).
Scene furnishedRoom();

// A 5 x 4 m room with a block on the floor under a 4000 lm ceiling panel
// (output/render_test.cpp, output/denoise_test.cpp).
Scene litRoom();

}  // namespace luxplan::test
