// The annual pictures: the temporal map puts each hour's value in its day-by-hour cell
// and leaves the others grey; the annual plan colours each planar point by its share of
// hours in range; writeAnnualPictures writes whole files.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/core/error.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/output/annual_plan.h>
#include <luxplan/output/temporal_map.h>
#include "support/scene_builder.h"
#include "support/temp_files.h"

namespace luxplan {
namespace annual_pictures_test {

DateTime at(int year, int month, int day, int hour, int minute = 30) { return {year, month, day, hour, minute, 0, -360}; }

TEST(TemporalMap, DayOfYear) {
    EXPECT_EQ(dayOfYear(at(2026, 1, 1, 0)), 1);
    EXPECT_EQ(dayOfYear(at(2026, 3, 1, 0)), 60);
    EXPECT_EQ(dayOfYear(at(2024, 3, 1, 0)), 61);
    EXPECT_EQ(dayOfYear(at(2026, 12, 31, 0)), 365);
    EXPECT_EQ(dayOfYear(at(2024, 12, 31, 0)), 366);
}

TEST(TemporalMap, EachHourInItsCellTheRestGrey) {
    AnnualSampler s;
    s.name = "desk";
    s.targetMin = 300, s.targetMax = 500;
    s.values = {400, 5000, std::nan("")};
    const std::vector<DateTime> hours = {at(2026, 1, 1, 12), at(2026, 3, 1, 8), at(2026, 3, 1, 9)};
    TemporalMapOptions o;
    o.unit = "lx";
    TemporalMapFrame f;
    const Image image = renderTemporalMap(s, hours, o, &f);
    EXPECT_EQ(f.days, 365);
    EXPECT_GE(image.width(), f.left + 365 * f.dayWidth);
    const FalseColor colors = temporalMapColors(s);
    ASSERT_TRUE(colors.band.has_value());  // the target band's scale
    // 12:30 fills the 12-13 row of 1 January; 08:30 the 8-9 row of 1 March (day 60).
    EXPECT_EQ(image.at(f.cellX(1), f.cellY(12)), colors.color(400));
    EXPECT_EQ(image.at(f.cellX(60), f.cellY(8)), colors.color(5000));
    EXPECT_NE(colors.color(400), colors.color(5000));
    // A non-finite value and hours not in the series are grey.
    EXPECT_EQ(image.at(f.cellX(60), f.cellY(9)), kUnmeasuredColor);
    EXPECT_EQ(image.at(f.cellX(1), f.cellY(11)), kUnmeasuredColor);
    EXPECT_EQ(image.at(f.cellX(200), f.cellY(3)), kUnmeasuredColor);
    // Hour 0 at the bottom: row 12 above row 8.
    EXPECT_LT(f.cellY(12), f.cellY(8));
}

TEST(TemporalMap, ALeapYearHas366Days) {
    AnnualSampler s;
    s.name = "floor";
    s.values = {100};
    TemporalMapFrame f;
    const Image image = renderTemporalMap(s, {at(2024, 12, 31, 15)}, {}, &f);
    EXPECT_EQ(f.days, 366);
    // No band: a logarithmic scale of the values.
    EXPECT_EQ(image.at(f.cellX(366), f.cellY(15)), temporalMapColors(s).color(100));
}

// A 4 x 3 m room with a world-fixed 2 x 1 m planar sampler of 2 x 1 points at 0.8 m,
// its cells x in [1, 2] and [2, 3], y in [1, 2].
Scene deskRoom() {
    return test::SceneBuilder()
        .material("wall", test::diffuse(0.5))
        .room({0, 0, 0}, {4, 3, 3}, "wall", "wall", "wall")
        .sampler("desk", planarSampler({2, 1.5, 0.8}, {0, 0, 1}, {0, 1, 0}, {2, 1}, {2, 1}), 300, 500)
        .build();
}

// 8 hours of the desk: the first point in range 2 of them, the second covered.
AnnualSeries deskSeries() {
    AnnualSeries series;
    for (int h = 0; h < 8; ++h) series.hours.push_back(at(2026, 6, 1, 8 + h));
    AnnualSampler s;
    s.name = "desk";
    s.type = "planar";
    s.planar = true;
    s.targetMin = 300, s.targetMax = 500;
    s.values = {350, 350, 100, 100, 100, 100, 100, 100};
    s.points = {{350, 350, 100, 100, 100, 100, 100, 100}, {}};
    series.samplers.push_back(s);
    return series;
}

TEST(AnnualPlan, EachPointColouredByItsShareInRange) {
    const Scene scene = deskRoom();
    const Layout layout = initialLayout(scene);
    const AnnualSeries series = deskSeries();
    const PlanCells cells = annualPlanCells(scene, layout, series);
    ASSERT_EQ(cells.quads.size(), 2u);
    EXPECT_DOUBLE_EQ(cells.values[0], 25);
    EXPECT_TRUE(std::isnan(cells.values[1]));
    EXPECT_NEAR(cells.quads[0][0].x, 1, 1e-12);
    EXPECT_NEAR(cells.quads[0][2].x, 2, 1e-12);
    EXPECT_NEAR(cells.quads[0][2].y, 2, 1e-12);
    EXPECT_NEAR(cells.quads[1][2].x, 3, 1e-12);

    PlanOptions options;  // 80 px/m, 50 px margin, 24 px title: world (x, y) at (50 + 80 x, 74 + 80 (3 - y))
    options.title = "annual";
    options.samplerLabels = false;
    const Image image = renderAnnualPlan(scene, layout, series, options);
    auto pixel = [&](double x, double y) { return image.at(int(50 + 80 * x), int(74 + 80 * (3 - y))); };
    EXPECT_EQ(pixel(1.3, 1.3), cells.colors.color(25));
    EXPECT_EQ(pixel(2.3, 1.3), (Rgb{205, 205, 205}));  // covered: hatched grey
    EXPECT_NE(pixel(3.5, 2.5), cells.colors.color(25));  // bare floor
    EXPECT_GT(image.width(), 4 * 80 + 2 * 50);           // room for the legend
}

TEST(AnnualPictures, WrittenWholeIntoTheFolder) {
    const Scene scene = deskRoom();
    AnnualSeries series = deskSeries();
    AnnualSampler eye;
    eye.name = "chair.eye/left";
    eye.type = "directional";
    eye.values.assign(8, 0.2);
    series.samplers.push_back(eye);

    test::TempDir dir;
    const std::filesystem::path folder = dir.path() / "annual" / "pictures";
    std::filesystem::create_directories(folder);
    dir.write("annual/pictures/temporal_map_desk.png", "not a picture");  // replaced whole
    const auto written = writeAnnualPictures(folder, scene, initialLayout(scene), series);
    ASSERT_EQ(written.size(), 3u);
    EXPECT_EQ(written[0], folder / "annual_plan.png");
    EXPECT_EQ(written[1], folder / "temporal_map_desk.png");
    EXPECT_EQ(written[2], folder / "temporal_map_chair.eye_left.png");
    TemporalMapOptions o;
    o.unit = "lx";
    EXPECT_EQ(readPng(written[1]).pixels(), renderTemporalMap(series.samplers[0], series.hours, o).pixels());
    EXPECT_EQ(readPng(written[0]).pixels(), renderAnnualPlan(scene, initialLayout(scene), series).pixels());
    // Nothing else left in the folder (no temporary files).
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(folder)) ++files;
    EXPECT_EQ(files, 3);

    // A folder that cannot be made: an error naming it.
    const std::filesystem::path blocked = dir.write("plain_file", "x") / "sub";
    try {
        writeAnnualPictures(blocked, scene, initialLayout(scene), series);
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(blocked.string()), std::string::npos) << e.what();
    }
}

}  // namespace annual_pictures_test
}  // namespace luxplan
