// The sky sampled through the room's openings (pathtracer/sky_light.h): near an opening
// by its spherical rectangle, farther away by its area. Both must draw directions with
// the density pdf() reports (chi-square over cells of each opening), and a sample's own
// pdf must be pdf()'s. A sensor's view also bounds each opening by a cone, so that a
// sensor that sees none of them draws no sky sample (SkyLight::seenBy).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/core/warp.h>
#include <luxplan/pathtracer/sky_light.h>
#include <luxplan/scene/room.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::SceneBuilder;

struct Chi2 {
    double value = 0;
    int dof = -1;
};

// n samples from p, binned by the opening they cross and a cells x cells grid on it,
// against n times the density integrated over each cell (quadrature in the opening's
// area: pdf(w) |cos| / d^2 dA).
Chi2 chiSquare(const SkyLight& sky, const SkyLight::View& view, const std::vector<Rect3>& openings, const Vec3& p) {
    const int cells = 6, n = 120000, m = 24;
    const size_t bins = openings.size() * cells * cells;
    std::vector<double> observed(bins, 0.0), expected(bins, 0.0);
    auto binOf = [&](const Vec3& w, int& bin) {
        for (size_t o = 0; o < openings.size(); ++o) {
            const Rect3& r = openings[o];
            const double t = r.intersect(p, w);
            if (t <= 0) continue;
            const Vec3 q = p + w * t - r.corner;
            const int a = std::min(cells - 1, int(dot(q, r.edgeU) / dot(r.edgeU, r.edgeU) * cells));
            const int b = std::min(cells - 1, int(dot(q, r.edgeV) / dot(r.edgeV, r.edgeV) * cells));
            bin = int(o) * cells * cells + std::max(0, a) * cells + std::max(0, b);
            return true;
        }
        return false;
    };
    Rng rng(11);
    for (int i = 0; i < n; ++i) {
        const EnvironmentSample s = sky.sample(view, p, {rng.uniform(), rng.uniform()});
        if (!(s.pdf > 0)) continue;
        EXPECT_NEAR(s.pdf, sky.pdf(view, p, s.wi), 1e-9 * s.pdf);
        int bin = -1;
        EXPECT_TRUE(binOf(s.wi, bin));
        if (bin >= 0) observed[size_t(bin)] += 1;
    }
    for (size_t o = 0; o < openings.size(); ++o) {
        const Rect3& r = openings[o];
        const Vec3 normal = r.normal();
        const double dA = r.area() / (double(cells) * cells * m * m);
        for (int a = 0; a < cells * m; ++a)
            for (int b = 0; b < cells * m; ++b) {
                const Vec3 q = r.corner + r.edgeU * ((a + 0.5) / (cells * m)) + r.edgeV * ((b + 0.5) / (cells * m));
                const Vec3 d = q - p;
                const double d2 = dot(d, d);
                const Vec3 w = d / std::sqrt(d2);
                expected[o * cells * cells + size_t(a / m) * cells + size_t(b / m)] +=
                    n * sky.pdf(view, p, w) * std::abs(dot(normal, w)) / d2 * dA;
            }
    }
    Chi2 c;
    double total = 0;
    for (size_t b = 0; b < bins; ++b) {
        total += expected[b];
        if (expected[b] < 20) continue;
        c.value += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
        ++c.dof;
    }
    EXPECT_NEAR(total / n, 1.0, 2e-3);  // every sample goes through an opening
    return c;
}

// A 4 x 5 x 3 m room under a uniform sky, with a south and an east window and a skylight.
Scene roomWithThreeOpenings() {
    return SceneBuilder()
        .material("grey", test::diffuse(0.5))
        .uniformSky(1000)
        .room({0, 0, 0}, {4, 5, 3}, "grey", "grey", "grey")
        .window(Wall::South, 1, 2, 1, 1.5)
        .window(Wall::East, 1, 1.2, 0.9, 1.2)
        .skylight({2, 3}, {1, 0.8})
        .build();
}

TEST(SkyLight, DirectionsFollowTheirDensityNearAndFarFromAnOpening) {
    const Scene scene = roomWithThreeOpenings();
    const DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    const SkyLight sky(scene, &daylight, true);
    std::vector<Rect3> openings;
    for (const Opening& o : scene.room()->openings) openings.push_back(openingQuad(scene.room()->box, o));
    // Near the south window (its spherical rectangle), and far from every opening
    // (areas), and a point that samples some each way.
    for (const Vec3 p : {Vec3(2, 0.6, 1.6), Vec3(0.5, 4.5, 0.3), Vec3(2.5, 2.8, 2.2)}) {
        SkyLight::View view;
        sky.view(p, view);
        ASSERT_TRUE(view.active);
        int spherical = 0;
        for (int i = 0; i < view.count; ++i) spherical += view.spherical[i];
        const Chi2 c = chiSquare(sky, view, openings, p);
        ASSERT_GT(c.dof, 30);
        // Above the 0.999 quantile of chi-square with these degrees of freedom.
        EXPECT_LT(c.value, c.dof + 4.5 * std::sqrt(2.0 * c.dof)) << "at " << p.x << "," << p.y << "," << p.z
                                                                 << ": " << spherical << " spherical rectangles";
    }
    // The three points do test both ways.
    SkyLight::View near, far;
    sky.view({2, 0.6, 1.6}, near);
    sky.view({0.5, 4.5, 0.3}, far);
    EXPECT_TRUE(near.spherical[0]);
    for (int i = 0; i < far.count; ++i) EXPECT_FALSE(far.spherical[i]) << i;
}

