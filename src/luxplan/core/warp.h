// Warps from the unit square to common domains, each with its pdf (per unit
// solid angle for directions, per unit area for points). Callers pass `u` in.
#pragma once

#include <luxplan/core/math.h>
#include <luxplan/core/sin_cos.h>

namespace luxplan {

// Shirley-Chiu concentric map to the unit disk (area-preserving, low distortion).
inline Vec2 sampleUniformDiskConcentric(Vec2 u) {
    double a = 2 * u.x - 1, b = 2 * u.y - 1;
    if (a == 0 && b == 0) return {0, 0};
    double r, theta;
    if (std::abs(a) > std::abs(b)) { r = a; theta = (kPi / 4) * (b / a); }
    else { r = b; theta = kPi / 2 - (kPi / 4) * (a / b); }
    const SinCos t = sinCos(theta);
    return {r * t.cos, r * t.sin};
}

// Cosine-weighted hemisphere about +z; pdf = cos(theta) / pi.
inline Vec3 sampleCosineHemisphere(Vec2 u) {
    Vec2 d = sampleUniformDiskConcentric(u);
    double z = std::sqrt(std::max(0.0, 1 - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}
inline double cosineHemispherePdf(double cosTheta) { return cosTheta > 0 ? cosTheta * kInvPi : 0; }

inline Vec3 sampleUniformHemisphere(Vec2 u) {
    double z = u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u.y;
    const SinCos t = sinCos(phi);
    return {r * t.cos, r * t.sin, z};
}
inline constexpr double uniformHemispherePdf() { return 1 / (2 * kPi); }

// Uniform over the hemisphere about +z, area-preserving from the unit square
// (Clarberg 2008): the concentric disk, then Lambert's azimuthal equal-area map. Each
// cell of a grid on the square maps to an equal solid angle, neighbours to
// neighbours, and the square's midlines to great circles through +z.
inline Vec3 equalAreaHemisphere(Vec2 u) {
    Vec2 d = sampleUniformDiskConcentric(u);
    double r2 = std::min(1.0, d.x * d.x + d.y * d.y), s = std::sqrt(2 - r2);
    return {d.x * s, d.y * s, 1 - r2};
}

inline Vec3 sampleUniformSphere(Vec2 u) {
    double z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u.y;
    const SinCos t = sinCos(phi);
    return {r * t.cos, r * t.sin, z};
}
inline constexpr double uniformSpherePdf() { return 1 / (4 * kPi); }

// Uniform over the cone of directions within acos(cosThetaMax) of +z.
inline Vec3 sampleUniformCone(Vec2 u, double cosThetaMax) {
    double cosTheta = (1 - u.x) + u.x * cosThetaMax;
    double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    double phi = 2 * kPi * u.y;
    const SinCos t = sinCos(phi);
    return {sinTheta * t.cos, sinTheta * t.sin, cosTheta};
}
inline double uniformConePdf(double cosThetaMax) { return 1 / (2 * kPi * (1 - cosThetaMax)); }

// Veach's power heuristic (beta = 2) for multiple importance sampling.
inline double powerHeuristic(double nf, double fPdf, double ng, double gPdf) {
    double f = nf * fPdf, g = ng * gPdf;
    if (std::isinf(f * f)) return 1;
    return f * f / (f * f + g * g);
}

}  // namespace luxplan
