#include <gtest/gtest.h>

#include <luxplan/core/math.h>
#include <luxplan/core/rng.h>

namespace luxplan {
namespace {

void expectNear(const Vec3& a, const Vec3& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Transform, PlacementRotatesCounterClockwiseThenTranslates) {
    Transform t = Transform::placement({1, 2, 0}, 90);
    expectNear(t.applyPoint({1, 0, 0}), {1, 3, 0});
    expectNear(t.applyVector({0, -1, 0}), {1, 0, 0});
}

TEST(Transform, CompositionAndInverse) {
    Transform a = Transform::placement({1, 2, 0.5}, 30), b = Transform::placement({-3, 0.25, 0}, -75) * Transform::scale(2);
    Vec3 p{0.3, -0.7, 1.1};
    expectNear((a * b).applyPoint(p), a.applyPoint(b.applyPoint(p)));
    expectNear((a * b).inverse().applyPoint((a * b).applyPoint(p)), p);
}

TEST(Frame, FromNormalIsOrthonormal) {
    for (Vec3 n : {Vec3(0, 0, 1), Vec3(0, 0, -1), normalize(Vec3(1, 2, -3)), Vec3(1, 0, 0)}) {
        Frame f = Frame::fromNormal(n);
        EXPECT_NEAR(dot(f.s, f.t), 0, 1e-12);
        EXPECT_NEAR(dot(f.s, f.n), 0, 1e-12);
        EXPECT_NEAR(length(f.s), 1, 1e-12);
        expectNear(cross(f.s, f.t), f.n);
    }
}

TEST(Rng, SameSeedSameStreamDifferentSeedDifferentStream) {
    Rng a(hashValues({1, 2, 3})), b(hashValues({1, 2, 3})), c(hashValues({1, 3, 2}));
    for (int i = 0; i < 100; ++i) {
        uint32_t va = a.nextU32();
        EXPECT_EQ(va, b.nextU32());
        (void)c;
    }
    EXPECT_NE(Rng(hashValues({1, 2, 3})).nextU32(), Rng(hashValues({1, 3, 2})).nextU32());
}

TEST(Rng, UniformInUnitInterval) {
    Rng r(42);
    double mean = 0;
    for (int i = 0; i < 100000; ++i) {
        double u = r.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        mean += u;
    }
    EXPECT_NEAR(mean / 100000, 0.5, 0.005);  // sigma of the mean = 0.29 / sqrt(1e5) = 0.0009
}

}  // namespace
}  // namespace luxplan
