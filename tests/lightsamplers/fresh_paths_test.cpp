// The measurement's parts (lightsamplers/measure_plan.h, fresh_paths.h): a path traced
// afresh is a function of (seed, sampler, item, path) alone, whatever was traced before
// it on the thread (FreshPaths keeps the last item's low-discrepancy sequences), and
// the work plan lists every sampler's items in order.
#include <gtest/gtest.h>

#include <vector>

#include <luxplan/lightsamplers/fresh_paths.h>
#include <luxplan/lightsamplers/measure_plan.h>
#include "support/closed_grey_room.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneLab;

TEST(MeasurePlan, ListsEverySamplersItemsInOrder) {
    const test::ClosedGreyRoom room(0.8, 2000, 100);
    const SceneLab lab(room.scene);
    const WorkPlan plan = planWork(*lab.tracer, MeasureOptions{}, nullptr);
    ASSERT_EQ(plan.samplers(), lab.scene.samplers.size());
    ASSERT_EQ(plan.firstWork.size(), plan.samplers() + 1);
    EXPECT_EQ(plan.firstWork.back(), plan.work.size());
    for (size_t k = 0; k < plan.samplers(); ++k) {
        EXPECT_EQ(plan.firstWork[k + 1] - plan.firstWork[k], size_t(plan.placed[k]->items()));
        for (size_t w = plan.firstWork[k]; w < plan.firstWork[k + 1]; ++w) {
            EXPECT_EQ(plan.work[w].sampler, int(k));
            EXPECT_EQ(plan.work[w].item, int(w - plan.firstWork[k]));
        }
    }
    EXPECT_EQ(plan.workSamplers().size(), plan.work.size());
    MeasureOptions wrongFloors;
    wrongFloors.lightFloors = {1.0};  // one, for a scene of six samplers
    EXPECT_THROW(planWork(*lab.tracer, wrongFloors, nullptr), std::logic_error);
}

TEST(FreshPaths, APathIsTheSameWhateverTheThreadTracedBefore) {
    const test::ClosedGreyRoom room(0.8, 2000, 100);
    const SceneLab lab(room.scene);
    MeasureOptions o;
    o.seed = 11;
    const WorkPlan plan = planWork(*lab.tracer, o, nullptr);
    ASSERT_GE(plan.work.size(), 2u);
    FreshPaths fresh(plan, o);
    RayStats stats;
    const size_t last = plan.work.size() - 1;
    const PathContributions first = fresh.trace(0, 5, stats, false);
    fresh.trace(last, 5, stats, true);  // another item's sequences in between
    const PathContributions again = fresh.trace(0, 5, stats, false);
    EXPECT_TRUE(again.sameAs(first));
    // With a footprint recorded, the same numbers, and the footprint holds its rays.
    const PathContributions recorded = fresh.trace(0, 5, stats, true);
    EXPECT_TRUE(recorded.sameAs(first));
    EXPECT_FALSE(FreshPaths::footprint().segments.empty());
    // Another seed, other paths.
    MeasureOptions other = o;
    other.seed = 12;
    FreshPaths reseeded(plan, other);
    int differ = 0;
    for (int path = 0; path < 8; ++path) {
        const PathContributions mine = fresh.trace(0, path, stats, false);
        differ += !reseeded.trace(0, path, stats, false).sameAs(mine);
    }
    EXPECT_GT(differ, 0);
}

}  // namespace
}  // namespace luxplan
