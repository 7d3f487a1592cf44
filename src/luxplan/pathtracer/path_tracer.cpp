#include <luxplan/pathtracer/path_tracer.h>

#include <algorithm>

#include <luxplan/core/warp.h>

namespace luxplan {
namespace {

constexpr double kRayEpsilon = 1e-4;  // metres; scenes are rooms, not microns

Vec3 offsetAlong(const Vec3& p, const Vec3& n, const Vec3& w) { return p + n * (dot(w, n) >= 0 ? kRayEpsilon : -kRayEpsilon); }

// Where the path currently scatters: the sensor itself or a surface.
struct Vertex {
    Vec3 p;
    Vec3 ng;  // geometric normal on the side the path arrived from (surfaces)
    Frame shading;
    Vec3 wo;  // local shading coordinates
    const Bsdf* bsdf = nullptr;  // null at the sensor

    bool isSurface() const { return bsdf != nullptr; }
};

}  // namespace

PathTracer::PathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, const PathTracerOptions& options)
    : rt_(rt), daylight_(daylight), options_(options), sky_(rt.scene(), daylight, options.portals), panes_(rt.scene()) {
    for (const Material& m : rt.scene().materials) bsdfs_.push_back(makeBsdf(m));
    updateLayout();
}

void PathTracer::updateLayout() {
    std::vector<Transform> world(rt_.scene().entities.size());
    for (size_t i = 0; i < world.size(); ++i) world[i] = rt_.worldFromEntity(int(i));
    emitters_ = EmitterSet(rt_.scene(), world, options_.emitterSelection);
}

double PathTracer::transmittance(const Vec3& origin, const Vec3& w, double tMax, int target, RayStats& stats) const {
    // Opaque surfaces first, by an any-hit query. Luminaires block as a path sees
    // them (they absorb what reaches them): towards the sky and sun all of them do,
    // towards an emitter every other one, found by closest-hit queries that step past
    // the target itself (float error in Embree's hit of the target, a grazing ray to
    // a small sphere, must not shadow it).
    ++stats.shadow;
    unsigned blockers = kOpaqueMask | (target < 0 ? kEmitterMask : 0u);
    double opaqueEnd = target < 0 ? tMax : tMax * (1 - 1e-4);
    // The emitter steps below run along this segment; the pane crossings add their own.
    const bool blocked = rt_.occluded({origin, w, 0, opaqueEnd, blockers});
    if (stats.footprint) stats.footprint->addOcclusion(origin, w, 0, opaqueEnd, blockers, blocked);
    if (blocked) return 0;
    if (target >= 0 && emitters_.size() > 1) {
        double tStart = 0;
        for (int steps = 0; steps < 4; ++steps) {
            ++stats.shadow;
            auto hit = rt_.intersect({origin, w, tStart, opaqueEnd, kEmitterMask});
            if (!hit) break;
            if (hit->index != target) return 0;
            tStart = hit->t + kRayEpsilon;
        }
    }
    // Then the windows' panes, analytically, and any other glass in the way, one
    // closest-hit query each, continuing from just beyond each pane along its normal
    // (a step along a grazing ray could stay on the pane and cross it twice).
    double T = panes_.transmittance(origin, w, opaqueEnd);
    if (!rt_.hasGlass() || T <= 0) return T;
    Vec3 p = origin;
    for (int crossings = 0; crossings < 16; ++crossings) {
        ++stats.shadow;
        const double left = opaqueEnd - dot(p - origin, w);
        if (left <= 0) return T;
        auto hit = rt_.intersect({p, w, 0, left, kGlassMask});
        if (stats.footprint) stats.footprint->add(p, w, 0, hit ? hit->t : left);
        if (!hit) return T;
        T *= bsdfs_[hit->material].straightTransmittance(std::abs(dot(w, hit->geometricNormal)));
        if (T <= 0) return 0;
        p = offsetAlong(hit->point, hit->geometricNormal, w);
    }
    return 0;
}

