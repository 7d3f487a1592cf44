// Disk emitter: sampling against its pdf (chi-square), its keys and its geometry.
#include <gtest/gtest.h>

#include "shape_chi2.h"

namespace luxplan::test {
namespace {

TEST(DiskEmitter, SamplingMatchesItsPdf) {
    Vec3 center(0.2, 0.1, 0.6), n(0, 0, -1), p(0, 0, 0);
    const double radius = 0.8;
    auto disk = diskEmitter(center, n, radius);
    // (r^2 / R^2, phi / 2 pi): equal-area cells on the disk.
    Parametrization param{
        [&](const Vec3&, const Vec3& q) {
            Vec3 d = q - center;
            double phi = std::atan2(d.y, d.x);
            return Vec2(lengthSquared(d) / (radius * radius), (phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi));
        },
        [&](double a, double b) {
            double r = radius * std::sqrt(a), phi = 2 * kPi * b;
            Vec3 q = center + Vec3(r * std::cos(phi), r * std::sin(phi), 0);
            return std::make_pair(q, kPi * radius * radius * solidAnglePerArea(p, q, n));
        }};
    auto r = shapeChi2(*disk, p, param, 300000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(DiskEmitter, GeometryAndKeys) {
    auto disk = diskEmitter({0, 0, 2}, {0, 0, -1}, 0.25);
    EXPECT_NEAR(disk->area(), kPi / 16, 1e-12);
    EXPECT_EQ(disk->primitive().kind, EmitterPrimitive::Kind::Disc);
    for (const Vec3& q : disk->outline()) EXPECT_NEAR(length(q - Vec3(0, 0, 2)), 0.25, 1e-12);
    std::vector<std::string> problems;
    readShape("disk", R"({"center": [0, 0, 2], "radius": -1})", &problems);
    EXPECT_EQ(problems, std::vector<std::string>{"/e/radius: value -1 outside >= 0.0001 m"});
}

}  // namespace
}  // namespace luxplan::test
