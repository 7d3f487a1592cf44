// No feasible layout has furniture in a wall: a chain whose regions let origins reach
// the walls, an interior wall and a blocker, checked at every step it holds a feasible
// layout, by a fresh evaluation of that layout.
#include <gtest/gtest.h>

#include <luxplan/constraints/geometry_cost.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

Scene crampedRoom() {
    const std::vector<double> quarter = {0, 90, 180, 270};
    Scene s = test::SceneBuilder()
                  .material("m", test::diffuse(0.5))
                  .room({0, 0, 0}, {6, 4, 2.7}, "m", "m", "m")
                  .box("partition", {2.95, 0, 0}, {3.05, 2.5, 2.7}, "m")
                  .blocker("door_free", {0, 3, 0}, {1.2, 4, 2})
                  // Origins anywhere in the room: every region reaches into the walls.
                  .entity("sofa", {1.5, 1, 0}).region({0, 0}, {6, 4}, quarter).part({2, 0.9, 0.85}, "m").end()
                  .entity("dining", {4.5, 2, 0}).region({0, 0}, {6, 4}, quarter).part({1.2, 0.8, 0.75}, "m")
                  .entity("chair", {0, -0.7, 0}).region({-0.8, -1}, {0.8, -0.6}).part({0.45, 0.5, 0.9}, "m").end()
                  .end()
                  .entity("shelf", {5.5, 3.5, 0}).region({0, 0}, {6, 4}, quarter).part({0.8, 0.3, 1.8}, "m").end()
                  .build();
    // The shelf's region bounds its footprint: it may stand anywhere it fits.
    s.entities[size_t(s.findEntity("shelf"))].regions[0].bound = RegionBound::Footprint;
    return s;
}

TEST(HardLimits, NoFeasibleLayoutHasFurnitureInAWall) {
    const Scene scene = crampedRoom();
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 3000;
    o.seed = 5;
    o.stopAtZeroCost = false;
    Optimizer chain(scene, o, nullptr);
    chain.initialize();
    int feasible = 0;
    for (int i = 0; i < o.iterations; ++i) {
        chain.step();
        if (chain.currentEvaluation().rejected) continue;
        ++feasible;
        GeometryEvaluator fresh(scene);
        GeometryResult g = fresh.evaluate(worldTransforms(scene, chain.current()), /* breakdown = */ true);
        ASSERT_FALSE(g.rejected) << "step " << i << ": " << g.rejectedBy;
        ASSERT_TRUE(g.footprints.empty()) << "step " << i;
        for (const PenaltyTerm& t : g.terms) {
            if (t.hardOverlap()) {
                ASSERT_LE(t.value, scene.overlap.wallTolerance) << "step " << i << ": " << describe(scene, t);
            }
        }
    }
    EXPECT_GT(feasible, o.iterations / 2);
    // The regions let the chain try the walls often: those proposals were turned down.
    uint64_t rejected = 0;
    for (const LevelStats& level : chain.levels())
        for (const MoveStats& m : level.moves) rejected += m.rejectedGeometry;
    EXPECT_GT(rejected, uint64_t(o.iterations / 10));
}

}  // namespace
}  // namespace luxplan
