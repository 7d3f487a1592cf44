#include "support/shared_scenes.h"

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include "support/scene_builder.h"

namespace luxplan::test {
namespace {

// What both offices have: a 6 x 4 x 3 m room with a door kept free (an invisible box)...
SceneBuilder officeRoom() {
    SceneBuilder b;
    b.name("office").material("m", diffuse(0.5)).room({0, 0, 0}, {6, 4, 3}, "m", "m", "m");
    b.blocker("door", {2.5, 0, 0}, {3.5, 1, 2});
    return b;
}

// ... and, after the workstation, a shelf on the west or the east wall and a plant.
SceneBuilder& shelfAndPlant(SceneBuilder& b) {
    return b.entity("shelf", {0.2, 3, 0}, 90).region({0.2, 1}, {0.2, 3.5}, {90}).region({5.8, 1}, {5.8, 3.5}, {270})
        .part({0.8, 0.3, 1.8}, "m").end()
        .entity("plant", {5, 3.5, 0}).region({0.4, 0.4}, {5.6, 3.6}).part({0.4, 0.4, 1.0}, "m").end();
}

}  // namespace

Scene flattenOffice() {
    SceneBuilder b = officeRoom();
    b.entity("workstation", {2, 2, 0}).region({1, 1}, {5, 3}, {0, 90, 180, 270})
        .sampler("desk_light", planarSampler({0.1, 0.2, 0.75}, {0, 0, 1}, {0, 1, 0}, {1, 0.5}, {4, 4}), 300, 500)
        .emitter("lamp", sphereEmitter({0.5, 0.3, 1.2}, 0.05), 500)
        .entity("desk", {0, 0.2, 0}).part({1.2, 0.6, 0.75}, "m")
        .entity("monitor", {0, 0.1, 0.75}).rangeRegion({-0.4, 0}, {0.4, 0.2}, -20, 20).part({0.5, 0.15, 0.4}, "m").end()
        .end()
        .entity("chair", {0, -0.5, 0}, 180).rangeRegion({-0.3, -0.8}, {0.3, -0.4}, 160, 200).part({0.5, 0.5, 0.9}, "m").end()
        .end();
    return shelfAndPlant(b)
        .constraint(alignmentConstraint(5), "workstation.desk", "room")
        .constraint(focusConstraint(15), "workstation.desk.monitor", "workstation.chair")
        .constraint(distanceConstraint({1.5, 100, std::nullopt}), "plant", "workstation.desk")
        .constraint(focusConstraint(60), "workstation", "plant")
        .constraint(conversationConstraint({1, 3, std::nullopt}, 90), "plant", "workstation")
        .build();
}

Scene optimizerOffice() {
    OptimizerSettings settings;
    settings.iterations = 3000;
    settings.seed = 3;
    SceneBuilder b = officeRoom();
    b.sampler("desk_light", planarSampler({0, 0, 0.75}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 300, 500)
        .entity("workstation", {2, 2, 0}).region({1, 1}, {5, 3}, {0, 90, 180, 270})
        .entity("desk").part({1.2, 0.6, 0.75}, "m")
        .entity("monitor", {0, 0.1, 0.75}).rangeRegion({-0.4, 0}, {0.4, 0.2}, -20, 20).part({0.5, 0.15, 0.4}, "m").end()
        .end()
        .entity("chair", {0, -0.7, 0}, 180).rangeRegion({-0.5, -1.0}, {0.5, -0.5}, 120, 240).part({0.5, 0.5, 0.9}, "m").end()
        .end();
    return shelfAndPlant(b)
        .constraint(alignmentConstraint(5), "workstation.desk", "room")
        .constraint(distanceConstraint({0.5, 0.9, std::nullopt}), "workstation.desk", "workstation.chair")
        .constraint(focusConstraint(20), "workstation.chair", "workstation.desk")
        .constraint(focusConstraint(15), "workstation.desk.monitor", "workstation.chair")
        .constraint(distanceConstraint({1.5, 100, std::nullopt}), "plant", "workstation")
        .lightingWeight(0.5)
        .optimizer(settings)
        .build();
}

Scene furnishedRoom() {
    return SceneBuilder()
        .material("wall", diffuse(0.6))
        .material("wood", glossy(0.04, 0.25, Vec3(0.5, 0.3, 0.1)))
        .material("glass", glass(0.8))
        .material("chrome", mirror(0.9))
        .room({0, 0, 0}, {5, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 1, 1.5, 0.9, 1.2, "glass")
        .box("pillar", {4, 3, 0}, {4.5, 3.5, 3}, "chrome")
        .blocker("blocker", {0, 0, 0}, {0.5, 0.5, 1})
        .emitter("panel", rectEmitter({2.5, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 1.2}), 3000)
        .emitter("bulb", sphereEmitter({1, 1, 2.5}, 0.1), 800)
        .entity("desk1", {2, 1.5, 0}, 90).region({1, 1}, {4, 3}, {0, 90}).preset("desk", "wood")
        .entity("lamp", {0.5, 0.2, 0.75}).part({0.1, 0.1, 0.4}, "chrome")
        .emitter("shade", diskEmitter({0, 0, 0.45}, {0, 0, -1}, 0.08), 400)
        .end()
        .end()
        .entity("group").entity("chair", {3, 2, 0}).preset("chair", "wood").end().end()
        .build();
}

Scene litRoom() {
    return SceneBuilder()
        .material("wall", diffuse(0.6))
        .material("wood", diffuse(0.4))
        .room({0, 0, 0}, {5, 4, 3}, "wall", "wall", "wall")
        .box("block", {2, 2, 0}, {3, 3, 1}, "wood")
        .emitter("lamp", rectEmitter({2.5, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 4000)
        .build();
}

}  // namespace luxplan::test
