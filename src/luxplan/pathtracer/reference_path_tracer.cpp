#include <luxplan/pathtracer/reference_path_tracer.h>

#include <luxplan/core/warp.h>
#include <luxplan/pathtracer/light_strategy.h>

namespace luxplan {

ReferencePathTracer::ReferencePathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, int maxDepth)
    : rt_(rt), daylight_(daylight), maxDepth_(maxDepth) {
    for (const Material& m : rt.scene().materials) bsdfs_.push_back(makeBsdf(m));
    std::vector<Transform> world(rt.scene().entities.size());
    for (size_t i = 0; i < world.size(); ++i) world[i] = rt.worldFromEntity(int(i));
    emitters_ = EmitterSet(rt.scene(), world, EmitterSelection::Uniform);
}

double ReferencePathTracer::visibility(const Vec3& p, const Vec3& w, double tMax, int target) const {
    double T = 1;
    Vec3 o = p;
    double left = target >= 0 ? tMax * (1 - 1e-4) : tMax;
    for (int crossings = 0; crossings < 64; ++crossings) {
        const auto hit = rt_.intersect({o, w, 0, left, kAllMask, crossings > 0});
        if (!hit) return T;
        if (hit->kind == HitKind::Emitter) {
            if (hit->index != target) return 0;
        } else {
            const Bsdf& bsdf = bsdfs_[hit->material];
            if (!bsdf.passesStraight()) return 0;
            T *= bsdf.straightTransmittance(std::abs(dot(w, hit->geometricNormal)));
            if (T <= 0) return 0;
        }
        const Vec3 next = hit->kind == HitKind::Emitter ? hit->point + w * kRayEpsilon : offsetAlong(hit->point, hit->geometricNormal, w);
        left -= dot(next - o, w);
        o = next;
        if (left <= 0) return T;
    }
    return 0;
}

