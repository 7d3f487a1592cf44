// The plan view and the work-plane grid: furniture shows on the floor, samplers take
// the colour of their result, and the grid measures pi L under a uniform sky.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/output/plan.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"
#include "support/pixels.h"
#include "support/temp_files.h"
#include "support/threads.h"

namespace luxplan {
namespace {

// An 8 x 4 m room with a glazed south window, an open west door and a ceiling panel at
// its east end; a table with a reading sampler (at least 300 lx) at its west end.
Scene roomWithTable() {
    return test::SceneBuilder()
        .material("wall", test::diffuse(0.5))
        .material("wood", test::diffuse(0.4))
        .material("glass", test::glass(0.8))
        .room({0, 0, 0}, {8, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 5, 2, 0.9, 1.2, "glass")
        .window(Wall::West, 1, 1, 0, 2.1)
        .emitter("lamp", rectEmitter({6.5, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 6000)
        .entity("table", {1.5, 2, 0}).region({1, 1}, {2.5, 3}, {0, 90}).preset("table", "wood", Vec3(1.0, 0.8, 0.75))
        .sampler("reading", planarSampler({0, 0, 0.76}, {0, 0, 1}, {0, 1, 0}, {0.8, 0.6}, {2, 2}), 300, kInf, 100)
        .end()
        .build();
}

bool isGreen(Rgb p) { return p.g > 140 && p.r < 40 && p.b < 100; }
bool isRed(Rgb p) { return p.r > 200 && p.g < 50 && p.b < 50; }

using test::countPixels;

TEST(Plan, FurnitureAndSamplersShowWhereTheyAre) {
    test::SceneLab lab(roomWithTable());
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
    EXPECT_GT(countPixels(image, isGreen), 100);
    EXPECT_EQ(countPixels(image, isRed), 0);

    PlanData fail = pass;
    (*fail.samplers)[0].value = 120;
    Image red = renderPlan(lab.scene, initialLayout(lab.scene), options, fail);
    EXPECT_GT(countPixels(red, isRed), 100);
    EXPECT_EQ(countPixels(red, isGreen), 0);

    test::TempDir dir;
    writePng(image, dir.path() / "plan.png");
    EXPECT_EQ(readPng(dir.path() / "plan.png").pixels(), image.pixels());
}

TEST(Plan, WorkPlaneUnderAUniformSkyIsPiL) {
    test::SceneLab lab(test::SceneBuilder().uniformSky(2000, 0).build());
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
    test::SceneLab lab(roomWithTable());
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

TEST(Plan, CellsInsideFurnitureAreNoPartOfTheWorkPlane) {
    // A 0.6 x 0.6 x 1.6 m cabinet at (6, 1): four cell centres of a 0.5 m grid are inside
    // it; the table (0.75 m high) is under the 0.8 m plane, so its cells are free.
    Scene scene = test::SceneBuilder()
                      .material("wall", test::diffuse(0.5))
                      .material("wood", test::diffuse(0.4))
                      .room({0, 0, 0}, {8, 4, 3}, "wall", "wall", "wall")
                      .emitter("lamp", rectEmitter({4, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 6000)
                      .entity("table", {1.5, 2, 0}).preset("table", "wood", Vec3(1.0, 0.8, 0.75)).end()
                      .entity("cabinet", {6, 1, 0}).part({0.6, 0.6, 1.6}, "wood").end()
                      .build();
    test::SceneLab lab(scene);
    IlluminanceGrid grid = measureWorkPlane(*lab.tracer, lab.scene.room()->box, 0.8, 0.5, 4, 1);
    std::vector<char> free = freeCells(lab.scene, initialLayout(lab.scene), grid);
    ASSERT_EQ(free.size(), grid.values.size());
    EXPECT_EQ(std::count(free.begin(), free.end(), 0), 4);
    for (auto [i, j] : {std::pair{11, 1}, {12, 1}, {11, 2}, {12, 2}}) EXPECT_EQ(free[size_t(j * grid.nx + i)], 0) << i << j;
    EXPECT_EQ(free[size_t(4 * grid.nx + 3)], 1);  // over the table
    // Moved, the cabinet takes its cells with it.
    Layout moved = initialLayout(lab.scene);
    moved.placements[1].position = {2, 1, 0};
    std::vector<char> after = freeCells(lab.scene, moved, grid);
    EXPECT_EQ(after[size_t(2 * grid.nx + 12)], 1);
    EXPECT_EQ(after[size_t(2 * grid.nx + 4)], 0);
}

TEST(Plan, WorkPlaneStatisticsAreOverTheFreeCells) {
    IlluminanceGrid g;
    g.nx = 2, g.ny = 2;
    g.values = {100, 200, 300, 5};
    g.errors = {1, 1, 1, 1};
    PointStatistics all = workPlaneStatistics(g);
    EXPECT_NEAR(all.mean.value, 151.25, 1e-9);
    EXPECT_EQ(all.min.value, 5);
    PointStatistics st = workPlaneStatistics(g, {1, 1, 1, 0});
    EXPECT_NEAR(st.mean.value, 200, 1e-9);
    EXPECT_EQ(st.min.value, 100);
    EXPECT_EQ(st.max.value, 300);
    EXPECT_NEAR(st.u0.value, 0.5, 1e-12);
}

TEST(Plan, ScaleCentresOnTheTargetsAndATableListsTheWorkPlanes) {
    test::SceneLab lab(roomWithTable());
    // The reading sampler asks at least 300 lx: 30 to 30000 lx, 300 a third of the way.
    FalseColor f = planFalseColor(lab.scene, {});
    EXPECT_NEAR(f.minValue(), 30, 1e-9);
    EXPECT_NEAR(f.fraction(300), 1.0 / 3, 1e-12);
    ASSERT_TRUE(f.band);
    // Without illuminance targets: a log scale of the values.
    Scene bare = test::SceneBuilder().material("wall", test::diffuse(0.5)).room({0, 0, 0}, {4, 4, 3}, "wall", "wall", "wall").build();
    FalseColor automatic = planFalseColor(bare, {100, 200, 300});
    EXPECT_FALSE(automatic.band);
    EXPECT_EQ(automatic.scale, ColorScale::Log);

    PlanData data;
    data.workPlane = measureWorkPlane(*lab.tracer, lab.scene.room()->box, 0.8, 0.5, 4, 1);
    Image mapOnly = renderPlan(lab.scene, initialLayout(lab.scene), {}, data);
    data.samplers = std::vector<SamplerResult>(1);
    (*data.samplers)[0].value = 450;
    (*data.samplers)[0].points = {440, 460, 450, 450};
    (*data.samplers)[0].pointErrors = {1, 1, 1, 1};
    Image withTable = renderPlan(lab.scene, initialLayout(lab.scene), {}, data);
    // A header and one row (9 + 3 px each) and 8 px of space.
    EXPECT_EQ(withTable.height(), mapOnly.height() + 2 * (kLineAdvance + 3) + 8);
    // The row is green: the sampler meets its target.
    int green = 0;
    for (int y = mapOnly.height(); y < withTable.height(); ++y)
        for (int x = 0; x < withTable.width(); ++x) green += withTable.at(x, y).g > 100 && withTable.at(x, y).r < 60;
    EXPECT_GT(green, 20);
    // Contours can be turned off; on, they draw dark lines over the map.
    PlanOptions noLines;
    noLines.contours = false;
    Image plain = renderPlan(lab.scene, initialLayout(lab.scene), noLines, data);
    int changed = 0, darker = 0;
    for (int y = 0; y < plain.height(); ++y)
        for (int x = 0; x < plain.width(); ++x) {
            Rgb a = plain.at(x, y), b = withTable.at(x, y);
            if (a == b) continue;
            ++changed;
            darker += int(b.r) + b.g + b.b < int(a.r) + a.g + a.b;
        }
    EXPECT_GT(changed, 100);
    EXPECT_GT(darker, changed / 2);  // dark lines (their value labels sit on light boxes)
    // The target band is marked beside the legend: without a band, that mark is gone.
    PlanOptions noBand;
    noBand.colors = planFalseColor(lab.scene, {});
    noBand.colors->band.reset();
    Image unmarked = renderPlan(lab.scene, initialLayout(lab.scene), noBand, data);
    const int legendX = 8 * 80 + 50 + int(std::max(4.0, 0.12 * 80)) + 62;  // the bar's left edge
    int mark = 0;
    for (int y = 0; y < withTable.height(); ++y)
        for (int x = legendX - 50; x < legendX; ++x) mark += withTable.at(x, y) != unmarked.at(x, y);
    EXPECT_GT(mark, 40);
    // The legend's bar (210 px for a 4 m deep room at 80 px/m) holds the ramp's ends.
    const int barHeight = 4 * 80 - 110;
    bool top = false, bottom = false;
    for (int y = 0; y < withTable.height(); ++y) {
        top = top || withTable.at(legendX + 8, y) == falseColorRamp(1 - 0.5 / barHeight);
        bottom = bottom || withTable.at(legendX + 8, y) == falseColorRamp(0.5 / barHeight);
    }
    EXPECT_TRUE(top);
    EXPECT_TRUE(bottom);
}

// Six chairs 0.35 m apart, each with a seat sampler, a cabinet and a desk among them,
// and an isolux map: every label drawn lies inside the picture and over no other, and
// the samplers' labels (with their values) are all drawn.
TEST(Plan, LabelsOfEntitiesCloseTogetherDoNotOverlap) {
    test::SceneBuilder builder;
    builder.material("wall", test::diffuse(0.5))
        .material("wood", test::diffuse(0.4))
        .room({0, 0, 0}, {4, 3, 3}, "wall", "wall", "wall")
        .emitter("lamp", rectEmitter({2, 1.5, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 6000)
        .box("cabinet", {1.9, 1.0, 0}, {2.3, 1.4, 1.6}, "wood");
    for (int k = 0; k < 6; ++k) {
        const std::string name = "chair " + std::to_string(k + 1);
        builder.entity(name, {1.2 + 0.35 * (k % 3), 1.1 + 0.35 * (k / 3), 0})
            .region({0.5, 0.5}, {3.5, 2.5}, {0})
            .preset("chair", "wood")
            .sampler(name + " seat", planarSampler({0, 0, 0.46}, {0, 0, 1}, {0, 1, 0}, {0.3, 0.3}, {2, 2}), 200, kInf, 50)
            .end();
    }
    builder.entity("desk", {1.6, 1.6, 0}).region({0.5, 0.5}, {3.5, 2.5}, {0}).preset("desk", "wood").end();
    test::SceneLab lab(builder.build());
    PlanData data;
    data.samplers = std::vector<SamplerResult>(lab.scene.samplers.size());
    for (size_t k = 0; k < data.samplers->size(); ++k) (*data.samplers)[k].value = 150 + 40.0 * double(k);
    data.workPlane = measureWorkPlane(*lab.tracer, lab.scene.room()->box, 0.8, 0.25, 4, 1);
    std::vector<PlanLabel> labels;
    Image image = renderPlan(lab.scene, initialLayout(lab.scene), {}, data, &labels);

    int samplerLabels = 0;
    for (const PlanLabel& l : labels) samplerLabels += l.text.find(" seat ") != std::string::npos;
    EXPECT_EQ(samplerLabels, 6);
    EXPECT_GE(labels.size(), 8u);
    for (size_t a = 0; a < labels.size(); ++a) {
        const PlanLabel& p = labels[a];
        EXPECT_TRUE(p.x0 >= 0 && p.y0 >= 0 && p.x1 <= image.width() && p.y1 <= image.height()) << p.text;
        // Legible: a line at least 12 px high.
        EXPECT_GE(p.y1 - p.y0, 12) << p.text;
        for (size_t b = a + 1; b < labels.size(); ++b) {
            const PlanLabel& q = labels[b];
            const bool overlap = p.x0 < q.x1 && q.x0 < p.x1 && p.y0 < q.y1 && q.y0 < p.y1;
            EXPECT_FALSE(overlap) << "\"" << p.text << "\" [" << p.x0 << ", " << p.y0 << ", " << p.x1 << ", " << p.y1
                                  << "] and \"" << q.text << "\" [" << q.x0 << ", " << q.y0 << ", " << q.x1 << ", "
                                  << q.y1 << "]";
        }
    }
}

}  // namespace
}  // namespace luxplan
