// GGX coat albedo: the reference quadrature, the table it generated
// (ggx_albedo_table.inc) and its bilinear lookup and exact cosine-weighted average.
#include <luxplan/materials/ggx_albedo.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <luxplan/materials/microfacet.h>

namespace luxplan {
namespace {

// kGgxAlbedoTable[row][column] = {scale, bias} at (ggxAlbedoTableAlpha(row), ggxAlbedoTableCos(column)).
#include "ggx_albedo_table.inc"

// Table coordinates in [0, 1]. The cosine axis blends a linear warp with a logarithmic one
// (dense down to mu ~ kCosWarpScale); the alpha axis blends linear with log(alpha). The
// weights were chosen by measuring the interpolation error against the quadrature.
constexpr double kCosWarpScale = 1e-3;
constexpr double kCosLinearWeight = 0.5;
constexpr double kAlphaLinearWeight = 0.3;

double cosCoord(double mu) {
    static const double logNorm = 1 / std::log1p(1 / kCosWarpScale);
    return kCosLinearWeight * mu + (1 - kCosLinearWeight) * std::log1p(mu / kCosWarpScale) * logNorm;
}

double alphaCoord(double alpha) {
    static const double logNorm = 1 / std::log(1 / kMinGgxAlpha);
    return kAlphaLinearWeight * (alpha - kMinGgxAlpha) / (1 - kMinGgxAlpha) +
           (1 - kAlphaLinearWeight) * std::log(alpha / kMinGgxAlpha) * logNorm;
}

// Inverse of an increasing map [lo, hi] -> [0, 1] by bisection (table nodes only).
template <class F>
double invert(const F& coord, double y, double lo, double hi) {
    if (y <= 0) return lo;
    if (y >= 1) return hi;
    for (int k = 0; k < 100 && hi - lo > 1e-17; ++k) {
        double mid = 0.5 * (lo + hi);
        (coord(mid) < y ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// ---- Reference quadrature ----

struct Terms {
    double scale = 0, bias = 0;
    Terms operator+(const Terms& o) const { return {scale + o.scale, bias + o.bias}; }
    Terms operator-(const Terms& o) const { return {scale - o.scale, bias - o.bias}; }
    Terms operator*(double s) const { return {scale * s, bias * s}; }
    double norm() const { return std::max(std::abs(scale), std::abs(bias)); }
};

// Adaptive Simpson on [a, b], vector-valued; depth-capped so that a jump (the horizon)
// costs a bounded number of evaluations.
template <class F>
Terms simpson(const F& f, double a, double b, const Terms& fa, const Terms& fm, const Terms& fb, const Terms& whole,
              double eps, int depth) {
    double m = 0.5 * (a + b);
    Terms flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
    Terms left = (fa + flm * 4 + fm) * ((m - a) / 6), right = (fm + frm * 4 + fb) * ((b - m) / 6);
    Terms delta = left + right - whole;
    if (depth <= 0 || delta.norm() <= 15 * eps) return left + right + delta * (1.0 / 15);
    return simpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) + simpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

// Starts from `panels` equal panels so that narrow features are seen at all.
template <class F>
Terms integrate(const F& f, double a, double b, double eps, int panels) {
    Terms sum;
    double h = (b - a) / panels;
    for (int k = 0; k < panels; ++k) {
        double x0 = a + k * h, x1 = x0 + h;
        Terms f0 = f(x0), fm = f(0.5 * (x0 + x1)), f1 = f(x1);
        sum = sum + simpson(f, x0, x1, f0, fm, f1, (f0 + fm * 4 + f1) * (h / 6), eps / panels, 24);
    }
    return sum;
}

// ---- Table lookup ----

constexpr int kCols = kGgxAlbedoCosCount, kRows = kGgxAlbedoAlphaCount;

// Per row, 2 int_0^1 E(mu) mu dmu of the row's interpolant (linear in cosCoord between
// nodes), by 5-point Gauss-Legendre on every segment: exact to rounding for this smooth integrand.
struct RowAverages {
    std::array<Terms, kRows> rows;
    RowAverages() {
        static constexpr double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                        0.9061798459386640};
        static constexpr double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                        0.4786286704993665, 0.2369268850561891};
        std::array<double, kCols> mu;
        for (int i = 0; i < kCols; ++i) mu[i] = ggxAlbedoTableCos(i);
        for (int j = 0; j < kRows; ++j) {
            Terms sum;
            for (int i = 0; i + 1 < kCols; ++i) {
                Terms e0{kGgxAlbedoTable[j][i][0], kGgxAlbedoTable[j][i][1]};
                Terms e1{kGgxAlbedoTable[j][i + 1][0], kGgxAlbedoTable[j][i + 1][1]};
                double s0 = double(i) / (kCols - 1), ds = 1.0 / (kCols - 1);
                double half = 0.5 * (mu[i + 1] - mu[i]), mid = 0.5 * (mu[i + 1] + mu[i]);
                for (int k = 0; k < 5; ++k) {
                    double m = mid + half * x[k];
                    double f = std::clamp((cosCoord(m) - s0) / ds, 0.0, 1.0);
                    sum = sum + (e0 * (1 - f) + e1 * f) * (w[k] * half * m);
                }
            }
            rows[j] = sum * 2;
        }
    }
};

}  // namespace

double ggxAlbedoTableCos(int column) {
    if (column >= kCols - 1) return 1;
    return invert(cosCoord, double(column) / (kCols - 1), 0.0, 1.0);
}

double ggxAlbedoTableAlpha(int row) {
    if (row >= kRows - 1) return 1;
    return invert(alphaCoord, double(row) / (kRows - 1), kMinGgxAlpha, 1.0);
}

GgxAlbedoRow ggxAlbedoRow(double alpha) {
    double x = alphaCoord(std::clamp(alpha, kMinGgxAlpha, 1.0)) * (kRows - 1);
    int row = std::clamp(int(x), 0, kRows - 2);
    return {row, std::clamp(x - row, 0.0, 1.0)};
}

GgxAlbedo ggxAlbedo(double cosTheta, GgxAlbedoRow row) {
    double x = cosCoord(std::clamp(cosTheta, 0.0, 1.0)) * (kCols - 1);
    int i = std::clamp(int(x), 0, kCols - 2);
    double f = std::clamp(x - i, 0.0, 1.0);
    const auto& r0 = kGgxAlbedoTable[row.row];
    const auto& r1 = kGgxAlbedoTable[row.row + 1];
    GgxAlbedo out;
    for (int c = 0; c < 2; ++c) {
        double v0 = (1 - f) * r0[i][c] + f * r0[i + 1][c];
        double v1 = (1 - f) * r1[i][c] + f * r1[i + 1][c];
        (c == 0 ? out.scale : out.bias) = (1 - row.t) * v0 + row.t * v1;
    }
    return out;
}

GgxAlbedo ggxAverageAlbedo(GgxAlbedoRow row) {
    static const RowAverages averages;
    Terms t = averages.rows[row.row] * (1 - row.t) + averages.rows[row.row + 1] * row.t;
    return {t.scale, t.bias};
}

GgxAlbedo ggxAlbedoQuadrature(double cosTheta, double alpha, double tolerance) {
    // E(wo) = int f cos(theta_i) dwi = int F(wo.h) D(h) G2(wo, wi) (wo.h) / wo.z dh over
    // microfacet normals h (dwi = 4 (wo.h) dh). h is parametrized by its slope
    // tan(theta_h) = alpha tan(pi v / 2), v in [0, 1), which spreads the GGX peak and tail
    // evenly, and by phi in [0, pi] (wo lies in the xz plane, so the integrand is even in phi).
    double mu = std::clamp(cosTheta, 1e-7, 1.0);
    alpha = std::clamp(alpha, kMinGgxAlpha, 1.0);
    Vec3 wo(std::sqrt(1 - mu * mu), 0, mu);
    auto overSlope = [&](double v) -> Terms {
        double m = alpha * std::tan(0.5 * kPi * v);
        if (!std::isfinite(m) || v >= 1) return {};  // h in the horizon: wi is below the surface
        double cosH = 1 / std::sqrt(1 + m * m), sinH = m * cosH;
        // D(h) sin(theta_h) d(theta_h)/dv, simplified.
        double jacobian = alpha * m / (2 * cosH * (alpha * alpha + m * m));
        auto overPhi = [&](double phi) -> Terms {
            Vec3 h(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
            double c = dot(wo, h);
            if (c <= 0) return {};
            Vec3 wi = reflect(wo, h);
            if (wi.z <= 0) return {};
            double value = jacobian * ggxG2(wo, wi, alpha) * c / mu;
            double w = schlickWeight(c);
            return {value * (1 - w), value * w};
        };
        return integrate(overPhi, 0.0, kPi, tolerance, 8) * 2;
    };
    Terms t = integrate(overSlope, 0.0, 1.0, tolerance, 16);
    return {t.scale, t.bias};
}

}  // namespace luxplan
