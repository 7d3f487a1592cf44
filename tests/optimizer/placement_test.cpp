// Placement sampling (paper 5.1): region measures, uniform draws inside a region and
// on the union of regions, immovable entities kept.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/optimizer/placement.h>
#include "support/chi2.h"
#include "support/scene_builder.h"

namespace luxplan {
namespace {

// A table on three regions (quarter turns, an interval, a rail) at 0.2 m above the
// floor, and a stool without regions.
Scene makeScene() {
    return test::SceneBuilder()
        .material("m", test::diffuse(0.5))
        .entity("table", {1, 1, 0.2})
        .region({0, 0}, {2, 1}, {0, 90, 180, 270})
        .rangeRegion({4, 0}, {5, 1}, 0, 90)
        .region({7, 0}, {7, 3}, {0})
        .end()
        .entity("stool", {3, 3, 0}).end()
        .build();
}

TEST(Placement, RegionMeasure) {
    Region r;
    r.lo = {0, 0}, r.hi = {2, 1};
    r.rotationsDeg = {0, 90, 180, 270};
    EXPECT_NEAR(regionMeasure(r), 8, 1e-12);
    r.rotationsDeg = {0, 360, -360};  // one orientation
    EXPECT_NEAR(regionMeasure(r), 2, 1e-12);
    r.continuousRotation = true, r.rotationMinDeg = 0, r.rotationMaxDeg = 90;
    EXPECT_NEAR(regionMeasure(r), 2 * kPi / 2, 1e-12);
    r.rotationMaxDeg = 720;  // at most a full turn
    EXPECT_NEAR(regionMeasure(r), 2 * 2 * kPi, 1e-12);
    r.lo = {1, 1}, r.hi = {1, 4};  // a rail: length 3, counting measure across
    r.rotationMaxDeg = 0;          // an empty span counts 1
    EXPECT_NEAR(regionMeasure(r), 3, 1e-12);
}

TEST(Placement, RotationHelpers) {
    Region r;
    r.continuousRotation = true, r.rotationMinDeg = -30, r.rotationMaxDeg = 30;
    EXPECT_NEAR(normalizeRotation(r, 350), -10, 1e-12);
    EXPECT_NEAR(normalizeRotation(r, 20), 20, 1e-12);
    EXPECT_FALSE(fullTurn(r));
    r.rotationMaxDeg = 330;
    EXPECT_TRUE(fullTurn(r));
    EXPECT_TRUE(sameRotation(-90, 270));
    EXPECT_FALSE(sameRotation(90, 270));
    Region d;
    d.rotationsDeg = {-90, 270, 0, 360, 45};
    std::vector<double> distinct = distinctRotations(d);
    ASSERT_EQ(distinct.size(), 3u);
    EXPECT_EQ(distinct[0], -90);
    EXPECT_EQ(distinct[1], 0);
    EXPECT_EQ(distinct[2], 45);
}

TEST(Placement, UniformOnTheUnionOfRegions) {
    Scene s = makeScene();
    const Entity& table = s.entities[0];
    Rng rng(hashValues({1, 2, 3}));
    const int n = 60000;
    std::vector<double> regionCounts(3, 0), xCounts(10, 0), rotationCounts(4, 0);
    for (int i = 0; i < n; ++i) {
        Placement p = samplePlacement(table, 0.2, rng);
        ASSERT_GE(p.region, 0);
        ASSERT_TRUE(regionContains(table.regions[p.region], {p.position.x, p.position.y}, p.rotationDeg));
        EXPECT_EQ(p.position.z, 0.2);
        regionCounts[p.region] += 1;
        if (p.region == 0) {
            xCounts[std::min(9, int(p.position.x / 2 * 10))] += 1;
            rotationCounts[int(std::lround(p.rotationDeg / 90)) % 4] += 1;
        }
        if (p.region == 1) {
            EXPECT_TRUE(p.rotationDeg >= 0 && p.rotationDeg <= 90);
        }
        if (p.region == 2) {
            EXPECT_EQ(p.position.x, 7);
        }
    }
    // Measures 8, pi/2 and 3: uniform on the union picks regions in that proportion.
    double m[3] = {8, kPi / 2, 3}, total = m[0] + m[1] + m[2];
    std::vector<double> expected = {n * m[0] / total, n * m[1] / total, n * m[2] / total};
    auto r = test::chi2Test(regionCounts, expected);
    EXPECT_GT(r.pValue, 1e-3) << r.table;
    double inFirst = regionCounts[0];
    r = test::chi2Test(xCounts, std::vector<double>(10, inFirst / 10));
    EXPECT_GT(r.pValue, 1e-3) << r.table;
    r = test::chi2Test(rotationCounts, std::vector<double>(4, inFirst / 4));
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

TEST(Placement, SampleLayoutKeepsImmovableEntities) {
    Scene s = makeScene();
    Layout base = initialLayout(s);
    Rng rng(hashValues({4}));
    Layout l = sampleLayout(s, base, rng);
    EXPECT_EQ(l.placements[1].position, base.placements[1].position);
    EXPECT_EQ(l.placements[1].region, -1);
    EXPECT_GE(l.placements[0].region, 0);
    EXPECT_EQ(l.placements[0].position.z, 0.2);
    EXPECT_THROW(samplePlacement(s.entities[1], 0, rng), std::invalid_argument);
}

}  // namespace
}  // namespace luxplan
