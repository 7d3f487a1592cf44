// The light map of the guided move: which entities it maps, its proposal density (a
// density over the regions' measure, integrating to 1), draws that follow it (chi-square),
// and the polish's snap move.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/light_map.h>
#include <luxplan/optimizer/moves.h>
#include <luxplan/optimizer/placement.h>
#include "support/chi2.h"
#include "support/scene_builder.h"

namespace luxplan {
namespace {

std::shared_ptr<const SamplerType> pad() { return planarSampler({0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2}); }

// Two tables alike (one map), a lamp without samplers (none), and a shelf with a sampler
// of its own (a map of its own); the tables' region is 4 x 2 m with two rotations.
Scene mapScene() {
    test::SceneBuilder b;
    b.material("m", test::diffuse(0.5)).lightingWeight(0.5);
    for (const char* name : {"t1", "t2"})
        b.entity(name, {1, 1, 0}).region({0, 0}, {4, 2}, {0, 90}).part({1, 1, 0.7}, "m").sampler("s", pad(), 0, 100, 100).end();
    b.entity("lamp", {2, 2, 0}).region({0, 0}, {4, 2}).part({0.3, 0.3, 1.5}, "m").end();
    b.entity("shelf", {0.5, 0, 0}).region({0, 0}, {4, 0}, {0}).part({1, 0.3, 1.5}, "m").sampler("s", pad(), 0, 100, 100).end();
    return b.build();
}

SamplerResult valued(double v) {
    SamplerResult r;
    r.value = v;
    return r;
}

TEST(LightMap, MapsTheEntitiesThatCarrySamplers) {
    const Scene s = mapScene();
    LightMap map(s, {0, 1, 2, 3});
    EXPECT_TRUE(map.covers(s.findEntity("t1")));
    EXPECT_TRUE(map.covers(s.findEntity("t2")));
    EXPECT_FALSE(map.covers(s.findEntity("lamp")));
    EXPECT_TRUE(map.covers(s.findEntity("shelf")));
    // What one table saw, the other knows (they are interchangeable).
    Layout l = initialLayout(s);
    l.placements[0].position = {0.2, 0.2, 0};
    map.observe(l, {valued(300), valued(50), valued(50)});
    Placement p = l.placements[0];
    EXPECT_NEAR(map.penaltyAt(s.findEntity("t2"), p), 2.0, 1e-12);  // 200 lx above 100, tolerance 100
    EXPECT_TRUE(std::isnan(map.penaltyAt(s.findEntity("t2"), {0, {3.9, 1.9, 0}, 90})));
}

TEST(LightMap, ItsDensityIntegratesToOneOverTheRegions) {
    const Scene s = mapScene();
    LightMap map(s, {0, 1, 2, 3});
    Layout l = initialLayout(s);
    Rng rng(3);
    for (int i = 0; i < 200; ++i) {
        l.placements[0] = samplePlacement(s.entities[0], 0, rng);
        map.observe(l, {valued(400 * rng.uniform()), valued(0), valued(0)});
    }
    // Sum over a fine grid of (x, y, rotation): each point stands for its share of the measure.
    const int n = 200;
    double integral = 0;
    for (double rot : {0.0, 90.0})
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n / 2; ++j) {
                Placement p{0, {(i + 0.5) * 4.0 / n, (j + 0.5) * 2.0 / (n / 2), 0}, rot};
                integral += std::exp(map.logDensity(0, p)) * (4.0 / n) * (2.0 / (n / 2));
            }
    EXPECT_NEAR(integral, 1.0, 1e-9);
}

TEST(LightMap, DrawsFollowItsDensity) {
    const Scene s = mapScene();
    LightMapOptions o;
    o.cellMetres = 1.0;
    LightMap map(s, {0, 1, 2, 3}, o);
    Layout l = initialLayout(s);
    // The left half read 150 lx (penalty 0.5), the right half 50 lx (0): the right half
    // is drawn e^5 times as often, less the uniform share.
    for (double x : {0.5, 1.5, 2.5, 3.5})
        for (double y : {0.5, 1.5})
            for (double rot : {0.0, 90.0}) {
                l.placements[0] = {0, {x, y, 0}, rot};
                // (t2 stands still at (1, 1) on the left, and reads the left's 150 lx)
                map.observe(l, {valued(x < 2 ? 150 : 50), valued(150), valued(0)});
            }
    Rng rng(7);
    std::vector<double> observed(2, 0);
    const int draws = 40000;
    for (int i = 0; i < draws; ++i) {
        Placement p = l.placements[0];
        map.propose(0, p, rng);
        observed[p.position.x < 2 ? 0 : 1] += 1;
    }
    const double wLeft = std::exp(-0.5 / o.temperature), wRight = 1.0;
    const double pLeft = o.uniformShare * 0.5 + (1 - o.uniformShare) * wLeft / (wLeft + wRight);
    auto r = test::chi2Test(observed, {draws * pLeft, draws * (1 - pLeft)});
    EXPECT_GT(r.pValue, 1e-3) << r.table;
}

TEST(Snap, TurnsToTheNearestQuarterOfTheRoom) {
    test::SceneBuilder b;
    b.material("m", test::diffuse(0.5)).entity("desk", {1, 1, 0}, 90).region({0, 0}, {2, 2}, {0, 90, 180, 270}).part({1, 0.6, 0.75}, "m")
        .entity("monitor", {0, 0.1, 0.75}, 7).rangeRegion({-0.3, 0}, {0.3, 0.2}, -30, 30).part({0.5, 0.1, 0.4}, "m").end()
        .end();
    const Scene s = b.build();
    const Entity& monitor = s.entities[size_t(s.findEntity("desk.monitor"))];
    Placement p{0, {0, 0.1, 0.75}, 7};
    ASSERT_TRUE(snapMove(monitor, p, 90));  // world 97 -> 90: its own rotation 0
    EXPECT_NEAR(p.rotationDeg, 0, 1e-12);
    EXPECT_FALSE(snapMove(monitor, p, 90));  // already on a quarter turn
    p.rotationDeg = 29;
    EXPECT_FALSE(snapMove(monitor, p, 90 + 45));  // world 164 -> 180 needs 45, outside [-30, 30]
    p.rotationDeg = 20;
    EXPECT_FALSE(snapMove(monitor, p, 250));  // world 270 already
    p.rotationDeg = 21;
    ASSERT_TRUE(snapMove(monitor, p, 250));
    EXPECT_NEAR(p.rotationDeg, 20, 1e-12);
}

}  // namespace
}  // namespace luxplan
