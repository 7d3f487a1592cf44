#include <luxplan/core/spherical_rect.h>

#include <luxplan/core/sin_cos.h>

namespace luxplan {

double Rect3::intersect(const Vec3& p, const Vec3& w) const {
    Vec3 n = cross(edgeU, edgeV);
    double denom = dot(n, w);
    if (denom == 0) return -1;
    double t = dot(n, corner - p) / denom;
    if (t <= 0) return -1;
    Vec3 q = p + w * t - corner;
    double a = dot(q, edgeU) / dot(edgeU, edgeU), b = dot(q, edgeV) / dot(edgeV, edgeV);
    return (a >= 0 && a <= 1 && b >= 0 && b <= 1) ? t : -1;
}

SphericalRect::SphericalRect(const Rect3& rect, const Vec3& origin) : origin_(origin) {
    double lenU = length(rect.edgeU), lenV = length(rect.edgeV);
    x_ = rect.edgeU / lenU;
    y_ = rect.edgeV / lenV;
    z_ = cross(x_, y_);
    Vec3 d = rect.corner - origin;
    x0_ = dot(d, x_), y0_ = dot(d, y_), z0_ = dot(d, z_);
    // The local frame is chosen so that the rectangle lies at z0 < 0.
    if (z0_ > 0) {
        z0_ = -z0_;
        z_ = -z_;
    }
    x1_ = x0_ + lenU, y1_ = y0_ + lenV;
    if (std::abs(z0_) < 1e-9 * (lenU + lenV)) return;  // origin in the plane: nothing seen
    Vec3 v00(x0_, y0_, z0_), v01(x0_, y1_, z0_), v10(x1_, y0_, z0_), v11(x1_, y1_, z0_);
    Vec3 n0 = normalize(cross(v00, v10)), n1 = normalize(cross(v10, v11));
    Vec3 n2 = normalize(cross(v11, v01)), n3 = normalize(cross(v01, v00));
    auto angle = [](const Vec3& a, const Vec3& b) { return std::acos(std::clamp(-dot(a, b), -1.0, 1.0)); };
    double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    b0_ = n0.z, b1_ = n2.z;
    k_ = 2 * kPi - g2 - g3;
    solidAngle_ = std::max(0.0, g0 + g1 - k_);
}

Vec3 SphericalRect::sample(Vec2 u) const {
    // Pick the x coordinate so that the solid angle left of it is u.x * S ...
    double au = u.x * solidAngle_ + k_;
    const SinCos a = sinCos(au);
    double fu = (a.cos * b0_ - b1_) / a.sin;
    double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_), -1.0, 1.0);
    double xu = std::clamp(-(cu * z0_) / std::sqrt(std::max(1e-300, 1 - cu * cu)), x0_, x1_);
    // ... then y uniformly in the projected height of that column.
    double d = std::sqrt(xu * xu + z0_ * z0_);
    double h0 = y0_ / std::sqrt(d * d + y0_ * y0_), h1 = y1_ / std::sqrt(d * d + y1_ * y1_);
    double hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
    double yv = hv2 < 1 - 1e-12 ? hv * d / std::sqrt(1 - hv2) : y1_;
    yv = std::clamp(yv, y0_, y1_);
    return origin_ + x_ * xu + y_ * yv + z_ * z0_;
}

}  // namespace luxplan
