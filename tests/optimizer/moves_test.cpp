// The mutations of Section 6: every move keeps layouts inside their regions, and
// translation, rotation, swap and jump do what the paper specifies.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/optimizer/moves.h>
#include <luxplan/optimizer/placement.h>
#include "support/chi2.h"
#include "support/scene_builder.h"

namespace luxplan {
namespace {

// A table group on three regions (quarter turns, a full turn, an interval) with two
// chairs on two local regions each and a fixed top, a shelf on two walls, a lamp
// on a strip (no rotations).
Scene roomScene() {
    return test::SceneBuilder()
        .material("m", test::diffuse(0.5))
        .entity("table", {1, 1, 0})
        .region({0.5, 0.5}, {2.5, 2.5}, {0, 90, 180, 270})
        .rangeRegion({4, 1}, {5, 1.5}, 0, 360)
        .rangeRegion({3, 3}, {3, 4}, -30, 30)
        .entity("c1", {0.5, 0, 0}, 90).region({0.4, -0.2}, {0.6, 0.2}, {90, 270}).region({-0.6, -0.2}, {-0.4, 0.2}, {270}).end()
        .entity("c2", {-0.5, 0, 0}, 270).region({-0.6, -0.2}, {-0.4, 0.2}, {270, 90}).rangeRegion({0.4, -0.2}, {0.6, 0.2}, 80, 100).end()
        .entity("top").part({1, 0.6, 0.05}, "m", Vec3(0, 0, 0.7)).end()
        .end()
        .entity("shelf", {0, 2, 0}, 90).region({0, 1}, {0, 3}, {90}).region({6, 1}, {6, 3}, {270}).end()
        .entity("lamp", {3, 0.5, 0}).region({2, 0.2}, {4, 0.8}).end()
        .build();
}

// p and q on each other's regions, r on p's first only.
Scene swapScene() {
    return test::SceneBuilder()
        .entity("p", {0.5, 0.5, 0}, 90).region({0, 0}, {1, 1}, {0, 90}).region({3, 0}, {4, 1}, {0, 90}).end()
        .entity("q", {3.5, 0.5, 0}).region({3, 0}, {4, 1}, {0, 90}).region({0, 0}, {1, 1}, {0, 90}).end()
        .entity("r", {0.2, 0.2, 0}).region({0, 0}, {1, 1}, {0, 90}).end()
        .build();
}

std::vector<int> movable(const Scene& s) {
    std::vector<int> out;
    for (size_t i = 0; i < s.entities.size(); ++i)
        if (s.entities[i].movable()) out.push_back(int(i));
    return out;
}

void expectInside(const Scene& s, const Layout& l) {
    for (int e : movable(s)) {
        const Placement& p = l.placements[e];
        ASSERT_GE(p.region, 0) << s.entities[e].path;
        ASSERT_TRUE(regionContains(s.entities[e].regions[p.region], {p.position.x, p.position.y}, p.rotationDeg))
            << s.entities[e].path << " at " << p.position.x << ", " << p.position.y << ", " << p.rotationDeg
            << " region " << p.region;
    }
}

TEST(Moves, EveryMoveKeepsTheLayoutInsideItsRegions) {
    Scene s = roomScene();
    Layout layout = initialLayout(s);
    expectInside(s, layout);
    MoveSet moves(s, movable(s));
    EXPECT_EQ(moves.types().size(), 4u);
    Rng rng(hashValues({11}));
    std::array<int, kMoveTypeCount> valid{};
    for (int i = 0; i < 20000; ++i) {
        Layout proposed = layout;
        Proposal p = moves.propose(proposed, rng);
        if (!p.valid) {
            // An invalid proposal leaves the state alone (the chain stays).
            continue;
        }
        ++valid[int(p.type)];
        expectInside(s, proposed);
        for (size_t e = 0; e < s.entities.size(); ++e)
            if (int(e) != p.entity && int(e) != p.partner) {
                ASSERT_EQ(proposed.placements[e].position, layout.placements[e].position);
            }
        layout = proposed;
    }
    for (MoveType t : moves.types()) EXPECT_GT(valid[int(t)], 100) << moveName(t);
    EXPECT_EQ(valid[int(MoveType::Snap)], 0);  // the polish's move only
}

TEST(Moves, ApplicabilityDependsOnRegionsOnly) {
    Scene s = roomScene();
    MoveSet moves(s, movable(s));
    int table = s.findEntity("table"), shelf = s.findEntity("shelf"), lamp = s.findEntity("lamp");
    int c1 = s.findEntity("table.c1"), c2 = s.findEntity("table.c2");
    auto has = [&](MoveType t, int e) {
        const auto& c = moves.candidates(t);
        return std::find(c.begin(), c.end(), e) != c.end();
    };
    EXPECT_TRUE(has(MoveType::Translate, lamp));
    EXPECT_FALSE(has(MoveType::Rotate, lamp));  // keeps its initial rotation
    EXPECT_FALSE(has(MoveType::Rotate, shelf));
    EXPECT_TRUE(has(MoveType::Jump, shelf));
    EXPECT_FALSE(has(MoveType::Jump, lamp));
    EXPECT_TRUE(has(MoveType::Swap, c1));  // siblings
    EXPECT_TRUE(has(MoveType::Swap, c2));
    EXPECT_TRUE(has(MoveType::Swap, table));  // top-level siblings: shelf, lamp
    EXPECT_THROW(MoveSet(s, {s.findEntity("table.top")}), std::invalid_argument);
}

TEST(Moves, TranslationStaysOrRefuses) {
    Entity e;
    Region r;
    r.lo = {0, 0}, r.hi = {1, 2};
    r.rotationsDeg = {0};
    e.regions = {r};
    Rng rng(hashValues({3}));
    int refused = 0;
    for (int i = 0; i < 20000; ++i) {
        Placement p{0, Vec3(0.0, 1.0, 0.3), 0};
        Placement before = p;
        if (!translateMove(e, p, 0.25, rng)) {
            ++refused;
            EXPECT_EQ(p.position, before.position);  // untouched
            continue;
        }
        EXPECT_TRUE(regionContains(r, {p.position.x, p.position.y}, 0));
        EXPECT_EQ(p.position.z, 0.3);
    }
    // On the border half the x draws fall outside and are refused, never redrawn.
    EXPECT_GT(refused, 20000 * 0.4);
    // Rail: a zero extent keeps that coordinate.
    r.lo = {0, 1}, r.hi = {1, 1};
    e.regions = {r};
    Placement p{0, Vec3(0.5, 1, 0), 0};
    for (int i = 0; i < 100; ++i)
        if (translateMove(e, p, 0.25, rng)) {
            EXPECT_EQ(p.position.y, 1);
        }
    r.lo = r.hi = {1, 1};  // a point cannot translate
    e.regions = {r};
    EXPECT_FALSE(translateMove(e, p, 0.25, rng));
}

TEST(Moves, RotationDiscreteIsUniformAmongTheOthers) {
    Entity e;
    Region r;
    r.rotationsDeg = {0, 90, 180, 270};
    e.regions = {r};
    Rng rng(hashValues({5}));
    std::vector<double> counts(4, 0);
    for (int i = 0; i < 30000; ++i) {
        Placement p{0, Vec3(), 90};
        ASSERT_TRUE(rotateMove(e, p, 0.25, rng));
        int k = int(std::lround(p.rotationDeg / 90)) % 4;
        counts[k] += 1;
    }
    EXPECT_EQ(counts[1], 0);
    auto res = test::chi2Test({counts[0], counts[2], counts[3]}, {10000, 10000, 10000});
    EXPECT_GT(res.pValue, 1e-3) << res.table;
    e.regions[0].rotationsDeg = {90};
    Placement p{0, Vec3(), 90};
    EXPECT_FALSE(rotateMove(e, p, 0.25, rng));
}

TEST(Moves, RotationContinuous) {
    Entity e;
    Region r;
    r.continuousRotation = true, r.rotationMinDeg = -30, r.rotationMaxDeg = 30;
    e.regions = {r};
    Rng rng(hashValues({6}));
    int refused = 0;
    for (int i = 0; i < 5000; ++i) {
        Placement p{0, Vec3(), 25};
        if (!rotateMove(e, p, 0.25, rng)) {
            ++refused;
            EXPECT_EQ(p.rotationDeg, 25);
            continue;
        }
        EXPECT_GE(p.rotationDeg, -30);
        EXPECT_LE(p.rotationDeg, 30);
    }
    EXPECT_GT(refused, 0);
    e.regions[0].rotationMinDeg = 0, e.regions[0].rotationMaxDeg = 360;  // full turn: wraps, never refused
    for (int i = 0; i < 5000; ++i) {
        Placement p{0, Vec3(), 350};
        ASSERT_TRUE(rotateMove(e, p, 0.25, rng));
        EXPECT_GE(p.rotationDeg, 0);
        EXPECT_LT(p.rotationDeg, 360);
    }
}

TEST(Moves, SwapExchangesPositionsOnly) {
    Scene s = swapScene();
    Layout l = initialLayout(s);
    Placement p = l.placements[0], q = l.placements[1];
    ASSERT_TRUE(swapMove(s.entities[0], p, s.entities[1], q));
    EXPECT_EQ(p.position, Vec3(3.5, 0.5, 0));
    EXPECT_EQ(q.position, Vec3(0.5, 0.5, 0));
    EXPECT_EQ(p.rotationDeg, 90);  // orientations are kept
    EXPECT_EQ(q.rotationDeg, 0);
    EXPECT_EQ(p.region, 1);  // the region that holds the new position
    EXPECT_EQ(q.region, 1);
    // Swapping back restores the state exactly (the move is an involution).
    ASSERT_TRUE(swapMove(s.entities[0], p, s.entities[1], q));
    EXPECT_EQ(p.position, l.placements[0].position);
    EXPECT_EQ(p.region, l.placements[0].region);
    EXPECT_EQ(q.position, l.placements[1].position);
    EXPECT_EQ(q.region, l.placements[1].region);
    // r has no region at q's position: no swap, nothing changed.
    Placement r = l.placements[2];
    Placement q0 = q, r0 = r;
    EXPECT_FALSE(swapMove(s.entities[2], r, s.entities[1], q));
    EXPECT_EQ(r.position, r0.position);
    EXPECT_EQ(q.position, q0.position);
}

TEST(Moves, JumpGoesToAnotherRegionUniformly) {
    Scene s = roomScene();
    const Entity& table = s.entities[s.findEntity("table")];
    Rng rng(hashValues({8}));
    std::vector<double> counts(3, 0), xCounts(4, 0);
    for (int i = 0; i < 20000; ++i) {
        Placement p{0, Vec3(1, 1, 0), 0};
        double logH = jumpMove(table, p, rng);
        ASSERT_NE(p.region, 0);
        ASSERT_TRUE(regionContains(table.regions[p.region], {p.position.x, p.position.y}, p.rotationDeg));
        counts[p.region] += 1;
        double expected = std::log(regionMeasure(table.regions[p.region]) / regionMeasure(table.regions[0]));
        EXPECT_NEAR(logH, expected, 1e-12);
        if (p.region == 1) xCounts[std::min(3, int((p.position.x - 4) * 4))] += 1;
    }
    auto r = test::chi2Test({counts[1], counts[2]}, {10000, 10000});
    EXPECT_GT(r.pValue, 1e-3) << r.table;
    r = test::chi2Test(xCounts, std::vector<double>(4, counts[1] / 4));
    EXPECT_GT(r.pValue, 1e-3) << r.table;
    // The reverse jump's factor is the inverse.
    Placement p{2, Vec3(3, 3.5, 0), 0};
    Rng other(hashValues({9}));
    double logH = 0;
    do {
        p = {2, Vec3(3, 3.5, 0), 0};
        logH = jumpMove(table, p, other);
    } while (p.region != 0);
    EXPECT_NEAR(logH, std::log(regionMeasure(table.regions[0]) / regionMeasure(table.regions[2])), 1e-12);
}

TEST(Moves, GroupMovesKeepTheGroupTogether) {
    Scene s = roomScene();
    Layout layout = initialLayout(s);
    int table = s.findEntity("table"), c1 = s.findEntity("table.c1"), top = s.findEntity("table.top");
    MoveSet groupLevel(s, {table, s.findEntity("shelf"), s.findEntity("lamp")});
    auto relative = [&](const Layout& l, int child) {
        auto world = worldTransforms(s, l);
        return world[table].inverse() * world[child];
    };
    Transform c1Before = relative(layout, c1), topBefore = relative(layout, top);
    Rng rng(hashValues({10}));
    int tableMoves = 0;
    for (int i = 0; i < 3000; ++i) {
        Layout proposed = layout;
        Proposal p = groupLevel.propose(proposed, rng);
        if (!p.valid) continue;
        tableMoves += p.entity == table || p.partner == table;
        layout = proposed;
        for (int child : {c1, top}) {
            Transform r = relative(layout, child), before = child == c1 ? c1Before : topBefore;
            for (int k = 0; k < 9; ++k) ASSERT_NEAR(r.m[k], before.m[k], 1e-9);
            ASSERT_NEAR(length(r.t - before.t), 0, 1e-9);
            ASSERT_EQ(layout.placements[child].position, initialLayout(s).placements[child].position);
        }
    }
    EXPECT_GT(tableMoves, 300);
}

}  // namespace
}  // namespace luxplan
