// The plan view and the work-plane grid: furniture shows on the floor, samplers take
// the colour of their result, and the grid measures pi L under a uniform sky.
#include <gtest/gtest.h>

#include <luxplan/output/plan.h>
#include "support/lab.h"
#include "support/threads.h"

namespace luxplan {
namespace {

const char* kRoomWithTable = R"({"luxplan": 1,
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.5}, "wood": {"type": "diffuse", "reflectance": 0.4},
                "glass": {"type": "glass", "transmittance": 0.8}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [8,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"},
                "openings": [{"wall": "south", "offset": 5, "width": 2, "sill": 0.9, "height": 1.2, "material": "glass"},
                             {"wall": "west", "offset": 1, "width": 1, "sill": 0, "height": 2.1}]}],
  "luminaires": [{"name": "lamp", "shape": "rect", "center": [6.5,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 6000}],
  "entities": [{"name": "table", "position": [1.5, 2],
                "placement": {"regions": [{"min": [1,1], "max": [2.5,3], "rotations": [0, 90]}]},
                "parts": [{"preset": "table", "size": [1.0, 0.8, 0.75], "material": "wood"}],
                "samplers": [{"name": "reading", "type": "planar", "center": [0,0,0.76], "size": [0.8,0.6],
                              "grid": [2,2], "target": [300, null], "tolerance": 100}]}]})";

bool isGreen(Rgb p) { return p.g > 140 && p.r < 40 && p.b < 100; }
bool isRed(Rgb p) { return p.r > 200 && p.g < 50 && p.b < 50; }

int count(const Image& image, bool (*test)(Rgb)) {
    return int(std::count_if(image.pixels().begin(), image.pixels().end(), test));
}

TEST(Plan, FurnitureAndSamplersShowWhereTheyAre) {
    test::Lab lab(kRoomWithTable);
    Layout layout = initialLayout(lab.scene);
    PlanOptions options;  // 80 px/m, 50 px margin: world (x, y) at (50 + 80 x, 50 + 80 (4 - y))
    auto pixel = [](double x, double y) { return std::pair<int, int>{int(50 + 80 * x), int(50 + 80 * (4 - y))}; };

    PlanData pass;
    pass.samplers = std::vector<SamplerResult>(1);
    (*pass.samplers)[0].value = 450;
    Image image = renderPlan(lab.scene, layout, options, pass);
    EXPECT_EQ(image.width(), 8 * 80 + 2 * 50);
    auto [fx, fy] = pixel(4, 3);          // bare floor
    auto [tx, ty] = pixel(1.05, 2.35);    // table top corner, outside the sampler's outline
    EXPECT_NE(image.at(tx, ty), image.at(fx, fy));
    // The table's footprint follows the layout.
    layout.placements[0].position = {2.5, 2.0, layout.placements[0].position.z};
    Image moved = renderPlan(lab.scene, layout, options, pass);
    EXPECT_EQ(moved.at(tx, ty), moved.at(fx, fy));
    EXPECT_GT(count(image, isGreen), 100);
    EXPECT_EQ(count(image, isRed), 0);

    PlanData fail = pass;
    (*fail.samplers)[0].value = 120;
    Image red = renderPlan(lab.scene, initialLayout(lab.scene), options, fail);
    EXPECT_GT(count(red, isRed), 100);
    EXPECT_EQ(count(red, isGreen), 0);

    test::TempDir dir;
    writePng(image, dir.path() / "plan.png");
    EXPECT_EQ(readPng(dir.path() / "plan.png").pixels(), image.pixels());
}

TEST(Plan, WorkPlaneUnderAUniformSkyIsPiL) {
    test::Lab lab(R"({"luxplan": 1, "daylight": {"sky": {"model": "uniform", "luminance_nits": 2000}, "sun": false, "ground_reflectance": 0}})");
    Bounds3 area({0, 0, 0}, {1.2, 0.7, 1});
    IlluminanceGrid grid = test::withThreads(2, [&] { return measureWorkPlane(*lab.tracer, area, 0.8, 0.5, 256, 3); });
    EXPECT_EQ(grid.nx, 3);
    EXPECT_EQ(grid.ny, 2);
    ASSERT_EQ(grid.values.size(), 6u);
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            Vec3 c = grid.cellCenter(i, j);
            EXPECT_TRUE(area.contains(c)) << i << " " << j;
            EXPECT_NEAR(c.z, 0.8, 1e-12);
            double sigma = grid.errors[size_t(j * grid.nx + i)];
            EXPECT_NEAR(grid.at(i, j), kPi * 2000, 4 * sigma + 1e-3 * kPi * 2000) << i << " " << j;
        }
    // The height is above the room's floor.
    IlluminanceGrid raised = measureWorkPlane(*lab.tracer, Bounds3({0, 0, 1}, {1, 1, 2}), 0.5, 1, 1, 3);
    EXPECT_NEAR(raised.cellCenter(0, 0).z, 1.5, 1e-12);
    // Seeded per cell and path: the thread count does not matter.
    IlluminanceGrid one = test::withThreads(1, [&] { return measureWorkPlane(*lab.tracer, area, 0.8, 0.5, 256, 3); });
    EXPECT_EQ(one.values, grid.values);
}

TEST(Plan, WorkPlaneMapAndLegendColourTheFloor) {
    test::Lab lab(kRoomWithTable);
    PlanData data;
    data.workPlane = measureWorkPlane(*lab.tracer, lab.scene.room()->box, 0.8, 0.5, 8, 1);
    EXPECT_EQ(data.workPlane->nx, 16);
    EXPECT_EQ(data.workPlane->ny, 8);
    PlanOptions options;
    options.title = "lit room";
    Image image = renderPlan(lab.scene, initialLayout(lab.scene), options, data);
    EXPECT_GT(image.width(), 8 * 80 + 2 * 50);  // room for the legend
    // Under the lamp the floor is brighter on the scale than in the far corner.
    FalseColor scale = autoFalseColor(data.workPlane->values);
    double under = data.workPlane->at(13, 4), corner = data.workPlane->at(0, 0);
    EXPECT_GT(under, corner);
    EXPECT_GE(scale.maxValue, under * 0.5);
}

}  // namespace
}  // namespace luxplan