// A sensor that responds inside a cone (exactly: maySee tests the angle between cones).
class ConeSensor final : public Sensor {
public:
    ConeSensor(const Vec3& p, const Vec3& axis, double halfAngle) : p_(p), axis_(axis), half_(halfAngle) {}
    Vec3 position() const override { return p_; }
    bool isDelta() const override { return false; }
    double response(const Vec3& wi) const override { return dot(wi, axis_) >= std::cos(half_) ? 1 : 0; }
    double pdf(const Vec3&) const override { return 0; }
    SensorSample sample(Vec2) const override { return {}; }
    bool maySee(const Vec3& axis, double cosHalfAngle) const override {
        if (!(cosHalfAngle > 0)) return true;
        return std::acos(std::clamp(dot(axis, axis_), -1.0, 1.0)) <= half_ + std::acos(cosHalfAngle) + 1e-9;
    }

private:
    Vec3 p_, axis_;
    double half_;
};

// A sensor's view of the portals holds a cone round each: every portal sample lies in
// its portal's cone, and a sensor that sees none of the cones is never reached by one.
TEST(SkyLight, ASensorSkipsTheSkyOnlyWhereNoPortalSampleWouldBeSeen) {
    const Scene scene = roomWithThreeOpenings();
    const DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    const SkyLight sky(scene, &daylight, true);
    Rng rng(23);
    int skipped = 0, drawn = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const Vec3 p(0.2 + 3.6 * rng.uniform(), 0.2 + 4.6 * rng.uniform(), 0.2 + 2.6 * rng.uniform());
        const ConeSensor sensor(p, sampleUniformSphere({rng.uniform(), rng.uniform()}), radians(5 + 40 * rng.uniform()));
        const SkyLight::View& view = sky.viewFromSensor(p);
        ASSERT_TRUE(view.active);
        const bool seen = sky.seenBy(view, sensor);
        (seen ? drawn : skipped) += 1;
        for (int k = 0; k < 2000; ++k) {
            const EnvironmentSample s = sky.sample(view, p, {rng.uniform(), rng.uniform()});
            if (!(s.pdf > 0)) continue;
            bool inACone = false;
            for (int i = 0; i < view.count; ++i) inACone = inACone || dot(s.wi, view.coneAxis[i]) >= view.coneCos[i] - 1e-12;
            ASSERT_TRUE(inACone) << "trial " << trial;
            if (!seen) {
                ASSERT_EQ(sensor.response(s.wi), 0) << "trial " << trial << ": a skipped sample would be seen";
            }
        }
    }
    EXPECT_GT(skipped, 50);
    EXPECT_GT(drawn, 50);
}

// The part of a ray inside the room, which the path tracer tests with an any-hit query
// before following an exterior sky sample: it ends at the room's box (half a millimetre
// wider), every point before its end is in the room, and the portal sample's point on
// its opening lies just past it.
TEST(SkyLight, AllOfARayBeforeItLeavesTheRoomIsInIt) {
    const Scene scene = roomWithThreeOpenings();
    const DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    const SkyLight sky(scene, &daylight, true);
    const Bounds3 box({0, 0, 0}, {4, 5, 3});
    Rng rng(29);
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 p(4 * rng.uniform(), 5 * rng.uniform(), 3 * rng.uniform());
        const Vec3 w = sampleUniformSphere({rng.uniform(), rng.uniform()});
        const double until = sky.inRoomUntil(p, w);
        // The exit from the box, by its slabs, plus the half millimetre along w.
        double exit = kInf, across = 0;  // across: w's component through the face it leaves by
        for (int a = 0; a < 3; ++a) {
            const double t = w[a] == 0 ? kInf : ((w[a] > 0 ? box.hi[a] : box.lo[a]) - p[a]) / w[a];
            if (t < exit) exit = t, across = std::abs(w[a]);
        }
        ASSERT_GE(until, exit) << trial;
        ASSERT_LE(until, exit + 5e-4 / across + 1e-12) << trial;
        for (double f : {0.0, 0.5, 1.0}) ASSERT_TRUE(sky.inRoom(p + w * (until * f))) << trial;
        ASSERT_FALSE(sky.inRoom(p + w * (until + 2e-3 / across))) << trial;
    }
    // A portal sample through the south window crosses the wall's plane within the slack.
    const SkyLight::View& view = sky.viewFromSensor({2, 2.5, 1.5});
    for (int k = 0; k < 200; ++k) {
        const EnvironmentSample s = sky.sample(view, {2, 2.5, 1.5}, {rng.uniform(), rng.uniform()});
        if (!(s.pdf > 0)) continue;
        const double until = sky.inRoomUntil({2, 2.5, 1.5}, s.wi);
        const Vec3 end = Vec3(2, 2.5, 1.5) + s.wi * until;
        const bool onAWall = end.x < 1e-3 || end.x > 4 - 1e-3 || end.y < 1e-3 || end.y > 5 - 1e-3 || end.z > 3 - 1e-3;
        EXPECT_TRUE(onAWall) << k;
    }
    // No room: nothing of a ray is inside.
    const Scene open = SceneBuilder().material("grey", test::diffuse(0.5)).uniformSky(1000).build();
    const DaylightEnvironment openSky = buildDaylight(*open.daylight, open.site);
    EXPECT_EQ(SkyLight(open, &openSky, true).inRoomUntil({0, 0, 0}, {0, 0, 1}), 0);
}

}  // namespace
}  // namespace luxplan
