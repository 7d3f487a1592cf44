// The C++ scene builder (support/scene_builder.h) against the loader: the scenes of
// support/shared_scenes.h and a scene with every other thing the builder writes are
// the very scenes the loader makes of the JSON they replaced, to the bit.
#include <gtest/gtest.h>

#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include "support/scene_builder.h"
#include "support/scene_compare.h"
#include "support/shared_scenes.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

Scene load(const std::string& file, const std::string& json) {
    test::TempDir dir;
    return io::loadScene(dir.write(file, json));
}

TEST(SceneBuilder, FlattenOffice) {
    test::expectSameScene(test::flattenOffice(), load("office.json", R"({
      "luxplan": 1,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [
        {"name": "room", "room": {"min": [0, 0, 0], "max": [6, 4, 3]}, "materials": {"floor": "m", "walls": "m", "ceiling": "m"}},
        {"name": "door", "box": {"min": [2.5, 0, 0], "max": [3.5, 1, 2]}, "invisible": true}
      ],
      "entities": [
        {"name": "workstation", "position": [2, 2],
         "placement": {"regions": [{"min": [1, 1], "max": [5, 3], "rotations": [0, 90, 180, 270]}]},
         "samplers": [{"name": "desk_light", "type": "planar", "center": [0.1, 0.2, 0.75], "size": [1, 0.5], "target": [300, 500]}],
         "emitters": [{"name": "lamp", "shape": "sphere", "center": [0.5, 0.3, 1.2], "radius": 0.05, "flux_lm": 500}],
         "children": [
           {"name": "desk", "position": [0, 0.2], "parts": [{"box": {"size": [1.2, 0.6, 0.75]}, "material": "m"}],
            "children": [{"name": "monitor", "position": [0, 0.1, 0.75],
                          "placement": {"regions": [{"min": [-0.4, 0], "max": [0.4, 0.2], "rotation_range": [-20, 20]}]},
                          "parts": [{"box": {"size": [0.5, 0.15, 0.4]}, "material": "m"}]}]},
           {"name": "chair", "position": [0, -0.5], "rotation": 180,
            "placement": {"regions": [{"min": [-0.3, -0.8], "max": [0.3, -0.4], "rotation_range": [160, 200]}]},
            "parts": [{"box": {"size": [0.5, 0.5, 0.9]}, "material": "m"}]}]},
        {"name": "shelf", "position": [0.2, 3], "rotation": 90,
         "placement": {"regions": [{"min": [0.2, 1], "max": [0.2, 3.5], "rotations": [90]},
                                   {"min": [5.8, 1], "max": [5.8, 3.5], "rotations": [270]}]},
         "parts": [{"box": {"size": [0.8, 0.3, 1.8]}, "material": "m"}]},
        {"name": "plant", "position": [5, 3.5],
         "placement": {"regions": [{"min": [0.4, 0.4], "max": [5.6, 3.6]}]},
         "parts": [{"box": {"size": [0.4, 0.4, 1.0]}, "material": "m"}]}
      ],
      "constraints": [
        {"type": "alignment", "a": "workstation.desk", "b": "room", "tolerance_deg": 5},
        {"type": "focus", "a": "workstation.desk.monitor", "b": "workstation.chair", "tolerance_deg": 15},
        {"type": "distance", "a": "plant", "b": "workstation.desk", "min": 1.5, "max": 100},
        {"type": "focus", "a": "workstation", "b": "plant", "tolerance_deg": 60},
        {"type": "conversation", "a": "plant", "b": "workstation", "min": 1, "max": 3, "tolerance_deg": 90}
      ]})"));
}

