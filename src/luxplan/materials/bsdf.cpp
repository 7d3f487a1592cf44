// The five scattering models behind Bsdf: Lambertian, GGX-coated diffuse, thin
// glass, mirror and diffuse transmitter (conventions in bsdf.h, derivations in
// docs/materials.md).
#include <luxplan/materials/bsdf.h>

#include <algorithm>

#include <luxplan/core/warp.h>
#include <luxplan/materials/microfacet.h>

namespace luxplan {
namespace {

Vec3 clamp01(const Vec3& v) {
    return {std::clamp(v.x, 0.0, 1.0), std::clamp(v.y, 0.0, 1.0), std::clamp(v.z, 0.0, 1.0)};
}

// The mirror direction about the normal (local frame).
Vec3 mirrorDirection(const Vec3& wo) { return {-wo.x, -wo.y, wo.z}; }

// Opaque models are two-sided: evaluate as if wo were above the surface.
Vec3 flipToUpper(const Vec3& w, bool flip) { return flip ? Vec3(w.x, w.y, -w.z) : w; }

}  // namespace

Bsdf Bsdf::diffuse(const Vec3& albedo) {
    Bsdf b;
    b.type_ = BsdfType::Diffuse;
    b.a_ = clamp01(albedo);
    return b;
}

Bsdf Bsdf::glossy(const Vec3& specularF0, const Vec3& baseAlbedo, double alpha) {
    Bsdf b;
    b.type_ = BsdfType::Glossy;
    b.a_ = clamp01(specularF0);
    b.b_ = clamp01(baseAlbedo);
    b.alpha_ = std::clamp(alpha, kMinGgxAlpha, 1.0);
    b.row_ = ggxAlbedoRow(b.alpha_);
    // The base is normalized by what enters it on average, so that its albedo seen
    // from wo is exactly base (1 - E(wo)) (docs/materials.md, "glossy").
    Vec3 avg = ggxAverageAlbedo(b.row_).with(b.a_);
    for (int c = 0; c < 3; ++c) {
        double transmitted = 1 - avg[c];
        b.baseScale_[c] = transmitted > 1e-9 ? b.b_[c] / (kPi * transmitted) : 0.0;
    }
    return b;
}

Bsdf Bsdf::thinGlass(double normalTransmittance, double ior) {
    Bsdf b;
    b.type_ = BsdfType::ThinGlass;
    b.glass_ = ThinGlass(normalTransmittance, ior);
    return b;
}

Bsdf Bsdf::mirror(const Vec3& reflectance) {
    Bsdf b;
    b.type_ = BsdfType::Mirror;
    b.a_ = clamp01(reflectance);
    return b;
}

Bsdf Bsdf::translucent(const Vec3& reflectance, const Vec3& transmittance) {
    Bsdf b;
    b.type_ = BsdfType::Translucent;
    b.a_ = clamp01(reflectance);
    b.t_ = clamp01(transmittance);
    for (int c = 0; c < 3; ++c) {
        double sum = b.a_[c] + b.t_[c];
        if (sum > 1) b.a_[c] /= sum, b.t_[c] /= sum;  // never more out than in
    }
    double r = luminance(b.a_), t = luminance(b.t_);
    b.reflectProbability_ = r + t > 0 ? r / (r + t) : 1.0;
    return b;
}

double Bsdf::straightTransmittance(double cosTheta) const {
    return type_ == BsdfType::ThinGlass ? glass_.transmittance(cosTheta) : 0.0;
}

// ---- Glossy: GGX coat over a diffuse base ----

Bsdf::GlossyView Bsdf::glossyView(double cosO) const {
    GlossyView v;
    v.coatAlbedo = ggxAlbedo(cosO, row_).with(a_);
    // Mix the lobes in proportion to the flux each scatters from wo (luminance-weighted).
    double coatWeight = luminance(v.coatAlbedo);
    double baseWeight = luminance(b_ * (Vec3(1, 1, 1) - v.coatAlbedo));
    double total = coatWeight + baseWeight;
    v.coatProbability = total > 0 ? coatWeight / total : 1.0;
    return v;
}

Vec3 Bsdf::evalGlossy(const Vec3& wo, const Vec3& wi, const GlossyView& view, double* pdf) const {
    Vec3 h = normalize(wo + wi);
    double d = ggxD(h, alpha_);
    Vec3 coat = schlickFresnel(a_, dot(wo, h)) * (d * ggxG2(wo, wi, alpha_) / (4 * wo.z * wi.z));
    Vec3 one(1, 1, 1);
    Vec3 base = baseScale_ * (one - view.coatAlbedo) * (one - ggxAlbedo(wi.z, row_).with(a_));
    if (pdf) {
        // Visible-normal sampling, reflected: D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 wo.z).
        double coatPdf = ggxG1(wo, alpha_) * d / (4 * wo.z);
        *pdf = view.coatProbability * coatPdf + (1 - view.coatProbability) * cosineHemispherePdf(wi.z);
    }
    return coat + base;
}

// ---- Dispatch ----

BsdfEval Bsdf::evalPdf(const Vec3& wo, const Vec3& wi) const {
    if (type_ == BsdfType::Translucent) {
        if (wo.z == 0 || wi.z == 0) return {};
        bool reflected = wo.z * wi.z > 0;
        return {(reflected ? a_ : t_) * kInvPi, pdf(wo, wi)};
    }
    if (isDelta() || wo.z * wi.z <= 0) return {};
    if (type_ == BsdfType::Diffuse) return {a_ * kInvPi, cosineHemispherePdf(std::abs(wi.z))};
    bool flip = wo.z < 0;
    Vec3 o = flipToUpper(wo, flip), i = flipToUpper(wi, flip);
    BsdfEval out;
    out.f = evalGlossy(o, i, glossyView(o.z), &out.pdf);
    return out;
}

double Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    if (type_ == BsdfType::Translucent) {
        if (wo.z == 0 || wi.z == 0) return 0;
        double lobe = wo.z * wi.z > 0 ? reflectProbability_ : 1 - reflectProbability_;
        return lobe * cosineHemispherePdf(std::abs(wi.z));
    }
    if (isDelta() || wo.z * wi.z <= 0) return 0;
    if (type_ == BsdfType::Diffuse) return cosineHemispherePdf(std::abs(wi.z));
    bool flip = wo.z < 0;
    Vec3 o = flipToUpper(wo, flip), i = flipToUpper(wi, flip);
    GlossyView view = glossyView(o.z);
    double coatPdf = ggxG1(o, alpha_) * ggxD(normalize(o + i), alpha_) / (4 * o.z);
    return view.coatProbability * coatPdf + (1 - view.coatProbability) * cosineHemispherePdf(i.z);
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, double uLobe, Vec2 u) const {
    if (wo.z == 0) return std::nullopt;
    BsdfSample s;
    switch (type_) {
        case BsdfType::Diffuse: {
            Vec3 wi = sampleCosineHemisphere(u);
            if (wi.z <= 0) return std::nullopt;
            s.wi = flipToUpper(wi, wo.z < 0);
            s.f = a_ * kInvPi;
            s.pdf = cosineHemispherePdf(wi.z);
            s.weight = a_;  // f cos / pdf, exactly
            return s;
        }
        case BsdfType::Glossy: {
            bool flip = wo.z < 0;
            Vec3 o = flipToUpper(wo, flip);
            GlossyView view = glossyView(o.z);
            Vec3 wi = uLobe < view.coatProbability ? reflect(o, sampleGgxVisibleNormal(o, alpha_, u))
                                                   : sampleCosineHemisphere(u);
            if (wi.z <= 0) return std::nullopt;  // the microfacet reflected below the surface
            s.f = evalGlossy(o, wi, view, &s.pdf);
            if (!(s.pdf > 0)) return std::nullopt;
            s.weight = s.f * (wi.z / s.pdf);
            s.wi = flipToUpper(wi, flip);
            return s;
        }
        case BsdfType::Translucent: {
            Vec3 wi = sampleCosineHemisphere(u);
            if (wi.z <= 0) return std::nullopt;
            // Reflection stays on wo's side; transmission goes to the other.
            bool reflect = uLobe < reflectProbability_;
            s.isTransmission = !reflect;
            s.wi = flipToUpper(wi, (wo.z < 0) == reflect);
            double lobe = reflect ? reflectProbability_ : 1 - reflectProbability_;
            s.f = (reflect ? a_ : t_) * kInvPi;
            s.pdf = lobe * cosineHemispherePdf(wi.z);
            s.weight = (reflect ? a_ : t_) / lobe;  // f cos / pdf, exactly
            return s;
        }
        case BsdfType::Mirror: {
            s.wi = mirrorDirection(wo);
            s.isDelta = true;
            s.pdf = 1;
            s.f = a_ / std::abs(wo.z);
            s.weight = a_;
            return s;
        }
        case BsdfType::ThinGlass: {
            PaneResponse r = glass_.response(wo.z);
            double total = r.reflectance + r.transmittance;
            if (!(total > 0)) return std::nullopt;
            // Choose reflection or transmission in proportion, so both carry weight R + T.
            double pReflect = r.reflectance / total;
            s.isDelta = true;
            s.isTransmission = uLobe >= pReflect;
            s.wi = s.isTransmission ? -wo : mirrorDirection(wo);
            s.pdf = s.isTransmission ? 1 - pReflect : pReflect;
            double fraction = s.isTransmission ? r.transmittance : r.reflectance;
            s.f = Vec3(1, 1, 1) * (fraction / std::abs(wo.z));
            s.weight = Vec3(total, total, total);
            return s;
        }
    }
    return std::nullopt;
}

