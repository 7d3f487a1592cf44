// Emitter sampling: chi-square of the sampled directions against pdf() for every
// shape, and the selection probabilities summing to one.
#include <gtest/gtest.h>

#include <functional>
#include <optional>

#include <luxplan/core/rng.h>
#include <luxplan/pathtracer/emitters.h>
#include "support/chi2.h"

namespace luxplan {
namespace {

Scene sceneWith(const Emitter& e) {
    Scene s;
    s.emitters = {e};
    return s;
}

// Samples from the origin binned by where they land in a parametrization of the
// emitter's visible part (cell = (a, b) in [0,1]^2), compared with pdf() integrated
// over each cell's solid angle. `param` maps a sample to (a, b); `cell` maps (a, b) to
// the point on the emitter and the solid angle that a sub-cell of area da db covers.
struct Parametrization {
    std::function<Vec2(const Vec3& wi, const Vec3& q)> toCell;
    std::function<std::pair<Vec3, double>(double a, double b)> fromCell;  // point, d(omega)/(da db)
};

test::Chi2Result emitterChi2(const EmitterSet& set, const Parametrization& param, int samples, int n = 10) {
    Vec3 p(0, 0, 0);
    Rng rng(5);
    std::vector<double> observed(n * n, 0.0), expected(n * n, 0.0);
    for (int k = 0; k < samples; ++k) {
        EmitterSample s = set.sample(p, rng.uniform(), {rng.uniform(), rng.uniform()});
        if (s.pdf <= 0) continue;
        Vec2 c = param.toCell(s.wi, s.wi * s.distance);
        int i = std::clamp(int(c.x * n), 0, n - 1), j = std::clamp(int(c.y * n), 0, n - 1);
        observed[j * n + i] += 1;
    }
    const int sub = 8;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double sum = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    auto [q, jacobian] = param.fromCell((i + (a + 0.5) / sub) / n, (j + (b + 0.5) / sub) / n);
                    sum += set.pdf(0, p, q) * jacobian;
                }
            expected[j * n + i] = sum / (double(sub) * sub * n * n) * samples;
        }
    return test::chi2Test(observed, expected);
}

// Solid angle per unit area of a surface element at q with unit normal nq, seen from the origin.
double solidAnglePerArea(const Vec3& q, const Vec3& nq) { return std::abs(dot(normalize(q), nq)) / lengthSquared(q); }

TEST(EmitterSampling, DiskMatchesItsPdf) {
    Emitter e;
    e.shape = EmitterShape::Disk, e.center = {0.2, 0.1, 0.6}, e.normal = {0, 0, -1}, e.radius = 0.8, e.fluxLm = 100;
    EmitterSet set(sceneWith(e), {}, EmitterSelection::PowerDistance);
    // (r^2 / R^2, phi / 2 pi): equal-area cells on the disk.
    Parametrization param{
        [&](const Vec3&, const Vec3& q) {
            Vec3 d = q - e.center;
            double phi = std::atan2(d.y, d.x);
            return Vec2(lengthSquared(d) / (e.radius * e.radius), (phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi));
        },
        [&](double a, double b) {
            double r = e.radius * std::sqrt(a), phi = 2 * kPi * b;
            Vec3 q = e.center + Vec3(r * std::cos(phi), r * std::sin(phi), 0);
            return std::make_pair(q, kPi * e.radius * e.radius * solidAnglePerArea(q, e.normal));
        }};
    auto r = emitterChi2(set, param, 300000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(EmitterSampling, RectMatchesItsPdf) {
    Emitter e;
    e.shape = EmitterShape::Rect, e.center = {-0.1, 0.2, 0.5}, e.normal = {0, 0, -1}, e.up = {0, 1, 0}, e.size = {1.2, 0.7};
    e.fluxLm = 100;
    EmitterSet set(sceneWith(e), {}, EmitterSelection::PowerDistance);
    Vec3 corner = e.center - Vec3(0.6, 0.35, 0);
    Parametrization param{
        [&](const Vec3&, const Vec3& q) { return Vec2((q.x - corner.x) / 1.2, (q.y - corner.y) / 0.7); },
        [&](double a, double b) {
            Vec3 q = corner + Vec3(1.2 * a, 0.7 * b, 0);
            return std::make_pair(q, 1.2 * 0.7 * solidAnglePerArea(q, e.normal));
        }};
    auto r = emitterChi2(set, param, 300000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(EmitterSampling, SphereMatchesItsPdf) {
    Emitter e;
    e.shape = EmitterShape::Sphere, e.center = {0.3, -0.2, 1.2}, e.radius = 0.7, e.fluxLm = 100;
    EmitterSet set(sceneWith(e), {}, EmitterSelection::PowerDistance);
    // Directions in the cone the sphere subtends: ((1 - cos) / (1 - cos max), phi / 2 pi).
    double dist = length(e.center), cosMax = std::sqrt(1 - e.radius * e.radius / (dist * dist));
    Frame f = Frame::fromNormal(e.center / dist);
    Parametrization param{
        [&](const Vec3& wi, const Vec3&) {
            Vec3 l = f.toLocal(wi);
            double phi = std::atan2(l.y, l.x);
            return Vec2((1 - l.z) / (1 - cosMax), (phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi));
        },
        [&](double a, double b) {
            double cosT = 1 - a * (1 - cosMax), sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT)), phi = 2 * kPi * b;
            Vec3 w = f.toWorld(Vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
            double bb = dot(w, e.center), c = lengthSquared(e.center) - e.radius * e.radius;
            Vec3 q = w * (bb - std::sqrt(std::max(0.0, bb * bb - c)));
            return std::make_pair(q, (1 - cosMax) * 2 * kPi);  // d(omega) = d(cos) d(phi)
        }};
    auto r = emitterChi2(set, param, 300000);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(EmitterSampling, SelectionProbabilitiesSumToOne) {
    Scene s;
    for (int i = 0; i < 5; ++i) {
        Emitter e;
        e.shape = EmitterShape::Disk, e.center = {double(i), 0, 3}, e.radius = 0.2, e.fluxLm = 100.0 * (i + 1);
        s.emitters.push_back(e);
    }
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    double sum = 0;
    for (size_t i = 0; i < set.size(); ++i) sum += set.selectionProbability(i, {1.5, 0.5, 0.8});
    EXPECT_NEAR(sum, 1.0, 1e-12);
    // A point above the one-sided disks is lit by none of them.
    EXPECT_EQ(set.selectionProbability(0, {0, 0, 4}), 0.0);
}

}  // namespace
}  // namespace luxplan
