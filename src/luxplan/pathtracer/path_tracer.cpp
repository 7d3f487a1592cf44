#include <luxplan/pathtracer/path_tracer.h>

#include <algorithm>
#include <atomic>

#include <luxplan/core/warp.h>
#include <luxplan/scene/room.h>

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
    const Bsdf* bsdf = nullptr;
    int sensor = -1;  // SensorKind as int for sensors, -1 for surfaces
    Vec3 sensorNormal;

    bool isSurface() const { return bsdf != nullptr; }
};

}  // namespace

PathTracer::PathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, const PathTracerOptions& options)
    : rt_(rt), daylight_(daylight), options_(options) {
    static std::atomic<uint64_t> nextId{1};
    id_ = nextId++;
    for (const Material& m : rt.scene().materials) bsdfs_.push_back(makeBsdf(m));
    if (const RoomShell* room = rt.scene().room()) {
        hasRoom_ = true;
        // Hit points on the shell lie on the box boundary, half of them a float ulp
        // outside: a millimetre of slack keeps them on the portal side.
        room_ = Bounds3(room->box.lo - Vec3(1e-3, 1e-3, 1e-3), room->box.hi + Vec3(1e-3, 1e-3, 1e-3));
        for (const Opening& o : room->openings) {
            WallFrame f = wallFrame(room->box, o.wall);
            auto r = openingRect(room->box, o);
            portals_.push_back({f.origin + f.u * r[0] + f.v * r[1], f.u * (r[2] - r[0]), f.v * (r[3] - r[1])});
            portalNormals_.push_back(cross(portals_.back().edgeU, portals_.back().edgeV));
        }
    }
    updateLayout();
}

void PathTracer::updateLayout() {
    std::vector<Transform> world(rt_.scene().entities.size());
    for (size_t i = 0; i < world.size(); ++i) world[i] = rt_.worldFromEntity(int(i));
    emitters_ = EmitterSet(rt_.scene(), world, options_.emitterSelection);
}

void PathTracer::viewPortals(const Vec3& p, PortalView& view) const {
    // Every path of a sampler point starts at the same place: keep the last view of
    // each thread (measureSamplers runs a point's paths on one thread in a row).
    thread_local uint64_t cachedTracer = 0;
    thread_local PortalView cachedView;
    if (cachedTracer != id_ || !(cachedView.point == p)) {
        computePortals(p, cachedView, true);
        cachedTracer = id_;
    }
    view = cachedView;
}

void PathTracer::computePortals(const Vec3& p, PortalView& view, bool buildAll) const {
    view.active = options_.portals && hasRoom_ && !portals_.empty() && room_.contains(p);
    view.point = p;
    view.count = 0;
    view.weightTotal = 0;
    if (!view.active) return;
    for (const Rect3& r : portals_) {
        if (view.count == kMaxPortals) break;
        const int i = view.count++;
        // Area x cos / d^2 = |n . d| / d^3 with n = edgeU x edgeV (|n| = area).
        Vec3 d = r.corner + (r.edgeU + r.edgeV) * 0.5 - p;
        double d2 = dot(d, d);
        double w = d2 > 0 ? std::abs(dot(portalNormals_[size_t(i)], d)) / (d2 * std::sqrt(d2)) : 2 * kPi;
        view.weight[i] = std::min(w, 2 * kPi);
        view.weightTotal += view.weight[i];
        view.built[i] = false;
        if (buildAll) portalRect(view, i);
    }
}

const SphericalRect& PathTracer::portalRect(const PortalView& view, int i) const {
    if (!view.built[i]) {
        view.rects[i] = SphericalRect(portals_[size_t(i)], view.point);
        view.built[i] = true;
    }
    return view.rects[i];
}

// Inside the room every sky direction that can reach p passes through one opening, so
// sampling the openings' spherical rectangles wastes no samples on walls. Outside,
// the sky map's own importance sampling is used.
double PathTracer::skyPdf(const PortalView& view, const Vec3& p, const Vec3& w) const {
    if (!daylight_ || !daylight_->hasSky()) return 0;
    if (!view.active) return daylight_->skyPdf(w);
    if (view.weightTotal <= 0) return 0;
    for (int i = 0; i < view.count; ++i)
        if (view.weight[i] > 0 && portals_[size_t(i)].intersect(p, w) > 0) {
            double omega = portalRect(view, i).solidAngle();
            return omega > 0 ? view.weight[i] / view.weightTotal / omega : 0;
        }
    return 0;
}

