// Small vector algebra for luxplan: 2D/3D vectors, bounds, orthonormal frames and
// affine transforms. Double precision throughout; Embree buffers convert to float.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace luxplan {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = 1.0 / std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr double radians(double deg) { return deg * (kPi / 180.0); }
constexpr double degrees(double rad) { return rad * (180.0 / kPi); }
// An angle in degrees brought into [0, 360).
inline double wrapDegrees(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d < 0) d += 360.0;
    return d >= 360.0 ? 0.0 : d;
}

struct Vec2 {
    double x = 0, y = 0;
    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}
    constexpr double operator[](int i) const { return i == 0 ? x : y; }
    constexpr double& operator[](int i) { return i == 0 ? x : y; }
    constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    constexpr bool operator==(const Vec2&) const = default;
};
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double length(Vec2 a) { return std::sqrt(dot(a, a)); }

struct Vec3 {
    double x = 0, y = 0, z = 0;
    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3&) const = default;
};
constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double lengthSquared(const Vec3& a) { return dot(a, a); }
inline Vec3 normalize(const Vec3& a) { return a / length(a); }
inline Vec3 min(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vec3 max(const Vec3& a, const Vec3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline double maxComponent(const Vec3& a) { return std::max({a.x, a.y, a.z}); }
// Relative luminance of linear sRGB/Rec.709 primaries (photometric weight of an RGB reflectance).
inline double luminance(const Vec3& rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

// Axis-aligned bounds; empty until the first point is added.
struct Bounds3 {
    Vec3 lo{kInf, kInf, kInf};
    Vec3 hi{-kInf, -kInf, -kInf};
    Bounds3() = default;
    Bounds3(const Vec3& a, const Vec3& b) : lo(min(a, b)), hi(max(a, b)) {}
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const Vec3& p) { lo = min(lo, p); hi = max(hi, p); }
    void extend(const Bounds3& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
    Vec3 size() const { return hi - lo; }
    Vec3 center() const { return (lo + hi) * 0.5; }
    double volume() const { Vec3 s = size(); return empty() ? 0.0 : s.x * s.y * s.z; }
    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
    }
};

// Right-handed orthonormal frame (s, t, n); toLocal/toWorld change vector coordinates.
struct Frame {
    Vec3 s, t, n;
    Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
    Frame(const Vec3& s_, const Vec3& t_, const Vec3& n_) : s(s_), t(t_), n(n_) {}
    // Duff et al. 2017, "Building an Orthonormal Basis, Revisited" (branchless, no singularity).
    static Frame fromNormal(const Vec3& n) {
        double sign = std::copysign(1.0, n.z);
        double a = -1.0 / (sign + n.z);
        double b = n.x * n.y * a;
        return Frame(Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y), n);
    }
    Vec3 toLocal(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

// Affine transform: p' = M p + t, with M a 3x3 matrix stored row-major.
struct Transform {
    std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
    Vec3 t{};

    static Transform translate(const Vec3& d) { Transform r; r.t = d; return r; }
    static Transform scale(double s) { Transform r; r.m = {s, 0, 0, 0, s, 0, 0, 0, s}; return r; }
    static Transform scale(const Vec3& s) { Transform r; r.m = {s.x, 0, 0, 0, s.y, 0, 0, 0, s.z}; return r; }
    // Counter-clockwise rotation about +z seen from above, angle in radians.
    static Transform rotateZ(double rad) {
        double c = std::cos(rad), s = std::sin(rad);
        Transform r; r.m = {c, -s, 0, s, c, 0, 0, 0, 1}; return r;
    }
    // The rigid motion of the scene format: rotate about z by `deg`, then translate.
    static Transform placement(const Vec3& position, double rotationDeg) {
        Transform r = rotateZ(radians(rotationDeg)); r.t = position; return r;
    }

    Vec3 applyVector(const Vec3& v) const {
        return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
                m[6] * v.x + m[7] * v.y + m[8] * v.z};
    }
    Vec3 applyPoint(const Vec3& p) const { return applyVector(p) + t; }
    // Normals transform by the inverse transpose; renormalized.
    Vec3 applyNormal(const Vec3& n) const {
        Transform inv = inverse();
        Vec3 r{inv.m[0] * n.x + inv.m[3] * n.y + inv.m[6] * n.z, inv.m[1] * n.x + inv.m[4] * n.y + inv.m[7] * n.z,
               inv.m[2] * n.x + inv.m[5] * n.y + inv.m[8] * n.z};
        return normalize(r);
    }
    // (this * o)(p) = this(o(p)).
    Transform operator*(const Transform& o) const {
        Transform r;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                r.m[3 * i + j] = m[3 * i] * o.m[j] + m[3 * i + 1] * o.m[3 + j] + m[3 * i + 2] * o.m[6 + j];
        r.t = applyVector(o.t) + t;
        return r;
    }
    double determinant() const {
        return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
               m[2] * (m[3] * m[7] - m[4] * m[6]);
    }
    Transform inverse() const {
        double inv = 1.0 / determinant();
        Transform r;
        r.m = {(m[4] * m[8] - m[5] * m[7]) * inv, (m[2] * m[7] - m[1] * m[8]) * inv, (m[1] * m[5] - m[2] * m[4]) * inv,
               (m[5] * m[6] - m[3] * m[8]) * inv, (m[0] * m[8] - m[2] * m[6]) * inv, (m[2] * m[3] - m[0] * m[5]) * inv,
               (m[3] * m[7] - m[4] * m[6]) * inv, (m[1] * m[6] - m[0] * m[7]) * inv, (m[0] * m[4] - m[1] * m[3]) * inv};
        r.t = -r.applyVector(t);
        return r;
    }
    Bounds3 apply(const Bounds3& b) const {
        Bounds3 r;
        if (b.empty()) return r;
        for (int c = 0; c < 8; ++c)
            r.extend(applyPoint({(c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z}));
        return r;
    }
};

}  // namespace luxplan
