// Spherical rectangle sampling: solid angle against quadrature, and a chi-square test
// of where the samples land against each cell's own solid angle.
#include <gtest/gtest.h>

#include <luxplan/core/rng.h>
#include <luxplan/core/spherical_rect.h>
#include "support/chi2.h"

namespace luxplan {
namespace {

double solidAngleByQuadrature(const Rect3& r, const Vec3& p, int n = 400) {
    double sum = 0, dA = r.area() / (double(n) * n);
    Vec3 normal = r.normal();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Vec3 q = r.corner + r.edgeU * ((i + 0.5) / n) + r.edgeV * ((j + 0.5) / n);
            Vec3 d = q - p;
            double dist2 = lengthSquared(d);
            sum += std::abs(dot(normalize(d), normal)) * dA / dist2;
        }
    return sum;
}

TEST(SphericalRect, SolidAngleMatchesQuadrature) {
    Rect3 r{{1, 2, 3}, {2, 0, 0}, {0, 1.5, 0}};
    for (Vec3 p : {Vec3(2, 2.75, 0), Vec3(0, 0, 2.5), Vec3(5, -1, 4), Vec3(1.5, 2.5, 2.9)}) {
        double expected = solidAngleByQuadrature(r, p);
        EXPECT_NEAR(SphericalRect(r, p).solidAngle(), expected, 1e-4 * expected + 1e-7);
    }
    // A whole hemisphere in the limit: a huge rectangle just above the point.
    Rect3 big{{-1000, -1000, 1}, {2000, 0, 0}, {0, 2000, 0}};
    EXPECT_NEAR(SphericalRect(big, Vec3(0, 0, 0)).solidAngle(), 2 * kPi, 1e-2);
}

TEST(SphericalRect, SamplesAreUniformInSolidAngle) {
    Rect3 r{{-1, 0.5, 1}, {3, 0, 0}, {0, 2, 0.5}};
    r.edgeV = Vec3(0, 2, 0);
    Vec3 p(0.3, 0.2, -0.4);
    SphericalRect sr(r, p);
    const int cells = 12, samples = 1000000;
    std::vector<double> observed(cells * cells), expected(cells * cells);
    Rng rng(11);
    for (int k = 0; k < samples; ++k) {
        Vec3 q = sr.sample({rng.uniform(), rng.uniform()}) - r.corner;
        int i = std::clamp(int(dot(q, r.edgeU) / dot(r.edgeU, r.edgeU) * cells), 0, cells - 1);
        int j = std::clamp(int(dot(q, r.edgeV) / dot(r.edgeV, r.edgeV) * cells), 0, cells - 1);
        observed[j * cells + i] += 1;
    }
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            Rect3 cell{r.corner + r.edgeU * (double(i) / cells) + r.edgeV * (double(j) / cells), r.edgeU / cells, r.edgeV / cells};
            expected[j * cells + i] = SphericalRect(cell, p).solidAngle() / sr.solidAngle() * samples;
        }
    auto result = test::chi2Test(observed, expected);
    EXPECT_GT(result.pValue, 0.01) << result.table;
}

}  // namespace
}  // namespace luxplan
