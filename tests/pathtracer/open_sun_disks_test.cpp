// The sun disks a vertex may see through a room's openings (pathtracer/open_sun_disks.h):
// a group is closed only where the shell blocks every direction of its disks, a lone
// disk is open exactly where the one-cone test of SunPatches says so, and the choice
// among the open disks follows their probabilities (chi-square). The estimates it gives
// are tested in lightsamplers/open_sun_disks_estimate_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/core/warp.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/daylight/solar_position.h>
#include <luxplan/pathtracer/open_sun_disks.h>
#include "support/chi2.h"
#include "support/scene_builder.h"
#include "support/two_window_room.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::twoWindowRoom;

// `count` suns of a morning, east to south and rising, of unequal weights.
DaylightEnvironment morning(int count) {
    DaylightParams black;
    black.model = SkyModelType::Uniform;
    black.luminanceNits = 0;
    black.sun = false;
    const DaylightEnvironment sky = buildDaylight(black, Site{}, {16, 8, 1, {}});
    std::vector<SunDisk> disks;
    double total = 0;
    for (int k = 0; k < count; ++k) total += 1 + k % 3;
    for (int k = 0; k < count; ++k) {
        const double t = count > 1 ? double(k) / (count - 1) : 0.5;
        SunDisk s;
        s.altitudeDeg = 10 + 40 * t;
        s.azimuthDeg = 95 + 90 * t;
        s.direction = horizonToScene(s.altitudeDeg, s.azimuthDeg, 0);
        s.weight = (1 + k % 3) / total;
        s.normalIlluminanceLx = 60000;
        s.luminance = s.weight * s.normalIlluminanceLx / kSunDiskProjectedSolidAngle;
        disks.push_back(s);
    }
    return DaylightEnvironment(sky.skyMap(), disks, 0.0);
}

constexpr double kEpsilon = 1e-4;  // the path tracer's ray offset

// Points anywhere in the room and on its faces: a surface point with its normal (the
// room's side), or a sensor's point (no normal).
struct Probe {
    Vec3 p;
    std::optional<Vec3> ng;
};
Probe probe(Rng& rng, int k) {
    Probe q{{6 * rng.uniform(), 4 * rng.uniform(), 3 * rng.uniform()}, std::nullopt};
    switch (k % 4) {
    case 0: q.p.z = 0, q.ng = Vec3(0, 0, 1); break;      // the floor
    case 1: q.p.x = 0, q.ng = Vec3(1, 0, 0); break;      // the west wall
    case 2: q.ng = normalize(sampleUniformSphere({rng.uniform(), rng.uniform()})); break;  // furniture
    default: break;                                       // a sensor
    }
    return q;
}

TEST(OpenSunDisks, AGroupIsClosedOnlyWhereEveryRayOfItsDisksIsBlocked) {
    const SunPatches shell(twoWindowRoom(), false);
    for (int count : {7, 100}) {  // a disk per group, and groups of three or four
        const DaylightEnvironment daylight = morning(count);
        const OpenSunDisks disks(&daylight, shell);
        ASSERT_TRUE(disks.active());
        EXPECT_EQ(disks.groupCount(), size_t(std::min(count, 32)));
        Rng rng(5);
        int closed = 0, groups = 0;
        for (int k = 0; k < 3000; ++k) {
            const Probe q = probe(rng, k);
            const OpenSunDisks::Open open = disks.at(q.p, q.ng ? &*q.ng : nullptr, kEpsilon);
            double share = 0;
            for (size_t g = 0; g < disks.groupCount(); ++g) {
                ++groups;
                if (open.all || (open.groups >> g & 1)) continue;
                ++closed;
                // Every direction of every disk of the group, from where a shadow ray
                // along it starts (spawn(): offset along the normal towards it), or
                // from within the offset of a sensor's point, leaves through a wall.
                for (size_t d = 0; d < daylight.sunDisks().size(); ++d) {
                    if (disks.groupOf(d) != g) continue;
                    const Frame frame = Frame::fromNormal(daylight.sunDisks()[d].direction);
                    for (int j = 0; j < 40; ++j) {
                        const Vec3 w = normalize(frame.toWorld(sampleUniformCone({j < 8 ? 1.0 : rng.uniform(), rng.uniform()}, kSunCosHalfAngle)));
                        Vec3 from = q.p + sampleUniformSphere({rng.uniform(), rng.uniform()}) * (kEpsilon * rng.uniform());
                        if (q.ng) from = q.p + *q.ng * (dot(w, *q.ng) >= 0 ? kEpsilon : -kEpsilon);
                        if (q.ng && std::abs(dot(disks.groupAxis(g), *q.ng)) <= disks.groupHalfAngle(g))
                            from = q.p + sampleUniformSphere({rng.uniform(), rng.uniform()}) * (kEpsilon * rng.uniform());
                        ASSERT_TRUE(shell.shadedByShell(from, w)) << "group " << g << " of " << count << " disks, point "
                                                                   << q.p.x << " " << q.p.y << " " << q.p.z;
                    }
                }
            }
            if (!open.all) {
                for (size_t d = 0; d < daylight.sunDisks().size(); ++d)
                    if (open.groups >> disks.groupOf(d) & 1) share += daylight.sunDiskProbability(d);
                EXPECT_NEAR(open.share, share, 1e-12);
            } else {
                EXPECT_EQ(open.share, 1.0);
            }
        }
        // The windows are small: most groups are closed from most places.
        EXPECT_GT(closed, groups / 2) << count << " disks";
    }
}

