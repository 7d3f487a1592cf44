// The sunlit patches as a light (pathtracer/sun_patches.h): the beam points land with
// the density the strategy claims (chi-square). The estimates it gives are tested in
// lightsamplers/sun_patches_estimate_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/core/warp.h>
#include <luxplan/pathtracer/sun_patches.h>
#include <luxplan/rt/embree_scene.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"
#include "support/two_window_room.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::twoWindowRoom;

TEST(SunPatches, BeamPointsLandWithTheDensityTheyClaim) {
    const Scene scene = twoWindowRoom();
    const SunPatches patches(scene, true);
    ASSERT_TRUE(patches.active());
    // The sun south-east and above: both windows face it.
    const Vec3 ws = normalize(Vec3(0.4, -0.7, 0.6));
    EXPECT_NEAR(patches.projectedArea(ws), 2.0 * 0.7 / length(Vec3(0.4, -0.7, 0.6)) + 1.8 * 0.4 / length(Vec3(0.4, -0.7, 0.6)),
                1e-12);
    EXPECT_EQ(patches.projectedArea(-ws), 0.0);  // the sun behind the windows lights nothing

    // Where the beams land in the empty room: the room box's exit point along -ws. Bins:
    // 0.5 m cells of the floor, then the four walls and the ceiling one bin each.
    const int nx = 12, ny = 8, floorBins = nx * ny;
    auto binOf = [&](const Vec3& y) {
        if (y.z < 1e-9) return std::min(int(y.x / 0.5), nx - 1) * ny + std::min(int(y.y / 0.5), ny - 1);
        if (y.z > 3 - 1e-9) return floorBins + 4;
        if (y.y < 1e-9) return floorBins + 0;
        if (y.y > 4 - 1e-9) return floorBins + 1;
        if (y.x < 1e-9) return floorBins + 2;
        return floorBins + 3;
    };
    const int n = 100000;
    std::vector<double> observed(size_t(floorBins + 5), 0.0);
    Rng rng(7);
    for (int i = 0; i < n; ++i) {
        Vec3 entry;
        ASSERT_TRUE(patches.sampleEntry(ws, {rng.uniform(), rng.uniform()}, entry));
        observed[size_t(binOf(patches.beamEnd(entry, -ws)))] += 1;
    }
    // Expected: n times the density integrated over each bin (midpoint quadrature; the
    // beams' edges cross cells, so the quadrature is fine enough to be exact here).
    std::vector<double> expected(observed.size(), 0.0);
    auto integrate = [&](Vec3 corner, Vec3 u, Vec3 v, Vec3 normal, int bin, int m) {
        const double dA = length(u) * length(v) / (double(m) * m);
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                const Vec3 y = corner + u * ((i + 0.5) / m) + v * ((j + 0.5) / m);
                expected[size_t(bin < 0 ? binOf(y) : bin)] += n * patches.density(y, normal, ws) * dA;
            }
    };
    integrate({0, 0, 0}, {6, 0, 0}, {0, 4, 0}, {0, 0, 1}, -1, 2400);
    integrate({0, 0, 0}, {6, 0, 0}, {0, 0, 3}, {0, 1, 0}, floorBins + 0, 600);
    integrate({0, 4, 0}, {6, 0, 0}, {0, 0, 3}, {0, 1, 0}, floorBins + 1, 600);
    integrate({0, 0, 0}, {0, 4, 0}, {0, 0, 3}, {1, 0, 0}, floorBins + 2, 600);
    integrate({6, 0, 0}, {0, 4, 0}, {0, 0, 3}, {1, 0, 0}, floorBins + 3, 600);
    integrate({0, 0, 3}, {6, 0, 0}, {0, 4, 0}, {0, 0, 1}, floorBins + 4, 600);
    double total = 0;
    for (double e : expected) total += e;
    EXPECT_NEAR(total / n, 1.0, 2e-3);  // every beam lands somewhere in the room

    // Bins expected to hold fewer than 20 are pooled.
    double chi2 = 0, pooledE = 0, pooledO = 0;
    int dof = -1;
    for (size_t b = 0; b < expected.size(); ++b) {
        if (expected[b] < 20) {
            pooledE += expected[b], pooledO += observed[b];
            continue;
        }
        chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
        ++dof;
    }
    if (pooledE > 0) chi2 += (pooledO - pooledE) * (pooledO - pooledE) / pooledE, ++dof;
    else EXPECT_EQ(pooledO, 0.0);
    ASSERT_GT(dof, 20);
    // The 0.999 quantile of chi-square is below dof + 4.5 sqrt(dof) for these dof.
    EXPECT_LT(chi2, dof + 4.5 * std::sqrt(2.0 * dof)) << "dof " << dof;
}

