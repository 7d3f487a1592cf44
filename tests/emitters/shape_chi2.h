// Chi-square test of an emitter shape's sample() against its pdf(): samples from a
// point binned by where they land in a parametrization of the shape's visible part
// (cell = (a, b) in [0,1]^2), against pdf() integrated over each cell's solid angle.
#pragma once

#include <algorithm>
#include <functional>

#include <luxplan/core/rng.h>
#include <luxplan/emitters/emitter_shape.h>
#include "support/chi2.h"

namespace luxplan::test {

struct Parametrization {
    std::function<Vec2(const Vec3& wi, const Vec3& q)> toCell;
    std::function<std::pair<Vec3, double>(double a, double b)> fromCell;  // point, d(omega)/(da db)
};

// Solid angle per unit area of a surface element at q with unit normal nq, seen from p.
inline double solidAnglePerArea(const Vec3& p, const Vec3& q, const Vec3& nq) {
    return std::abs(dot(normalize(q - p), nq)) / lengthSquared(q - p);
}

inline Chi2Result shapeChi2(const EmitterShape& shape, const Vec3& p, const Parametrization& param, int samples, int n = 10) {
    Rng rng(5);
    std::vector<double> observed(n * n, 0.0), expected(n * n, 0.0);
    for (int k = 0; k < samples; ++k) {
        auto s = shape.sample(p, {rng.uniform(), rng.uniform()});
        if (!s || s->pdf <= 0) continue;
        Vec2 c = param.toCell(normalize(s->position - p), s->position);
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
                    sum += shape.pdf(p, q) * jacobian;
                }
            expected[j * n + i] = sum / (double(sub) * sub * n * n) * samples;
        }
    return chi2Test(observed, expected);
}

// Reads a shape from a JSON object through the registry, as the loader does.
std::shared_ptr<const EmitterShape> readShape(const std::string& name, const std::string& jsonText,
                                              std::vector<std::string>* problems = nullptr);

}  // namespace luxplan::test
