// A light sample the sensor cannot see is not drawn (Sensor::maySee; the sky's portals
// in sky_light_test.cpp): the tracer skips it only where the sample would surely have
// added nothing, so every direction the skipped strategy could draw must lie outside
// what the sensor sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <luxplan/core/rng.h>
#include <luxplan/core/warp.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/pathtracer/sensor.h>

namespace luxplan {
namespace {

Vec3 randomDirection(Rng& rng) { return sampleUniformSphere({rng.uniform(), rng.uniform()}); }

// Random pyramids (a glare frustum's) and random cones: a cone one of whose directions
// lies in the pyramid must be seen. Directions are drawn inside each cone and on its rim.
TEST(SensorCone, APyramidSeesEveryConeThatReachesIt) {
    Rng rng(17);
    int unseen = 0, seen = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const Frame frame = Frame::fromNormal(randomDirection(rng));
        const double tanHalfFov = std::tan(radians(5 + 80 * rng.uniform()));
        const Vec3 axis = randomDirection(rng);
        const double cosHalf = std::cos(radians(trial % 4 == 0 ? 0.3 : 60 * rng.uniform()));
        const bool maySee = pyramidMaySee(frame.n, frame.s, frame.t, tanHalfFov, axis, cosHalf);
        (maySee ? seen : unseen) += 1;
        if (maySee) continue;
        const Frame cone = Frame::fromNormal(axis);
        for (int k = 0; k < 400; ++k) {
            // The last 100 on the rim, where a wrong test fails first.
            const double cosTheta = k < 300 ? 1 - rng.uniform() * (1 - cosHalf) : cosHalf;
            const double phi = 2 * kPi * rng.uniform(), sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
            const Vec3 w = cone.toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
            const double z = dot(w, frame.n);
            const bool inside = z > 0 && std::abs(dot(w, frame.s)) <= tanHalfFov * z && std::abs(dot(w, frame.t)) <= tanHalfFov * z;
            ASSERT_FALSE(inside) << "trial " << trial << ": a direction of the cone lies in the pyramid";
        }
    }
    // Both answers are common, so the test above is not vacuous.
    EXPECT_GT(unseen, 800);
    EXPECT_GT(seen, 800);
    // A cone round the pyramid's own axis, and a hemisphere's worth, are always seen.
    EXPECT_TRUE(pyramidMaySee({0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 0.5, {0, 0, 1}, 0.9999));
    EXPECT_TRUE(pyramidMaySee({0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 0.5, {0, 0, -1}, 0.0));
}

// A sensor skips a luminaire whose sphere of radius reach() round center() it cannot
// see: every point a shape's sampling draws, from anywhere, lies in that sphere.
TEST(SensorCone, EveryLuminaireLiesInItsReachAroundItsCentre) {
    Rng rng(29);
    const Transform placed = Transform::placement({1, 2, 0.3}, 37);
    for (const auto& shape : {rectEmitter({0, 0, 2.5}, {0, 0, -1}, {0, 1, 0}, {1.2, 0.3}),
                              diskEmitter({1, 1, 2.5}, normalize(Vec3(0.3, 0, -1)), 0.25), sphereEmitter({2, 0, 2}, 0.1),
                              rectEmitter({0, 0, 2.5}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6})->transformed(placed)}) {
        int drawn = 0;
        double farthest = 0;
        for (int k = 0; k < 20000; ++k) {
            const Vec3 p(-3 + 6 * rng.uniform(), -3 + 6 * rng.uniform(), 3 * rng.uniform());
            const auto q = shape->sample(p, {rng.uniform(), rng.uniform()});
            if (!q) continue;
            ++drawn;
            farthest = std::max(farthest, length(q->position - shape->center()));
        }
        EXPECT_GT(drawn, 5000) << shape->describe();
        EXPECT_LE(farthest, shape->reach() + 1e-9) << shape->describe();  // rounding, within maySee's slack
        EXPECT_GT(farthest, 0.9 * shape->reach()) << shape->describe();  // a tight sphere, not any
    }
}

}  // namespace
}  // namespace luxplan
