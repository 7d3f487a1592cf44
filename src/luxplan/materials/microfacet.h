// GGX (Trowbridge-Reitz) microfacet terms, visible-normal sampling and Fresnel
// factors, all in the local shading frame (z = shading normal, directions unit length).
#pragma once

#include <luxplan/core/math.h>
#include <luxplan/core/sin_cos.h>

namespace luxplan {

// Smallest GGX alpha the BSDFs use (roughness is clamped to it; the albedo table starts
// here). Its lobe is ~0.06 degrees wide: any smoother coat is a mirror for lighting.
inline constexpr double kMinGgxAlpha = 1e-3;

// Mirror reflection of w about the unit vector n, in the BSDF convention: w points away
// from the surface and so does the result. A ray direction d travelling towards the
// surface reflects into reflect(-d, n) (= d - 2 (d.n) n).
constexpr Vec3 reflect(const Vec3& w, const Vec3& n) { return 2 * dot(w, n) * n - w; }

// GGX normal distribution D(h), per unit solid angle of microfacet normals; it
// satisfies the projected-area identity  int D(h) cos(theta_h) dh = 1.
inline double ggxD(const Vec3& h, double alpha) {
    if (h.z <= 0) return 0;
    double a2 = alpha * alpha;
    double t = h.z * h.z * (a2 - 1) + 1;
    return a2 / (kPi * t * t);
}

// Smith Lambda for GGX: G1 = 1 / (1 + Lambda).
inline double ggxLambda(const Vec3& w, double alpha) {
    double cos2 = w.z * w.z;
    if (cos2 <= 0) return kInf;
    double tan2 = std::max(0.0, 1 - cos2) / cos2;
    return 0.5 * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}

// Smith masking of one direction.
inline double ggxG1(const Vec3& w, double alpha) { return 1 / (1 + ggxLambda(w, alpha)); }

// Height-correlated Smith masking-shadowing (Heitz 2014, "Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT 3(2)).
inline double ggxG2(const Vec3& wo, const Vec3& wi, double alpha) {
    // Summed first, so that G2 is exactly symmetric in (wo, wi) for reciprocity.
    return 1 / (1 + (ggxLambda(wo, alpha) + ggxLambda(wi, alpha)));
}

// A microfacet normal drawn from the distribution of normals visible from wo
// (wo.z > 0): D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z. Heitz 2018, "Sampling the
// GGX Distribution of Visible Normals", JCGT 7(4), https://jcgt.org/published/0007/04/01/
inline Vec3 sampleGgxVisibleNormal(const Vec3& wo, double alpha, Vec2 u) {
    // Stretch to the hemisphere configuration (alpha = 1).
    Vec3 vh = normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
    double lensq = vh.x * vh.x + vh.y * vh.y;
    Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
    Vec3 t2 = cross(vh, t1);
    // Uniform point on the disk, squeezed onto the visible half of the projected hemisphere.
    double r = std::sqrt(u.x), phi = 2 * kPi * u.y;
    const SinCos t = sinCos(phi);
    double p1 = r * t.cos, p2 = r * t.sin;
    double s = 0.5 * (1 + vh.z);
    p2 = (1 - s) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + s * p2;
    Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2));
    // Unstretch back to the ellipsoid configuration.
    return normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(1e-12, nh.z)));
}

// Density of sampleGgxVisibleNormal over microfacet normals h (per unit solid angle).
inline double ggxVisibleNormalPdf(const Vec3& wo, const Vec3& h, double alpha) {
    double cosOh = dot(wo, h);
    if (wo.z <= 0 || cosOh <= 0) return 0;
    return ggxG1(wo, alpha) * cosOh * ggxD(h, alpha) / wo.z;
}

// Schlick's approximation of Fresnel reflectance, f0 = reflectance at normal incidence.
inline double schlickWeight(double cosTheta) {
    double m = std::clamp(1 - cosTheta, 0.0, 1.0);
    double m2 = m * m;
    return m2 * m2 * m;
}
inline Vec3 schlickFresnel(const Vec3& f0, double cosTheta) {
    double w = schlickWeight(cosTheta);
    return f0 * (1 - w) + Vec3(w, w, w);
}

// Exact Fresnel reflectance of a smooth interface seen from the medium of lower
// index (eta = n2/n1 >= 1, so no total internal reflection), for s and p polarized
// light; the unpolarized reflectance is their mean. cosTheta in [0, 1].
struct PolarizedReflectance {
    double s = 0, p = 0;
};
inline PolarizedReflectance dielectricFresnel(double cosTheta, double eta) {
    double cosI = std::clamp(cosTheta, 0.0, 1.0);
    if (cosI <= 0) return {1, 1};  // the grazing limit
    double sin2T = (1 - cosI * cosI) / (eta * eta);
    double cosT = std::sqrt(std::max(0.0, 1 - sin2T));
    double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return {rs * rs, rp * rp};
}

}  // namespace luxplan