TEST(SceneBuilder, OptimizerOffice) {
    test::expectSameScene(test::optimizerOffice(), load("office.json", R"({
      "luxplan": 1,
      "name": "office",
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [
        {"name": "room", "room": {"min": [0, 0, 0], "max": [6, 4, 3]}, "materials": {"floor": "m", "walls": "m", "ceiling": "m"}},
        {"name": "door", "box": {"min": [2.5, 0, 0], "max": [3.5, 1, 2]}, "invisible": true}
      ],
      "samplers": [{"name": "desk_light", "type": "planar", "center": [0, 0, 0.75], "size": [1, 1], "target": [300, 500]}],
      "entities": [
        {"name": "workstation", "position": [2, 2],
         "placement": {"regions": [{"min": [1, 1], "max": [5, 3], "rotations": [0, 90, 180, 270]}]},
         "children": [
           {"name": "desk", "parts": [{"box": {"size": [1.2, 0.6, 0.75]}, "material": "m"}],
            "children": [{"name": "monitor", "position": [0, 0.1, 0.75],
                          "placement": {"regions": [{"min": [-0.4, 0], "max": [0.4, 0.2], "rotation_range": [-20, 20]}]},
                          "parts": [{"box": {"size": [0.5, 0.15, 0.4]}, "material": "m"}]}]},
           {"name": "chair", "position": [0, -0.7], "rotation": 180,
            "placement": {"regions": [{"min": [-0.5, -1.0], "max": [0.5, -0.5], "rotation_range": [120, 240]}]},
            "parts": [{"box": {"size": [0.5, 0.5, 0.9]}, "material": "m"}]}]},
        {"name": "shelf", "position": [0.2, 3], "rotation": 90,
         "placement": {"regions": [{"min": [0.2, 1], "max": [0.2, 3.5], "rotations": [90]},
                                   {"min": [5.8, 1], "max": [5.8, 3.5], "rotations": [270]}]},
         "parts": [{"box": {"size": [0.8, 0.3, 1.8]}, "material": "m"}]},
        {"name": "plant", "position": [5, 3.5],
         "placement": {"regions": [{"min": [0.4, 0.4], "max": [5.6, 3.6]}]},
         "parts": [{"box": {"size": [0.4, 0.4, 1.0]}, "material": "m"}]}
      ],
      "constraints": [
        {"type": "alignment", "a": "workstation.desk", "b": "room", "tolerance_deg": 5},
        {"type": "distance", "a": "workstation.desk", "b": "workstation.chair", "min": 0.5, "max": 0.9},
        {"type": "focus", "a": "workstation.chair", "b": "workstation.desk", "tolerance_deg": 20},
        {"type": "focus", "a": "workstation.desk.monitor", "b": "workstation.chair", "tolerance_deg": 15},
        {"type": "distance", "a": "plant", "b": "workstation", "min": 1.5, "max": 100}
      ],
      "objective": {"lighting_weight": 0.5},
      "optimizer": {"iterations": 3000, "seed": 3}
    })"));
}

TEST(SceneBuilder, FurnishedRoom) {
    test::expectSameScene(test::furnishedRoom(), load("scene.json", R"({"luxplan": 1,
      "materials": {"wall": {"type": "diffuse", "reflectance": 0.6},
                    "wood": {"type": "glossy", "reflectance": 0.04, "base": [0.5, 0.3, 0.1], "roughness": 0.25},
                    "glass": {"type": "glass", "transmittance": 0.8},
                    "chrome": {"type": "mirror", "reflectance": 0.9}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [5,4,3]},
                    "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"},
                    "openings": [{"wall": "south", "offset": 1, "width": 1.5, "sill": 0.9, "height": 1.2, "material": "glass"}]},
                   {"name": "pillar", "box": {"min": [4,3,0], "max": [4.5,3.5,3]}, "material": "chrome"},
                   {"name": "blocker", "box": {"min": [0,0,0], "max": [0.5,0.5,1]}, "invisible": true}],
      "luminaires": [{"name": "panel", "shape": "rect", "center": [2.5,2,2.99], "normal": [0,0,-1], "size": [0.6,1.2],
                      "up": [0,1,0], "flux_lm": 3000, "cct_k": 4000},
                     {"name": "bulb", "shape": "sphere", "center": [1,1,2.5], "radius": 0.1, "flux_lm": 800}],
      "entities": [{"name": "desk1", "position": [2,1.5], "rotation": 90,
                    "placement": {"regions": [{"min": [1,1], "max": [4,3], "rotations": [0, 90]}]},
                    "parts": [{"preset": "desk", "material": "wood"}],
                    "children": [{"name": "lamp", "position": [0.5,0.2,0.75],
                                  "parts": [{"box": {"size": [0.1,0.1,0.4]}, "material": "chrome"}],
                                  "emitters": [{"name": "shade", "shape": "disk", "center": [0,0,0.45], "normal": [0,0,-1],
                                                "radius": 0.08, "flux_lm": 400}]}]},
                   {"name": "group", "children": [{"name": "chair", "position": [3,2],
                                                   "parts": [{"preset": "chair", "material": "wood"}]}]}]})"));
}

