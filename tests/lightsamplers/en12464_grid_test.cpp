// EN 12464-1's calculation grid (the planar type's "grid": "en12464"): cells of at
// most p = 0.2 * 5^log10(d) m, d the longer side, p at most 10 m, and ceil(side / p)
// cells per side with a point at each centre.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {
namespace {

TEST(En12464Grid, TheWorkedExampleFiveByFourMetres) {
    // d = 5 m: p = 0.2 * 5^0.69897 = 0.6160 m; 5 / p = 8.12 -> 9, 4 / p = 6.49 -> 7.
    EXPECT_NEAR(en12464Spacing(5), 0.6160, 5e-5);
    EXPECT_EQ(en12464Grid({5, 4}), (std::array<int, 2>{9, 7}));
    EXPECT_EQ(en12464Grid({4, 5}), (std::array<int, 2>{7, 9}));  // d is the longer side either way
}

TEST(En12464Grid, SpacingAtPowersOfTenAndItsCap) {
    EXPECT_NEAR(en12464Spacing(1), 0.2, 1e-15);
    EXPECT_NEAR(en12464Spacing(10), 1, 1e-15);
    EXPECT_NEAR(en12464Spacing(100), 5, 1e-13);
    // p reaches 10 m at d = 10^(log5 50) = 270 m and stays there.
    EXPECT_EQ(en12464Spacing(1000), 10);
    EXPECT_NEAR(en12464Spacing(269), 0.2 * std::pow(5, std::log10(269.0)), 1e-12);
    EXPECT_LT(en12464Spacing(269), 10);
}

TEST(En12464Grid, WholeCellsGainNoPointFromRounding) {
    EXPECT_EQ(en12464Grid({1, 1}), (std::array<int, 2>{5, 5}));        // p = 0.2 m
    EXPECT_EQ(en12464Grid({10, 3}), (std::array<int, 2>{10, 3}));      // p = 1 m
    EXPECT_EQ(en12464Grid({100, 100}), (std::array<int, 2>{20, 20}));  // p = 5 m
    EXPECT_EQ(en12464Grid({1000, 20}), (std::array<int, 2>{100, 2}));  // p = 10 m
    EXPECT_EQ(en12464Grid({0.6, 0.01}), (std::array<int, 2>{5, 1}));   // p = 0.14 m; at least one point a side
}

TEST(En12464Grid, PointsAtTheCentresOfEqualCells) {
    const Vec2 size(5, 4);
    const auto grid = en12464Grid(size);
    const auto placed = planarSampler({2.5, 2, 0.8}, {0, 0, 1}, {0, 1, 0}, size, grid)->place(Transform());
    const std::vector<Vec3> points = placed->drawing().dots;
    ASSERT_EQ(points.size(), 63u);
    // Row by row, x fastest: cells of 5/9 x 4/7 m from the corner (0, 0).
    EXPECT_NEAR(points[0].x, 2.5 / 9, 1e-12);
    EXPECT_NEAR(points[0].y, 2.0 / 7, 1e-12);
    EXPECT_NEAR(points[8].x, 5 - 2.5 / 9, 1e-12);
    EXPECT_NEAR(points[62].y, 4 - 2.0 / 7, 1e-12);
    EXPECT_NEAR(points[31].x, 2.5, 1e-12);  // the middle point of an odd grid
    EXPECT_NEAR(points[31].y, 2, 1e-12);
}

}  // namespace
}  // namespace luxplan