TEST(SunPatches, OnlyRoomsWithSunlitEntrancesHaveThem) {
    EXPECT_FALSE(SunPatches(twoWindowRoom(), false).active());
    const Scene closed = SceneBuilder()
                             .material("wall", test::diffuse(0.5))
                             .room({0, 0, 0}, {6, 4, 3}, "wall", "wall", "wall")
                             .window(Wall::South, 1, 2, 1, 1, "wall")
                             .build();
    EXPECT_FALSE(SunPatches(closed, true).active());
    // Outside the room, or on a line that leaves the room through a wall, the strategy
    // makes no point.
    const SunPatches patches(twoWindowRoom(), true);
    const Vec3 ws = normalize(Vec3(0.4, -0.7, 0.6));
    EXPECT_EQ(patches.density({3, -1, 1}, {0, 0, 1}, ws), 0.0);
    EXPECT_EQ(patches.density({0.2, 3.8, 0}, {0, 0, 1}, ws), 0.0);
}

// The sun's shadow rays that must leave through a wall are not traced (the shell is
// static: no move changes their answer). Only from strictly inside the room, so that a
// path that went out of a window still sees the sun from the shell's outer face.
// A sun disk whose every direction the shell blocks from near a vertex draws no sample
// there (path_tracer.cpp): shadesCone must say so only when shadedByShell would for
// every start within the offset and every direction within the cone, and should say
// so for most of a room's points when the sun is low behind a wall.
TEST(SunPatches, AConeIsShadedOnlyWhereEveryRayInItIs) {
    const SunPatches shell(twoWindowRoom(), false);
    Rng rng(11);
    const double offset = 2e-4;
    int shaded = 0, cones = 0;
    for (int k = 0; k < 4000; ++k) {
        // Points anywhere in the room and near its faces, cones from a sun's disk up to
        // 20 degrees wide, pointing anywhere above the horizon.
        Vec3 p(6 * rng.uniform(), 4 * rng.uniform(), 3 * rng.uniform());
        if (k % 4 == 0) p.y = 1e-3 * rng.uniform();  // by the south wall
        const Vec3 axis = sampleUniformHemisphere({rng.uniform(), rng.uniform()});
        const double halfAngle = k % 2 ? 0.0047 : 0.35 * rng.uniform();
        // A shadow ray's own origin, exactly (a floor point's, kRayEpsilon above it), or
        // a point within `offset` of it.
        const bool exact = k % 4 == 1;
        if (exact) p.z = 1e-4;
        const double within = exact ? 0.0 : offset;
        ++cones;
        if (!shell.shadesCone(p, within, axis, halfAngle)) continue;
        ++shaded;
        const Frame frame = Frame::fromNormal(axis);
        for (int j = 0; j < 200; ++j) {
            // Directions inside and on the rim of the cone, from starts in the offset's ball.
            const double cosMax = std::cos(halfAngle);
            Vec3 w = normalize(frame.toWorld(sampleUniformCone({j < 20 ? 1.0 : rng.uniform(), rng.uniform()}, cosMax)));
            const Vec3 q = p + sampleUniformSphere({rng.uniform(), rng.uniform()}) * (within * rng.uniform());
            ASSERT_TRUE(shell.shadedByShell(q, w)) << "p " << p.x << " " << p.y << " " << p.z << ", axis " << axis.x << " "
                                                   << axis.y << " " << axis.z << ", half angle " << halfAngle;
        }
    }
    EXPECT_GT(shaded, cones / 2);  // the windows are small: most cones meet only walls
    // A sun low in the north (the windows face south and east) is behind walls from
    // everywhere; a point by the south window with the sun right behind it is not shaded.
    EXPECT_TRUE(shell.shadesCone({3, 2, 1.5}, offset, normalize(Vec3(-0.1, 1, 0.2)), 0.0047));
    EXPECT_FALSE(shell.shadesCone({2, 0.5, 1.5}, offset, normalize(Vec3(0, -1, 0)), 0.0047));
    EXPECT_FALSE(shell.shadesCone({2, 0.5, 1.5}, offset, normalize(Vec3(0, 1, 0.2)), 0.0047 + kPi));  // too wide to bound
    EXPECT_FALSE(shell.shadesCone({7, 2, 1.5}, offset, normalize(Vec3(0, 1, 0.2)), 0.0047));  // outside the room
}

