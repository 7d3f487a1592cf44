// layout.json of what the optimizer finds, read back by io: the best layout of a run,
// and a flat layout that broke a group, seen in the scene's hierarchy (a member
// outside its regions is written without a region index). The scenes and runs are
// those of tests/optimizer (optimizer_test.cpp, flatten_test.cpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/io/layout_io.h>
#include <luxplan/optimizer/flatten.h>
#include <luxplan/optimizer/optimizer.h>
#include "support/desk_light.h"
#include "support/shared_scenes.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

TEST(LayoutFile, TheBestLayoutOfARunReadsBack) {
    const Scene scene = test::optimizerOffice();
    test::DeskLight light(scene);
    OptimizerOptions o = optimizerOptions(scene);
    o.iterations = 500;
    OptimizerResult r = Optimizer(scene, o, &light).run();
    test::TempDir dir;
    io::writeLayout(dir.path() / "layout.json", scene, r.best);

    Layout back = io::readLayout(dir.path() / "layout.json", scene);
    for (size_t e = 0; e < scene.entities.size(); ++e) {
        EXPECT_NEAR(back.placements[e].position.x, r.best.placements[e].position.x, 1e-12);
        EXPECT_NEAR(back.placements[e].rotationDeg, r.best.placements[e].rotationDeg, 1e-12);
    }
}

TEST(LayoutFile, AMemberOutsideItsRegionsIsWrittenWithoutARegionAndReadsBack) {
    const Scene scene = test::flattenOffice();
    const FlatScene flat = flattenScene(scene);
    Layout flatLayout = initialLayout(flat.scene);
    flatLayout.placements[size_t(flat.scene.findEntity("workstation.chair"))].position.y -= 1.0;  // 1 m further from the desk
    Layout layout = hierarchicalLayoutOf(scene, flat, flatLayout);
    const int original = scene.findEntity("workstation.chair");
    ASSERT_EQ(layout.placements[size_t(original)].region, -1);

    auto json = nlohmann::json::parse(io::layoutToJson(scene, layout));
    EXPECT_FALSE(json["entities"]["workstation.chair"].contains("region"));
    EXPECT_TRUE(json["entities"]["workstation"].contains("region"));
    test::TempDir dir;
    auto file = dir.write("layout.json", io::layoutToJson(scene, layout));
    Layout read = io::readLayout(file, scene);
    EXPECT_NEAR(length(read.placements[size_t(original)].position - layout.placements[size_t(original)].position), 0.0,
                1e-9);
}

}  // namespace
}  // namespace luxplan