Vec3 Bsdf::albedo(const Vec3& wo) const {
    if (wo.z == 0) return {};
    switch (type_) {
        case BsdfType::Diffuse:
        case BsdfType::Mirror:
            return a_;
        case BsdfType::Translucent: return a_ + t_;
        case BsdfType::Glossy: {
            Vec3 coat = ggxAlbedo(std::abs(wo.z), row_).with(a_);
            return coat + b_ * (Vec3(1, 1, 1) - coat);
        }
        case BsdfType::ThinGlass: {
            PaneResponse r = glass_.response(wo.z);
            double total = r.reflectance + r.transmittance;
            return {total, total, total};
        }
    }
    return {};
}

Bsdf makeBsdf(const Material& material) {
    switch (material.type) {
        case MaterialType::Diffuse: return Bsdf::diffuse(material.reflectance);
        case MaterialType::Glossy: return Bsdf::glossy(material.reflectance, material.base, material.roughness);
        case MaterialType::Glass: return Bsdf::thinGlass(material.transmittance);
        case MaterialType::Mirror: return Bsdf::mirror(material.reflectance);
        case MaterialType::Translucent: return Bsdf::translucent(material.reflectance, material.diffuseTransmittance);
    }
    return Bsdf::diffuse(material.reflectance);
}

}  // namespace luxplan