TEST(OpenSunDisks, ALoneDiskIsOpenWhereTheOneConeTestSaysSo) {
    const SunPatches shell(twoWindowRoom(), false);
    const DaylightEnvironment daylight = morning(7);
    const OpenSunDisks disks(&daylight, shell);
    Rng rng(9);
    const double halfAngle = kSunHalfAngle * (1 + 1e-6) + 1e-9;  // the path tracer's cone round a disk
    int open = 0, cases = 0;
    for (int k = 0; k < 4000; ++k) {
        const Probe q = probe(rng, k);
        const OpenSunDisks::Open o = disks.at(q.p, q.ng ? &*q.ng : nullptr, kEpsilon);
        for (size_t d = 0; d < 7; ++d) {
            const Vec3& axis = daylight.sunDisks()[d].direction;
            Vec3 from = q.p;
            double within = kEpsilon;
            if (q.ng && std::abs(dot(axis, *q.ng)) > halfAngle) from = q.p + *q.ng * (dot(axis, *q.ng) >= 0 ? kEpsilon : -kEpsilon), within = 0;
            const bool expected = !shell.shadesCone(from, within, axis, halfAngle);
            ++cases;
            open += expected;
            EXPECT_EQ(o.all || (o.groups >> d & 1), expected) << "disk " << d << " at " << q.p.x << " " << q.p.y << " " << q.p.z;
        }
    }
    EXPECT_GT(open, cases / 20);  // both answers are tested
    EXPECT_LT(open, cases / 2);
}

TEST(OpenSunDisks, ChoosesAmongTheOpenDisksInProportion) {
    const SunPatches shell(twoWindowRoom(), false);
    for (int count : {7, 100}) {
        const DaylightEnvironment daylight = morning(count);
        const OpenSunDisks disks(&daylight, shell);
        const size_t groups = disks.groupCount();
        // Every other group open, the first one too.
        OpenSunDisks::Open open;
        open.all = false, open.share = 0;
        std::vector<double> expected(size_t(count), 0.0);
        for (size_t g = 0; g < groups; g += 2) open.groups |= uint32_t(1) << g;
        for (int d = 0; d < count; ++d)
            if (open.groups >> disks.groupOf(size_t(d)) & 1) expected[size_t(d)] = daylight.sunDiskProbability(size_t(d)), open.share += expected[size_t(d)];
        const int n = 200000;
        std::vector<double> observed(size_t(count), 0.0);
        Rng rng(3);
        for (int i = 0; i < n; ++i) {
            const size_t d = disks.choose(open, rng.uniform());
            ASSERT_LT(d, size_t(count));
            ASSERT_GT(expected[d], 0) << "disk " << d << " of a closed group";
            observed[d] += 1;
        }
        for (double& e : expected) e *= n / open.share;
        const test::Chi2Result r = test::chi2Test(observed, expected);
        EXPECT_GT(r.pValue, 1e-3) << count << " disks\n" << r.table;
        // u at the ends stays in the open groups.
        EXPECT_GT(expected[disks.choose(open, 0.0)], 0);
        EXPECT_GT(expected[disks.choose(open, std::nextafter(1.0, 0.0))], 0);
        // All open: the period's own choice; none open: none.
        OpenSunDisks::Open all;
        for (double u : {0.0, 0.3, 0.77, 0.999}) EXPECT_EQ(disks.choose(all, u), daylight.sunDiskOf(u));
        OpenSunDisks::Open none;
        none.all = false, none.share = 0;
        EXPECT_EQ(disks.choose(none, 0.5), OpenSunDisks::kNone);
    }
}

TEST(OpenSunDisks, InactiveWithoutAnOpaqueShellOrASun) {
    const DaylightEnvironment daylight = morning(7);
    const Scene seeThrough = SceneBuilder()
                                 .material("wall", test::diffuse(0.5))
                                 .material("glass", test::glass(0.8))
                                 .room({0, 0, 0}, {6, 4, 3}, "wall", "glass", "wall")
                                 .window(Wall::South, 1, 2, 1, 1)
                                 .build();
    EXPECT_FALSE(OpenSunDisks(&daylight, SunPatches(seeThrough, false)).active());
    EXPECT_FALSE(OpenSunDisks(nullptr, SunPatches(twoWindowRoom(), false)).active());
    const OpenSunDisks inactive;
    const OpenSunDisks::Open o = inactive.at({1, 1, 1}, nullptr, kEpsilon);
    EXPECT_TRUE(o.all);
    EXPECT_EQ(o.share, 1.0);
}

}  // namespace
}  // namespace luxplan
