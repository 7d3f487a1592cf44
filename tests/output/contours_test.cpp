// Marching squares against fields whose isolines are known: exact on linear fields
// (linear interpolation along edges is exact there), within the grid's resolution on
// a circle, and none through masked samples.
#include <gtest/gtest.h>

#include <luxplan/output/contours.h>

namespace luxplan {
namespace {

std::vector<double> field(int nx, int ny, double (*f)(double, double)) {
    std::vector<double> v;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) v.push_back(f(i, j));
    return v;
}

TEST(Isolines, OfALinearFieldLieExactlyOnTheLevelLine) {
    const int nx = 9, ny = 7;
    std::vector<double> v = field(nx, ny, [](double x, double y) { return 100 * x + 20 * y; });
    for (double level : {150.0, 333.0, 612.5}) {
        std::vector<ContourSegment> segments = isolines(v, nx, ny, level);
        ASSERT_FALSE(segments.empty()) << level;
        for (const ContourSegment& s : segments)
            for (Vec2 p : {s.a, s.b}) EXPECT_NEAR(100 * p.x + 20 * p.y, level, 1e-9) << level;
        // The line 100 x + 20 y = level crosses every row once: one segment per row of squares it passes.
        int rows = 0;
        for (int j = 0; j + 1 < ny; ++j) {
            double x0 = (level - 20 * j) / 100, x1 = (level - 20 * (j + 1)) / 100;
            if (std::max(x0, x1) > 0 && std::min(x0, x1) < nx - 1) ++rows;
        }
        EXPECT_GE(int(segments.size()), rows) << level;
    }
    // Outside the field's range: nothing.
    EXPECT_TRUE(isolines(v, nx, ny, -1).empty());
    EXPECT_TRUE(isolines(v, nx, ny, 1e6).empty());
}

TEST(Isolines, OfACircularFieldFollowTheCircle) {
    const int n = 41;
    std::vector<double> v = field(n, n, [](double x, double y) { return std::hypot(x - 20, y - 20); });
    std::vector<ContourSegment> segments = isolines(v, n, n, 12.5);
    double length = 0;
    for (const ContourSegment& s : segments) {
        for (Vec2 p : {s.a, s.b}) EXPECT_NEAR(std::hypot(p.x - 20, p.y - 20), 12.5, 0.05);
        length += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
    }
    // A closed polygon inscribed in the circle: its length just under 2 pi r.
    EXPECT_NEAR(length, 2 * kPi * 12.5, 0.01 * 2 * kPi * 12.5);
}

TEST(Isolines, MaskedSamplesAndSaddlesAreHandled) {
    // x + y with the centre sample masked: no segment in the four squares around it.
    const int n = 5;
    std::vector<double> v = field(n, n, [](double x, double y) { return x + y; });
    std::vector<char> valid(v.size(), 1);
    valid[2 * n + 2] = 0;
    for (const ContourSegment& s : isolines(v, n, n, 4.0, valid))
        for (Vec2 p : {s.a, s.b}) EXPECT_FALSE(std::abs(p.x - 2) < 1 - 1e-9 && std::abs(p.y - 2) < 1 - 1e-9);
    EXPECT_LT(isolines(v, n, n, 4.0, valid).size(), isolines(v, n, n, 4.0).size());
    // A saddle: 1 0 / 0 1. Centre mean 0.5 >= 0.4: the high corners connect, the
    // segments cut off the two low corners.
    std::vector<double> saddle{1, 0, 0, 1};
    std::vector<ContourSegment> s = isolines(saddle, 2, 2, 0.4);
    ASSERT_EQ(s.size(), 2u);
    for (const ContourSegment& seg : s) {
        Vec2 mid = (seg.a + seg.b) * 0.5;
        // Around corner (1, 0) or (0, 1): the low ones.
        EXPECT_TRUE(std::hypot(mid.x - 1, mid.y) < 0.5 || std::hypot(mid.x, mid.y - 1) < 0.5) << mid.x << " " << mid.y;
    }
    // Level 0.6 > centre: the low corners connect, the high corners are cut off.
    for (const ContourSegment& seg : isolines(saddle, 2, 2, 0.6)) {
        Vec2 mid = (seg.a + seg.b) * 0.5;
        EXPECT_TRUE(std::hypot(mid.x, mid.y) < 0.5 || std::hypot(mid.x - 1, mid.y - 1) < 0.5) << mid.x << " " << mid.y;
    }
    // Too small a grid, or NaN samples: nothing, no crash.
    EXPECT_TRUE(isolines({1.0}, 1, 1, 0.5).empty());
    EXPECT_TRUE(isolines({std::nan(""), 0, 0, 1}, 2, 2, 0.5).empty());
}

}  // namespace
}  // namespace luxplan
