// Scattering models of the five material types (diffuse, glossy, glass, mirror,
// translucent):
// evaluation, importance sampling and pdf in the local shading frame. A Bsdf is a
// small value type with a switch inside: no allocation, no virtual calls.
#pragma once

#include <cstdint>
#include <optional>

#include <luxplan/core/math.h>
#include <luxplan/materials/ggx_albedo.h>
#include <luxplan/materials/material.h>
#include <luxplan/materials/thin_glass.h>

namespace luxplan {

// Conventions shared by every model:
//  - Directions are unit vectors in the local shading frame (z = shading normal, see
//    Frame::toLocal), both pointing away from the surface: wo towards where the light
//    goes (camera / previous path vertex), wi towards where it comes from.
//  - f = eval(wo, wi) is the BSDF per steradian, WITHOUT the cosine: the reflected
//    radiance is L(wo) = int f(wo, wi) L(wi) |wi.z| dwi. Values are linear RGB.
//  - Opaque models (diffuse, glossy, mirror) are two-sided: the side wo is on is the
//    lit side, and wi must be on the same side. f is reciprocal: f(wo, wi) = f(wi, wo).
//  - The translucent model scatters to both sides: wi on wo's side is reflection, on
//    the other side transmission (both Lambertian, both reciprocal).
//  - Delta lobes (mirror, glass) are not functions: eval and pdf return 0 for them
//    and only sample() reaches them.

// One sampled direction. For every sample, weight = f * |wi.z| / pdf.
struct BsdfSample {
    Vec3 wi;
    // Non-delta: the BSDF value eval(wo, wi), as above.
    // Delta: the fraction of flux the lobe scatters, divided by |wi.z| (pbrt's convention).
    Vec3 f;
    // Non-delta: solid-angle density of wi (the full mixture pdf, = pdf(wo, wi)).
    // Delta: the discrete probability of having chosen this lobe.
    double pdf = 0;
    // What the path throughput is multiplied by: for delta lobes the lobe's reflectance
    // or transmittance divided by the probability of choosing it.
    Vec3 weight;
    bool isDelta = false;         // wi is the lobe's only direction: no MIS, no light sampling
    bool isTransmission = false;  // wi is on the other side of the surface than wo
};

// f and pdf of one direction pair, as eval() and pdf() return them.
struct BsdfEval {
    Vec3 f;
    double pdf = 0;
};

enum class BsdfType : uint8_t { Diffuse, Glossy, ThinGlass, Mirror, Translucent };

class Bsdf {
public:
    // A black diffuse surface.
    Bsdf() = default;

    // Lambertian: f = albedo / pi; cosine-weighted sampling.
    static Bsdf diffuse(const Vec3& albedo);
    // A diffuse base under a GGX specular coat (docs/materials.md):
    //   f = F(wo.h) D(h) G2(wo, wi) / (4 |wo.z| |wi.z|)
    //     + base (1 - E(wo)) (1 - E(wi)) / (pi (1 - Eavg)),
    // F Schlick with normal-incidence reflectance specularF0, D GGX with roughness alpha
    // (clamped to [kMinGgxAlpha, 1]), G2 height-correlated Smith, E the coat's
    // directional albedo and Eavg its cosine-weighted average. Directional albedo:
    // E(wo) + base (1 - E(wo)) <= 1.
    static Bsdf glossy(const Vec3& specularF0, const Vec3& baseAlbedo, double alpha);
    // A thin pane (ThinGlass): mirror reflection and straight-through transmission.
    static Bsdf thinGlass(double normalTransmittance, double ior = kGlassIor);
    // A perfect mirror: delta reflection scaled by `reflectance` at every angle.
    static Bsdf mirror(const Vec3& reflectance);
    // A diffuse transmitter (a lampshade, a frosted sheet): f = reflectance / pi on wo's
    // side, transmittance / pi on the other; each is clamped to [0, 1] and, where their
    // sum exceeds 1, both are scaled down to sum 1. The lobe is chosen in proportion to
    // the luminance of each, then a cosine-weighted direction on its side.
    static Bsdf translucent(const Vec3& reflectance, const Vec3& transmittance);

