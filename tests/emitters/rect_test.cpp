// Rect emitter: sampling against its pdf (chi-square), its keys, and what it gives
// Embree, the plan and glTF.
#include <gtest/gtest.h>

#include "shape_chi2.h"

namespace luxplan::test {
namespace {

TEST(RectEmitter, SamplingMatchesItsPdf) {
    Vec3 center(-0.1, 0.2, 0.5), n(0, 0, -1);
    auto rect = rectEmitter(center, n, {0, 1, 0}, {1.2, 0.7});
    Vec3 corner = center - Vec3(0.6, 0.35, 0), p(0, 0, 0);
    Parametrization param{
        [&](const Vec3&, const Vec3& q) { return Vec2((q.x - corner.x) / 1.2, (q.y - corner.y) / 0.7); },
        [&](double a, double b) {
            Vec3 q = corner + Vec3(1.2 * a, 0.7 * b, 0);
            return std::make_pair(q, 1.2 * 0.7 * solidAnglePerArea(p, q, n));
        }};
    auto r = shapeChi2(*rect, p, param, 300000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
    // From its plane it is not seen at all.
    EXPECT_FALSE(rect->sample({3, 0, 0.5}, {0.5, 0.5}).has_value());
}

TEST(RectEmitter, GeometryForEmbreePlanAndGltf) {
    auto rect = rectEmitter({1, 2, 3}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.4});
    EXPECT_NEAR(rect->area(), 0.24, 1e-12);
    ASSERT_TRUE(rect->normal().has_value());
    EmitterPrimitive prim = rect->primitive();
    ASSERT_EQ(prim.kind, EmitterPrimitive::Kind::Triangles);
    ASSERT_EQ(prim.triangles.triangles.size(), 2u);
    const auto& t = prim.triangles.triangles[0];
    const auto& v = prim.triangles.positions;
    EXPECT_LT(dot(cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]), Vec3(0, 0, 1)), 0) << "winding faces the normal";
    EXPECT_EQ(rect->outline().size(), 4u);
    EmitterMesh m = rect->mesh();
    EXPECT_NEAR(length(m.frame.applyVector({0, 0, -1}) - Vec3(0, 0, -1)), 0, 1e-12);  // local -z is the normal
}

TEST(RectEmitter, ReadsItsKeys) {
    std::vector<std::string> problems;
    auto rect = readShape("rect", R"({"center": [0, 0, 2], "size": [1, 0.5], "normal": [0, 0, -1]})", &problems);
    EXPECT_TRUE(problems.empty());
    EXPECT_NEAR(rect->area(), 0.5, 1e-12);
    problems.clear();
    readShape("rect", R"({"center": [0, 0, 2], "size": [1, 0.5], "up": [0, 0, 1]})", &problems);
    EXPECT_EQ(problems, std::vector<std::string>{"/e/up: \"up\" is parallel to \"normal\""});
    problems.clear();
    readShape("rect", R"({"center": [0, 0, 2]})", &problems);
    EXPECT_EQ(problems, std::vector<std::string>{"/e: missing required key \"size\""});
}

}  // namespace
}  // namespace luxplan::test