TEST(SceneBuilder, LitRoom) {
    test::expectSameScene(test::litRoom(), load("scene.json", R"({"luxplan": 1,
      "materials": {"wall": {"type": "diffuse", "reflectance": 0.6}, "wood": {"type": "diffuse", "reflectance": 0.4}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [5,4,3]},
                    "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}},
                   {"name": "block", "box": {"min": [2,2,0], "max": [3,3,1]}, "material": "wood"}],
      "luminaires": [{"name": "lamp", "shape": "rect", "center": [2.5,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 4000}]})"));
}

// What the shared scenes leave out: presets of another size or off the floor, the
// objective, the maintenance factor.
TEST(SceneBuilder, PresetsAndTheObjective) {
    test::expectSameScene(test::SceneBuilder()
                              .material("wood", test::diffuse(0.4))
                              .lightingWeight(1)
                              .maintenanceFactor(0.67)
                              .entity("table", {1.5, 2, 0}).region({1, 1}, {2.5, 3}, {0, 90}).preset("table", "wood", Vec3(1.0, 0.8, 0.75))
                              .entity("lamp", {0, 0, 0.75}).preset("stand_lamp", "wood", std::nullopt, Vec3(0.2, 0, 0.1)).end()
                              .end()
                              .build(),
                          load("scene.json", R"({"luxplan": 1,
      "materials": {"wood": {"type": "diffuse", "reflectance": 0.4}},
      "objective": {"lighting_weight": 1},
      "maintenance_factor": 0.67,
      "entities": [{"name": "table", "position": [1.5, 2],
                    "placement": {"regions": [{"min": [1, 1], "max": [2.5, 3], "rotations": [0, 90]}]},
                    "parts": [{"preset": "table", "size": [1.0, 0.8, 0.75], "material": "wood"}],
                    "children": [{"name": "lamp", "position": [0, 0, 0.75],
                                  "parts": [{"preset": "stand_lamp", "center": [0.2, 0, 0.1], "material": "wood"}]}]}]})"));
}

// A sampler's statistics goals, with the loader's default tolerances and order.
TEST(SceneBuilder, StatisticsGoals) {
    test::expectSameScene(test::SceneBuilder()
                              .sampler("work", planarSampler({3, 2, 0.8}, {0, 0, 1}, {0, 1, 0}, {2, 1}, {4, 2}), 500)
                              .statistic(Statistic::U0, 0.6, 1, 0.2)
                              .statistic(Statistic::Min, 200, 1e9)
                              .statistic(Statistic::Max, 0, 2000)
                              .build(),
                          load("scene.json", R"({"luxplan": 1,
      "samplers": [{"name": "work", "type": "planar", "center": [3, 2, 0.8], "size": [2, 1], "grid": [4, 2], "target": [500, null],
                    "statistics": {"u0": {"target": [0.6, 1], "tolerance": 0.2}, "min": {"target": [200, 1e9]},
                                   "max": {"target": [0, 2000]}}}]})"));
}

}  // namespace
}  // namespace luxplan
