// Issue 58: the optimizer's independent measurements take their paths by use. The
// report's (the result, `measure`'s default count) is high; the selection's (zero-cost
// confirmations, the candidates' re-measures: dozens in a run) stays low.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/path_traced_lighting.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace independent_paths {

Scene litBox() {
    const Vec3 kZ(0, 0, 1);
    return test::SceneBuilder()
        .material("wall", test::diffuse(0.5))
        .room({0, 0, 0}, {4, 3, 2.8}, "wall", "wall", "wall")
        .emitter("panel", rectEmitter({2, 1.5, 2.79}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
        .sampler("task", planarSampler({2, 1.5, 0.8}, kZ, {0, 1, 0}, {1, 1}, {2, 2}), 100, 1000, 100)
        .build();
}

TEST(IndependentPaths, TheReportAndTheSelectionEachTakeTheirOwnCount) {
    const Scene scene = litBox();
    MeasureOptions measure;
    measure.pathsPerPoint = 4, measure.seed = 3;
    PathTracedLighting lighting(scene, nullptr, measure);
    lighting.setReportPaths(96);
    lighting.setSelectionPaths(24);
    const Layout layout = initialLayout(scene);
    const std::vector<Transform> world = worldTransforms(scene, layout);
    LightingBreakdown report, selection;
    lighting.measureIndependently(layout, world, &report, 7, IndependentUse::Report);
    lighting.measureIndependently(layout, world, &selection, 7, IndependentUse::Selection);
    ASSERT_EQ(report.samplers.size(), 1u);
    ASSERT_EQ(selection.samplers.size(), 1u);
    EXPECT_EQ(report.samplers[0].pathsPerPoint, 96);
    EXPECT_EQ(selection.samplers[0].pathsPerPoint, 24);
    // Unset: the search's count for both (an evaluator nobody configured).
    PathTracedLighting plain(scene, nullptr, measure);
    LightingBreakdown unset;
    plain.measureIndependently(layout, world, &unset, 7, IndependentUse::Report);
    ASSERT_EQ(unset.samplers.size(), 1u);
    EXPECT_EQ(unset.samplers[0].pathsPerPoint, 4);
}

}  // namespace independent_paths
}  // namespace luxplan