EnvironmentSample PathTracer::sampleSky(const PortalView& view, const Vec3& p, Vec2 u) const {
    if (!view.active) return daylight_->sampleSky(u);
    EnvironmentSample s;
    if (view.weightTotal <= 0) return s;
    // Choose a portal by weight, reusing u.x within the chosen interval.
    double target = u.x * view.weightTotal, acc = 0;
    int chosen = -1;
    for (int i = 0; i < view.count; ++i) {
        if (view.weight[i] > 0 && target < acc + view.weight[i]) {
            chosen = i;
            u.x = std::min((target - acc) / view.weight[i], 1 - 1e-12);
            break;
        }
        acc += view.weight[i];
    }
    if (chosen < 0) return s;
    const SphericalRect& rect = portalRect(view, chosen);
    if (rect.solidAngle() <= 0) return s;
    Vec3 q = rect.sample(u);
    s.wi = normalize(q - p);
    s.Le = daylight_->Le(s.wi);
    s.pdf = view.weight[chosen] / view.weightTotal / rect.solidAngle();
    return s;
}

double PathTracer::transmittance(const Vec3& origin, const Vec3& w, double tMax, int target, RayStats& stats) const {
    // Opaque surfaces first, by an any-hit query. Towards an emitter, other luminaires
    // are not counted as blockers (and the target itself cannot shadow itself); towards
    // the sky and sun, luminaire bodies block.
    ++stats.shadow;
    unsigned blockers = kOpaqueMask | (target < 0 ? kEmitterMask : 0u);
    double opaqueEnd = target < 0 ? tMax : tMax * (1 - 1e-4);
    if (rt_.occluded({origin, w, 0, opaqueEnd, blockers})) return 0;
    if (!rt_.hasGlass()) return 1;
    // Then the panes in the way, one closest-hit query each.
    double T = 1, travelled = 0;
    Vec3 p = origin;
    for (int crossings = 0; crossings < 16; ++crossings) {
        ++stats.shadow;
        auto hit = rt_.intersect({p, w, 0, opaqueEnd - travelled, kGlassMask});
        if (!hit) return T;
        T *= bsdfs_[hit->material].straightTransmittance(std::abs(dot(w, hit->geometricNormal)));
        if (T <= 0) return 0;
        travelled += hit->t + kRayEpsilon;
        p = hit->point + w * kRayEpsilon;
    }
    return 0;
}

double PathTracer::illuminanceSample(const Vec3& p, const Vec3& n, Rng& rng, RayStats& stats) const {
    return trace(SensorKind::Hemisphere, p, n, rng, stats);
}
double PathTracer::sphericalLuminanceSample(const Vec3& p, Rng& rng, RayStats& stats) const {
    return trace(SensorKind::Sphere, p, Vec3(0, 0, 1), rng, stats);
}
double PathTracer::radianceSample(const Ray& ray, Rng& rng, RayStats& stats) const {
    return trace(SensorKind::Camera, ray.origin, ray.direction, rng, stats);
}
double PathTracer::radianceSample(const Ray& ray, Rng& rng, RayStats& stats, bool& hitEmitterFirst) const {
    hitEmitterFirst = false;
    return trace(SensorKind::Camera, ray.origin, ray.direction, rng, stats, &hitEmitterFirst);
}