    BsdfType type() const { return type_; }
    // Every lobe is a delta: eval and pdf are 0 everywhere, so light sampling is useless.
    bool isDelta() const { return type_ == BsdfType::ThinGlass || type_ == BsdfType::Mirror; }
    // Rays cross it unscattered (thin glass): paths and shadow rays go through instead
    // of making a vertex there.
    bool passesStraight() const { return type_ == BsdfType::ThinGlass; }
    // It scatters light arriving from the side opposite wo (translucent): light sampling
    // at its vertices looks to both sides. Its surfaces still block shadow rays.
    bool hasDiffuseTransmission() const { return type_ == BsdfType::Translucent; }
    // For shadow rays: the fraction of flux passing straight through at |cos| = cosTheta
    // to the normal (ThinGlass::transmittance), 0 for every other material.
    double straightTransmittance(double cosTheta) const;

    Vec3 eval(const Vec3& wo, const Vec3& wi) const { return evalPdf(wo, wi).f; }
    double pdf(const Vec3& wo, const Vec3& wi) const;
    // Both at once (what light sampling with MIS needs), sharing the work.
    BsdfEval evalPdf(const Vec3& wo, const Vec3& wi) const;
    // uLobe picks the lobe, u the direction within it (all uniform in [0, 1)). nullopt when
    // no direction is produced: wo.z == 0, or a microfacet reflected below the surface
    // (pdf() integrates to the probability of producing one, so the estimate stays unbiased).
    std::optional<BsdfSample> sample(const Vec3& wo, double uLobe, Vec2 u) const;

    // The fraction of the flux arriving from wo that is scattered, int f |wi.z| dwi plus
    // the delta lobes. Exact except for glossy, whose coat albedo comes from the table.
    Vec3 albedo(const Vec3& wo) const;

    // Parameters as built (after clamping), for inspection and tests.
    const Vec3& reflectance() const { return a_; }  // diffuse/mirror/translucent albedo, glossy F0
    const Vec3& base() const { return b_; }         // glossy base albedo
    const Vec3& transmittance() const { return t_; }  // translucent
    double alpha() const { return alpha_; }         // glossy GGX alpha
    const ThinGlass& glass() const { return glass_; }

private:
    // Glossy terms that depend on wo alone (wo.z > 0).
    struct GlossyView {
        Vec3 coatAlbedo;         // E(wo), per channel
        double coatProbability;  // of sampling the coat rather than the base
    };
    GlossyView glossyView(double cosO) const;
    // wo.z > 0 and wi.z > 0; `pdf` may be null when only f is wanted.
    Vec3 evalGlossy(const Vec3& wo, const Vec3& wi, const GlossyView& view, double* pdf) const;

    BsdfType type_ = BsdfType::Diffuse;
    Vec3 a_{0, 0, 0}, b_{0, 0, 0};
    double alpha_ = 1;
    GgxAlbedoRow row_{};     // glossy: alpha's place in the albedo table
    Vec3 baseScale_{0, 0, 0};  // glossy: base / (pi (1 - Eavg)), per channel
    Vec3 t_{0, 0, 0};          // translucent: diffuse transmittance
    double reflectProbability_ = 1;  // translucent: of sampling the reflection lobe
    ThinGlass glass_{};
};

// The BSDF of a scene material (material.h): diffuse uses `reflectance`; glossy
// `reflectance` (F0), `base` and `roughness`; glass `transmittance` with n = 1.52;
// mirror `reflectance`; translucent `reflectance` and `diffuseTransmittance`. Inputs
// are clamped to their documented ranges.
Bsdf makeBsdf(const Material& material);

}  // namespace luxplan