double PathTracer::sample(const Sensor& sensor, PathSamples& samples, RayStats& stats, bool* hitEmitterFirst,
                          SensorLight* sensorLight) const {
    if (sensorLight) sensorLight->count = 0;
    const Vec3 origin = sensor.position();
    Vec3 L, throughput(1, 1, 1);
    Vertex v;
    v.p = origin;

    // f * |cos| and the sampling pdf of the current vertex for a world direction.
    auto evalCos = [&](const Vertex& x, const Vec3& wi) -> Vec3 {
        if (!x.isSurface()) {
            double r = sensor.response(wi);
            return Vec3(r, r, r);
        }
        // Light must arrive on the side the path is on (no leaks through surfaces), or
        // from the other side of a translucent one; on the same side of the geometric
        // and the shading normal (wo is on the upper side of both).
        const double side = dot(wi, x.ng);
        if (side == 0 || (side < 0 && !x.bsdf->hasDiffuseTransmission())) return Vec3();
        Vec3 local = x.shading.toLocal(wi);
        if ((side > 0) != (local.z > 0)) return Vec3();
        return x.bsdf->eval(x.wo, local) * std::abs(local.z);
    };
    auto pdfOf = [&](const Vertex& x, const Vec3& wi) -> double {
        if (!x.isSurface()) return sensor.pdf(wi);
        return x.bsdf->pdf(x.wo, x.shading.toLocal(wi));
    };
    // Rays leave a surface offset along its normal, and a sensor 0.1 mm along the ray,
    // so that a sampler point lying on a surface (a micron off it, after the transforms
    // of a rotated entity) sees past that surface.
    auto spawn = [&](const Vertex& x, const Vec3& wi) {
        return x.isSurface() ? offsetAlong(x.p, x.ng, wi) : x.p + wi * kRayEpsilon;
    };

    bool lastDelta = false;
    double lastPdf = 0;
    Vec3 lastPoint = origin;
    const bool sky = sky_.active();
    SkyLight::View views[2];  // this vertex's, and the last non-delta vertex's
    int current = 0;
    double firstWeight = 0;

    for (int depth = 0; depth < options_.maxDepth; ++depth) {
        samples.setDepth(depth);
        bool deltaVertex = v.isSurface() ? v.bsdf->isDelta() : sensor.isDelta();

        // ---- next-event estimation (skipped at delta vertices) ----
        if (!deltaVertex) {
            auto addLight = [&](const Vec3& wi, const Vec3& Le, double lightPdf, double maxT, int target, int source) {
                if (!(lightPdf > 0) || maxComponent(Le) <= 0) return;
                Vec3 f = evalCos(v, wi);
                if (maxComponent(f) <= 0) return;
                double T = transmittance(spawn(v, wi), wi, v.isSurface() ? maxT : maxT - kRayEpsilon, target, stats);
                if (T <= 0) return;
                double w = powerHeuristic(1, lightPdf, 1, pdfOf(v, wi));
                Vec3 contribution = throughput * f * Le * (T * w / lightPdf);
                if (stats.budget) stats.budget->credit(source, depth, luminance(contribution));
                if (depth == 0 && sensorLight) {
                    sensorLight->wi[sensorLight->count] = wi;
                    sensorLight->value[sensorLight->count++] = luminance(contribution);
                } else {
                    L += contribution;
                }
            };
            if (!emitters_.empty()) {
                if (stats.footprint) stats.footprint->usedEmitterChoice = true;
                const double uChoice = samples.get1D(PathSamples::EmitterChoice);
                EmitterSample s = emitters_.sample(v.p, uChoice, samples.get2D(PathSamples::EmitterPoint));
                if (s.pdf > 0 && s.Lv > 0) addLight(s.wi, Vec3(s.Lv, s.Lv, s.Lv), s.pdf, s.distance, s.emitter, s.emitter);
            }
            if (daylight_ && daylight_->hasSun()) {
                const double uDisk = samples.get1D(PathSamples::SunDisk);
                EnvironmentSample s = daylight_->sampleSun(uDisk, samples.get2D(PathSamples::SunPoint));
                addLight(s.wi, s.Le, s.pdf, kInf, -1, LightBudget::kSun);
            }
            if (sky) {
                SkyLight::View& view = views[current];
                if (depth == 0) sky_.viewFromSensor(v.p, view);
                else sky_.view(v.p, view);
                EnvironmentSample s = sky_.sample(view, v.p, samples.get2D(PathSamples::SkyPoint));
                addLight(s.wi, s.Le, s.pdf, kInf, -1, LightBudget::kSky);
            }
        }

        // ---- choose the next direction ----
        Vec3 d, weight;
        double pdf = 0;
        bool delta = false;
        if (!v.isSurface()) {
            // A delta sensor draws no random numbers for its one direction.
            SensorSample s = sensor.isDelta() ? sensor.sample({0, 0}) : sensor.sample(samples.get2D(PathSamples::Direction));
            d = s.wi, weight = Vec3(s.weight, s.weight, s.weight), pdf = s.pdf, delta = s.delta;
        } else {
            const double uLobe = samples.get1D(PathSamples::Lobe);
            auto s = v.bsdf->sample(v.wo, uLobe, samples.get2D(PathSamples::Direction));
            if (!s) break;
            d = v.shading.toWorld(s->wi);
            // Reflection must stay on the arrival side of the geometric surface and
            // transmission cross it (as evalCos() requires of light samples).
            if (s->isTransmission ? dot(d, v.ng) >= 0 : dot(d, v.ng) <= 0) break;
            weight = s->weight, pdf = s->pdf, delta = s->isDelta;
        }
        throughput = throughput * weight;
        if (maxComponent(throughput) <= 0) break;
        if (depth == 0) firstWeight = maxComponent(throughput);
        if (!delta) {
            lastPdf = pdf;
            lastPoint = v.p;
            if (sky) current ^= 1;  // views[current ^ 1] is now the last non-delta vertex's
        }
        lastDelta = delta;

        // ---- Russian roulette ----
        if (depth >= options_.rouletteDepth) {
            double q = std::min(0.95, maxComponent(throughput) / firstWeight);
            if (samples.get1D(PathSamples::Roulette) >= q) break;
            throughput = throughput * (1 / q);
        }

        // ---- follow the ray, passing through glass panes ----
        Vec3 o = spawn(v, d);
        bool scattered = false;
        for (int crossings = 0; crossings < 32 && !scattered; ++crossings) {
            ++stats.closest;
            auto hit = rt_.intersect({o, d});
            if (stats.footprint) stats.footprint->add(o, d, 0, hit ? hit->t : kInf);
            if (!hit) {
                if (daylight_) {
                    // Depth 0 is the sensor's own ray, through panes and off mirrors.
                    const bool hidden = depth == 0 && sensor.hidesSources();
                    Vec3 sky = daylight_->Le(d), sun = hidden ? Vec3() : daylight_->sunLe(d);
                    double wSky = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, sky_.pdf(views[current ^ 1], lastPoint, d));
                    double wSun = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, daylight_->sunPdf(d));
                    L += throughput * (sky * wSky + sun * wSun);
                    if (stats.budget) {
                        stats.budget->credit(LightBudget::kSky, depth, luminance(throughput * sky * wSky));
                        stats.budget->credit(LightBudget::kSun, depth, luminance(throughput * sun * wSun));
                    }
                }
                return luminance(L);
            }
            if (hit->kind == HitKind::Emitter) {
                if (hitEmitterFirst && depth == 0 && crossings == 0) *hitEmitterFirst = true;
                if (stats.footprint) stats.footprint->usedEmitterChoice = true;  // the MIS weight reads it
                double Le = depth == 0 && sensor.hidesSources() ? 0.0 : emitters_.emitted(size_t(hit->index), d);
                if (Le > 0) {
                    double w = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, emitters_.pdf(size_t(hit->index), lastPoint, hit->point));
                    L += throughput * Vec3(Le, Le, Le) * w;
                    if (stats.budget) stats.budget->credit(hit->index, depth, luminance(throughput * Vec3(Le, Le, Le) * w));
                }
                return luminance(L);  // emitters absorb what reaches them
            }
            const Bsdf& bsdf = bsdfs_[hit->material];
            if (bsdf.passesStraight()) {
                // A thin pane: pass straight through (not a scattering event, so the MIS
                // state of the last vertex stays) or reflect (a delta event).
                const PaneResponse r = bsdf.glass().response(std::abs(dot(d, hit->geometricNormal)));
                double scatter = r.reflectance + r.transmittance;
                if (scatter <= 0) return luminance(L);
                throughput = throughput * scatter;
                if (samples.rng().uniform() * scatter < r.transmittance) {
                    o = offsetAlong(hit->point, hit->geometricNormal, d);
                } else {
                    d = reflect(-d, hit->geometricNormal);
                    o = offsetAlong(hit->point, hit->geometricNormal, d);
                    lastDelta = true;
                }
                continue;
            }
            // A scattering surface: the next vertex. Surfaces are two-sided.
            v = Vertex();
            v.p = hit->point;
            v.bsdf = &bsdf;
            Vec3 wo = -d;
            v.ng = dot(hit->geometricNormal, wo) >= 0 ? hit->geometricNormal : -hit->geometricNormal;
            Vec3 ns = dot(hit->shadingNormal, v.ng) >= 0 ? hit->shadingNormal : -hit->shadingNormal;
            v.shading = Frame::fromNormal(ns);
            v.wo = v.shading.toLocal(wo);
            if (v.wo.z <= 0) v.wo = normalize(Vec3(v.wo.x, v.wo.y, 1e-6));  // shading normal tilted away
            scattered = true;
        }
        if (!scattered) break;
    }
    return luminance(L);
}

}  // namespace luxplan