double PathTracer::trace(SensorKind sensor, const Vec3& origin, const Vec3& n, Rng& rng, RayStats& stats,
                         bool* hitEmitterFirst) const {
    Vec3 L, throughput(1, 1, 1);
    Vertex v;
    v.p = origin;
    v.sensor = int(sensor);
    v.sensorNormal = n;

    // f * |cos| and the sampling pdf of the current vertex for a world direction.
    auto evalCos = [&](const Vertex& x, const Vec3& wi) -> Vec3 {
        if (!x.isSurface()) {
            if (x.sensor == int(SensorKind::Hemisphere)) {
                double c = dot(wi, x.sensorNormal);
                return c > 0 ? Vec3(c, c, c) : Vec3();
            }
            return Vec3(1, 1, 1) * (1 / (4 * kPi));  // sphere sensor
        }
        // Light must arrive on the side the path is on (no leaks through surfaces).
        if (dot(wi, x.ng) <= 0) return Vec3();
        Vec3 local = x.shading.toLocal(wi);
        return x.bsdf->eval(x.wo, local) * std::abs(local.z);
    };
    auto pdfOf = [&](const Vertex& x, const Vec3& wi) -> double {
        if (!x.isSurface())
            return x.sensor == int(SensorKind::Hemisphere) ? cosineHemispherePdf(dot(wi, x.sensorNormal))
                                                           : uniformSpherePdf();
        return x.bsdf->pdf(x.wo, x.shading.toLocal(wi));
    };
    auto spawn = [&](const Vertex& x, const Vec3& wi) { return x.isSurface() ? offsetAlong(x.p, x.ng, wi) : x.p; };

    bool lastDelta = false;
    double lastPdf = 0;
    Vec3 lastPoint = origin;
    const bool sky = daylight_ && daylight_->hasSky();
    PortalView views[2];  // this vertex's, and the last non-delta vertex's
    int current = 0;
    double firstWeight = 0;

    for (int depth = 0; depth < options_.maxDepth; ++depth) {
        bool deltaVertex = sensor == SensorKind::Camera && depth == 0 ? true : (v.isSurface() && v.bsdf->isDelta());

        // ---- next-event estimation (skipped at delta vertices) ----
        if (!deltaVertex) {
            auto addLight = [&](const Vec3& wi, const Vec3& Le, double lightPdf, double maxT, int target) {
                if (!(lightPdf > 0) || maxComponent(Le) <= 0) return;
                Vec3 f = evalCos(v, wi);
                if (maxComponent(f) <= 0) return;
                double T = transmittance(spawn(v, wi), wi, maxT, target, stats);
                if (T <= 0) return;
                double w = powerHeuristic(1, lightPdf, 1, pdfOf(v, wi));
                L += throughput * f * Le * (T * w / lightPdf);
            };
            if (!emitters_.empty()) {
                EmitterSample s = emitters_.sample(v.p, rng.uniform(), {rng.uniform(), rng.uniform()});
                if (s.pdf > 0 && s.Lv > 0) addLight(s.wi, Vec3(s.Lv, s.Lv, s.Lv), s.pdf, s.distance, s.emitter);
            }
            if (daylight_ && daylight_->hasSun()) {
                double uDisk = rng.uniform();
                EnvironmentSample s = daylight_->sampleSun(uDisk, {rng.uniform(), rng.uniform()});
                addLight(s.wi, s.Le, s.pdf, kInf, -1);
            }
            if (sky) {
                PortalView& view = views[current];
                if (depth == 0) viewPortals(v.p, view);
                else computePortals(v.p, view, false);
                EnvironmentSample s = sampleSky(view, v.p, {rng.uniform(), rng.uniform()});
                addLight(s.wi, s.Le, s.pdf, kInf, -1);
            }
        }

        // ---- choose the next direction ----
        Vec3 d, weight;
        double pdf = 0;
        bool delta = false;
        if (!v.isSurface()) {
            if (sensor == SensorKind::Camera) {
                d = normalize(n), weight = Vec3(1, 1, 1), delta = true;
            } else if (sensor == SensorKind::Hemisphere) {
                Vec3 local = sampleCosineHemisphere({rng.uniform(), rng.uniform()});
                d = Frame::fromNormal(n).toWorld(local);
                pdf = cosineHemispherePdf(local.z);
                weight = Vec3(kPi, kPi, kPi);  // cos / pdf
            } else {
                d = sampleUniformSphere({rng.uniform(), rng.uniform()});
                pdf = uniformSpherePdf();
                weight = Vec3(1, 1, 1);  // (1 / 4 pi) / pdf
            }
        } else {
            double uLobe = rng.uniform();
            auto s = v.bsdf->sample(v.wo, uLobe, {rng.uniform(), rng.uniform()});
            if (!s) break;
            d = v.shading.toWorld(s->wi);
            // Reflection must stay on the arrival side of the geometric surface.
            if (!s->isTransmission && dot(d, v.ng) <= 0) break;
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
            if (rng.uniform() >= q) break;
            throughput = throughput * (1 / q);
        }

        // ---- follow the ray, passing through glass panes ----
        Vec3 o = spawn(v, d);
        bool scattered = false;
        for (int crossings = 0; crossings < 32 && !scattered; ++crossings) {
            ++stats.closest;
            auto hit = rt_.intersect({o, d});
            if (!hit) {
                if (daylight_) {
                    Vec3 sky = daylight_->Le(d), sun = daylight_->sunLe(d);
                    double wSky = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, skyPdf(views[current ^ 1], lastPoint, d));
                    double wSun = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, daylight_->sunPdf(d));
                    L += throughput * (sky * wSky + sun * wSun);
                }
                return luminance(L);
            }
            if (hit->kind == HitKind::Emitter) {
                if (hitEmitterFirst && depth == 0 && crossings == 0) *hitEmitterFirst = true;
                double Le = emitters_.emitted(size_t(hit->index), d);
                if (Le > 0) {
                    double w = lastDelta ? 1 : powerHeuristic(1, lastPdf, 1, emitters_.pdf(size_t(hit->index), lastPoint, hit->point));
                    L += throughput * Vec3(Le, Le, Le) * w;
                }
                return luminance(L);  // emitters absorb what reaches them
            }
            const Bsdf& bsdf = bsdfs_[hit->material];
            if (bsdf.hasTransmission()) {
                // A thin pane: pass straight through (not a scattering event, so the MIS
                // state of the last vertex stays) or reflect (a delta event).
                const PaneResponse r = bsdf.glass().response(std::abs(dot(d, hit->geometricNormal)));
                double scatter = r.reflectance + r.transmittance;
                if (scatter <= 0) return luminance(L);
                throughput = throughput * scatter;
                if (rng.uniform() * scatter < r.transmittance) {
                    o = hit->point + d * kRayEpsilon;
                } else {
                    d = reflect(-d, hit->geometricNormal);
                    o = offsetAlong(hit->point, hit->geometricNormal, d);
                    lastDelta = true;
                }
                continue;
            }
            // An opaque surface: the next vertex. Surfaces are two-sided.
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