double ReferencePathTracer::sample(const Sensor& sensor, Rng& rng) const {
    Vec3 L, throughput(1, 1, 1);
    Vertex v;
    v.p = sensor.position();
    auto evalCos = [&](const Vertex& x, const Vec3& wi) -> Vec3 {
        if (!x.isSurface()) return Vec3(1, 1, 1) * sensor.response(wi);
        const double side = dot(wi, x.ng);
        if (side == 0 || (side < 0 && !x.bsdf->hasDiffuseTransmission())) return Vec3();
        const Vec3 local = x.shading.toLocal(wi);
        if ((side > 0) != (local.z > 0)) return Vec3();
        return x.bsdf->eval(x.wo, local) * std::abs(local.z);
    };
    auto pdfOf = [&](const Vertex& x, const Vec3& wi) {
        return x.isSurface() ? x.bsdf->pdf(x.wo, x.shading.toLocal(wi)) : sensor.pdf(wi);
    };
    auto spawn = [&](const Vertex& x, const Vec3& wi) { return x.isSurface() ? offsetAlong(x.p, x.ng, wi) : x.p + wi * kRayEpsilon; };
    // One light sample: direction, radiance, density, distance, emitter.
    auto nee = [&](const Vec3& wi, const Vec3& Le, double pdf, double maxT, int target) {
        if (!(pdf > 0) || maxComponent(Le) <= 0) return;
        const Vec3 f = evalCos(v, wi);
        if (maxComponent(f) <= 0) return;
        const double T = visibility(spawn(v, wi), wi, v.isSurface() ? maxT : maxT - kRayEpsilon, target);
        if (T > 0) L += throughput * f * Le * (T * powerHeuristic(1, pdf, 1, pdfOf(v, wi)) / pdf);
    };
    bool lastDelta = true;
    double lastPdf = 0;
    Vec3 lastPoint = v.p;
    for (int depth = 0; depth <= maxDepth_; ++depth) {
        const bool delta = v.isSurface() ? v.bsdf->isDelta() : sensor.isDelta();
        if (!delta) {
            if (!emitters_.empty()) {
                const double uChoice = rng.uniform();
                const EmitterSample s = emitters_.sample(v.p, uChoice, {rng.uniform(), rng.uniform()});
                nee(s.wi, Vec3(s.Lv, s.Lv, s.Lv), s.pdf, s.distance, s.emitter);
            }
            if (daylight_ && daylight_->hasSun()) {
                const double uDisk = rng.uniform();
                const EnvironmentSample s = daylight_->sampleSun(uDisk, {rng.uniform(), rng.uniform()});
                nee(s.wi, s.Le, s.pdf, kInf, -1);
            }
            if (daylight_ && daylight_->hasSky()) {
                const double u0 = rng.uniform();
                const EnvironmentSample s = daylight_->sampleSky({u0, rng.uniform()});
                nee(s.wi, s.Le, s.pdf, kInf, -1);
            }
        }
        if (depth == maxDepth_) break;
        // BSDF sampling (the sensor's own sampling at the first vertex).
        Vec3 d, weight;
        double pdf = 0;
        bool sampledDelta = false;
        if (!v.isSurface()) {
            const SensorSample s = sensor.isDelta() ? sensor.sample({0, 0}) : sensor.sample({rng.uniform(), rng.uniform()});
            d = s.wi, weight = Vec3(s.weight, s.weight, s.weight), pdf = s.pdf, sampledDelta = s.delta;
        } else {
            const double uLobe = rng.uniform();
            const auto s = v.bsdf->sample(v.wo, uLobe, {rng.uniform(), rng.uniform()});
            if (!s) break;
            d = v.shading.toWorld(s->wi);
            if (s->isTransmission ? dot(d, v.ng) >= 0 : dot(d, v.ng) <= 0) break;
            weight = s->weight, pdf = s->pdf, sampledDelta = s->isDelta;
        }
        throughput = throughput * weight;
        if (maxComponent(throughput) <= 0) break;
        lastDelta = sampledDelta, lastPdf = pdf, lastPoint = v.p;
        // Follow the ray through thin panes to the next surface or light.
        Vec3 o = spawn(v, d);
        bool scattered = false;
        for (int crossings = 0; crossings < 64 && !scattered; ++crossings) {
            const auto hit = rt_.intersect({o, d, 0, kInf, kAllMask, true});
            const bool hidden = depth == 0 && sensor.hidesSources();
            if (!hit) {
                if (!daylight_) return luminance(L);
                const Vec3 sky = daylight_->Le(d), sun = hidden ? Vec3() : daylight_->sunLe(d);
                const double wSky = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, daylight_->hasSky() ? daylight_->skyPdf(d) : 0.0);
                const double wSun = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, daylight_->hasSun() ? daylight_->sunPdf(d) : 0.0);
                L += throughput * (sky * wSky + sun * wSun);
                return luminance(L);
            }
            if (hit->kind == HitKind::Emitter) {
                const double Le = hidden ? 0.0 : emitters_.emitted(size_t(hit->index), d);
                const double w = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, emitters_.pdf(size_t(hit->index), lastPoint, hit->point));
                if (Le > 0) L += throughput * Vec3(Le, Le, Le) * w;
                return luminance(L);
            }
            const Bsdf& bsdf = bsdfs_[hit->material];
            if (bsdf.passesStraight()) {
                const PaneResponse r = bsdf.glass().response(std::abs(dot(d, hit->geometricNormal)));
                const double scatter = r.reflectance + r.transmittance;
                if (scatter <= 0) return luminance(L);
                throughput = throughput * scatter;
                if (!(rng.uniform() * scatter < r.transmittance)) d = reflect(-d, hit->geometricNormal), lastDelta = true;
                o = offsetAlong(hit->point, hit->geometricNormal, d);
                continue;
            }
            v = surfaceVertex(*hit, bsdf, -d);
            scattered = true;
        }
        if (!scattered) break;
    }
    return luminance(L);
}

}  // namespace luxplan