TEST(SunPatches, TheShellShadesWhatCannotLeaveThroughAnOpening) {
    const SunPatches off(twoWindowRoom(), false);  // works without the strategy too
    const Vec3 ws = normalize(Vec3(0.4, -0.7, 0.6));
    EXPECT_FALSE(off.shadedByShell({2, 1.0, 0.8}, ws));   // out through the south window
    EXPECT_TRUE(off.shadedByShell({2, 3.5, 0.2}, ws));    // into the ceiling
    EXPECT_TRUE(off.shadedByShell({0.3, 0.3, 2.5}, ws));  // into the south wall beside it
    EXPECT_FALSE(off.shadedByShell({2, -1e-4, 2.5}, ws)); // the south wall's outer face
    EXPECT_FALSE(off.shadedByShell({7, 2, 1}, ws));       // outside the room
    EXPECT_TRUE(off.shadedByShell({0.3, 3.9, 0.1}, -ws));  // the sun behind the windows
    // The door (an opaque panel) is shell; a translucent shell lets light through anywhere.
    EXPECT_TRUE(off.shadedByShell({1.5, 1.5, 1}, normalize(Vec3(-1, 0, 0.1))));
    Material translucent = test::diffuse(0.4);
    translucent.type = MaterialType::Translucent;
    translucent.diffuseTransmittance = Vec3(0.2, 0.2, 0.2);
    const Scene paper = SceneBuilder()
                            .material("wall", test::diffuse(0.5))
                            .material("paper", translucent)
                            .room({0, 0, 0}, {6, 4, 3}, "wall", "paper", "wall")
                            .window(Wall::South, 1, 2, 1, 1)
                            .build();
    EXPECT_FALSE(SunPatches(paper, false).shadedByShell({2, 3.5, 0.2}, ws));
    // An invisible room only collides: no shell in the ray-tracing scene.
    Scene invisible = twoWindowRoom();
    for (auto& g : invisible.geometry)
        if (g.room) g.invisible = true;
    EXPECT_FALSE(SunPatches(invisible, false).shadedByShell({2, 3.5, 0.2}, ws));
}

// What it declares shaded, Embree finds blocked (random points and directions).
TEST(SunPatches, WhatTheShellShadesEmbreeFindsBlocked) {
    const Scene scene = twoWindowRoom();
    const EmbreeScene rt(scene, initialLayout(scene));
    const SunPatches patches(scene, false);
    Rng rng(3);
    int shaded = 0, open = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p(rng.uniform() * 6, rng.uniform() * 4, rng.uniform() * 3);
        const double z = rng.uniform(), phi = 2 * kPi * rng.uniform(), r = std::sqrt(1 - z * z);
        const Vec3 w(r * std::cos(phi), r * std::sin(phi), z);
        if (!patches.shadedByShell(p, w)) {
            ++open;
            continue;
        }
        ++shaded;
        EXPECT_TRUE(rt.occluded({p, w, 0, kInf, kOpaqueMask})) << p.x << "," << p.y << "," << p.z;
    }
    EXPECT_GT(shaded, 10000);
    EXPECT_GT(open, 500);
}

}  // namespace
}  // namespace luxplan
