// Sphere emitter: sampling against its pdf (chi-square), its keys and its geometry.
#include <gtest/gtest.h>

#include "shape_chi2.h"

namespace luxplan::test {
namespace {

TEST(SphereEmitter, SamplingMatchesItsPdf) {
    Vec3 center(0.3, -0.2, 1.2), p(0, 0, 0);
    const double radius = 0.7;
    auto sphere = sphereEmitter(center, radius);
    // Directions in the cone the sphere subtends: ((1 - cos) / (1 - cos max), phi / 2 pi).
    double dist = length(center), cosMax = std::sqrt(1 - radius * radius / (dist * dist));
    Frame f = Frame::fromNormal(center / dist);
    Parametrization param{
        [&](const Vec3& wi, const Vec3&) {
            Vec3 l = f.toLocal(wi);
            double phi = std::atan2(l.y, l.x);
            return Vec2((1 - l.z) / (1 - cosMax), (phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi));
        },
        [&](double a, double b) {
            double cosT = 1 - a * (1 - cosMax), sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT)), phi = 2 * kPi * b;
            Vec3 w = f.toWorld(Vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
            double bb = dot(w, center), c = lengthSquared(center) - radius * radius;
            Vec3 q = w * (bb - std::sqrt(std::max(0.0, bb * bb - c)));
            return std::make_pair(q, (1 - cosMax) * 2 * kPi);  // d(omega) = d(cos) d(phi)
        }};
    auto r = shapeChi2(*sphere, p, param, 300000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
    // From inside, nothing to sample.
    EXPECT_FALSE(sphere->sample(center, {0.5, 0.5}).has_value());
}

TEST(SphereEmitter, EmitsAllRoundAndMeshesOutward) {
    auto sphere = sphereEmitter({0, 0, 2}, 0.1);
    EXPECT_FALSE(sphere->normal().has_value());
    EXPECT_NEAR(sphere->area(), 4 * kPi * 0.01, 1e-12);
    EmitterMesh m = sphere->mesh();
    EXPECT_EQ(m.mesh.triangles.size(), 320u);
    for (const auto& t : m.mesh.triangles) {
        Vec3 a = m.mesh.positions[t[0]], b = m.mesh.positions[t[1]], c = m.mesh.positions[t[2]];
        EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0);
    }
    std::vector<std::string> problems;
    readShape("sphere", R"({"center": [0, 0, 2], "radius": 0.05, "normal": [0, 0, -1]})", &problems);
    EXPECT_EQ(problems, std::vector<std::string>{"/e/normal: unknown key \"normal\" (known keys: center, radius)"});
}

}  // namespace
}  // namespace luxplan::test
