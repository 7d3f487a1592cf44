#include <luxplan/pathtracer/path_tracer.h>

#include <algorithm>
#include <atomic>

#include <luxplan/core/warp.h>
#include <luxplan/pathtracer/light_strategies.h>

namespace luxplan {
namespace {

const SkyLight::View kNoView;  // before a vertex has sampled the sky

// The strategies, in the order they draw their numbers at a vertex.
const EmitterStrategy kEmitterLight;
const SunStrategy kSunLight;
const SkyStrategy kSkyLight;
const SunPatchStrategy kPatchLight;
const LightStrategy* const kStrategies[] = {&kEmitterLight, &kSunLight, &kSkyLight, &kPatchLight};

// `n` with its zero components +0. Touching parts (a lamp shade's four walls) have
// coincident faces: the same plane with opposite normals. A ray that meets the plane
// hits either face, as the order of the BVH of the moment decides, and turned to the
// side the path came from the two normals agree but in the signs of their zeros, which
// Frame::fromNormal reads (its basis turns half a turn). With +0 the path scatters the
// same whichever face it hit, and so a path kept by the path cache matches the one
// traced afresh after a move has rebuilt the BVH (incremental/path_cache.h).
Vec3 positiveZeros(const Vec3& n) { return n + Vec3(0, 0, 0); }  // -0 + 0 = +0

}  // namespace

Vertex surfaceVertex(const Hit& hit, const Bsdf& bsdf, const Vec3& wo) {
    Vertex v;
    v.p = hit.point;
    v.bsdf = &bsdf;
    v.ng = positiveZeros(dot(hit.geometricNormal, wo) >= 0 ? hit.geometricNormal : -hit.geometricNormal);
    Vec3 ns = positiveZeros(dot(hit.shadingNormal, v.ng) >= 0 ? hit.shadingNormal : -hit.shadingNormal);
    v.shading = Frame::fromNormal(ns);
    v.wo = v.shading.toLocal(wo);
    if (v.wo.z <= 0) v.wo = normalize(Vec3(v.wo.x, v.wo.y, 1e-6));  // shading normal tilted away
    return v;
}

PathTracer::PathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, const PathTracerOptions& options)
    : rt_(rt), daylight_(daylight), options_(options), sky_(rt.scene(), daylight, options.portals),
      // Glass inside the room would bend no beam but would have to be crossed one hit
      // at a time both ways; such scenes keep BSDF sampling alone for the patches.
      patches_(rt.scene(), options.sunPatches && daylight && daylight->hasSun() && !rt.hasGlass()),
      sunDisks_(options.openSunDisks ? OpenSunDisks(daylight, patches_) : OpenSunDisks()),
      panes_(rt.scene()) {
    for (const Material& m : rt.scene().materials) bsdfs_.push_back(makeBsdf(m));
    exteriorSun_ = options.exteriorSun && options.portals && daylight && daylight->hasSun() && daylight->hasSky() &&
                   !rt.hasGlass() && SkyStrategy::sunlitOutside(rt.scene(), *daylight, bsdfs_);
    updateLayout();
}

void PathTracer::updateLayout() {
    std::vector<Transform> world(rt_.scene().entities.size());
    for (size_t i = 0; i < world.size(); ++i) world[i] = rt_.worldFromEntity(int(i));
    emitters_ = EmitterSet(rt_.scene(), world, options_.emitterSelection);
    sealed_ = SealedBoxes(rt_.scene(), world, emitters_);
    static std::atomic<uint64_t> stamps{0};
    layoutStamp_ = ++stamps;
}

bool PathTracer::sealedAt(const Vec3& p, Vec3* exit) const {
    if (sealed_.empty()) return false;
    // A sampler's paths for one point come one after another on a thread: the answer
    // is kept for the point until the layout or the point changes.
    thread_local uint64_t stamp = 0;
    thread_local Vec3 point, way;
    thread_local bool answer = false;
    if (stamp != layoutStamp_ || !(point == p)) stamp = layoutStamp_, point = p, answer = sealed_.contain(p, way);
    if (exit) *exit = way;
    return answer;
}

double PathTracer::transmittance(const Vec3& origin, const Vec3& w, double tMax, int target, RayStats& stats,
                                 PathFootprint* footprint) const {
    // Opaque surfaces first, by an any-hit query. Luminaires block as a path sees
    // them (they absorb what reaches them): towards the sky and sun all of them do,
    // towards an emitter every other one. A ray to a flat emitter crosses its plane
    // once, at the sampled point (tMax); when float error moves that by far less than
    // the 1e-4 cut below, the others join the same query. Otherwise (a sphere, a point
    // near the plane) they are found by closest-hit queries that step past the target
    // itself: float error in Embree's hit of the target must not shadow it.
    ++stats.shadow;
    bool frontOnFlat = false;
    if (target >= 0 && emitters_[size_t(target)].normal) {
        // The cut across the plane, 1e-4 of the distance to it, against Embree's float
        // copy of the plane: at least 8 float ulps of the coordinates' magnitude.
        const double across = tMax * std::abs(dot(w, *emitters_[size_t(target)].normal));
        const double magnitude = std::max({1.0, std::abs(origin.x), std::abs(origin.y), std::abs(origin.z)});
        frontOnFlat = across > 1e-2 * magnitude;
    }
    const bool stepPastTarget = target >= 0 && emitters_.size() > 1 && !frontOnFlat;
    const unsigned blockers = kOpaqueMask | (target < 0 || frontOnFlat ? kEmitterMask : 0u);
    double opaqueEnd = target < 0 ? tMax : tMax * (1 - 1e-4);
    // The emitter steps below run along this segment; the pane crossings add their own.
    const bool blocked = rt_.occluded({origin, w, 0, opaqueEnd, blockers});
    if (footprint) footprint->addOcclusion(origin, w, 0, opaqueEnd, blockers, blocked);
    if (blocked) return 0;
    if (stepPastTarget) {
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
        auto hit = rt_.intersect({p, w, 0, left, kGlassMask, crossings > 0});
        if (footprint) footprint->add(p, w, 0, hit ? hit->t : left);
        if (!hit) return T;
        T *= bsdfs_[hit->material].straightTransmittance(std::abs(dot(w, hit->geometricNormal)));
        if (T <= 0) return 0;
        p = offsetAlong(hit->point, hit->geometricNormal, w);
    }
    return 0;
}


double PathTracer::directSun(const Sensor& sensor, const Vec3& towardsSun, RayStats& stats, PathFootprint* footprint) const {
    // The whole ray in the footprint, whatever the answer: what moves onto it may change
    // it (a desk over the point seals it, a chair shades it).
    if (footprint) footprint->add(sensor.position(), towardsSun, 0, kInf);
    if (sensor.hidesSources() || sealedAt(sensor.position())) return 0;
    const double response = sensor.response(towardsSun);
    if (!(response > 0)) return 0;
    const Vec3 from = sensor.position() + towardsSun * kRayEpsilon;  // as a sensor's rays leave it
    if (patches_.shadedByShell(from, towardsSun)) return 0;
    return response * transmittance(from, towardsSun, kInf, -1, stats);
}

double PathTracer::otherSunDensity(const Path& path, const Vec3& ws) const {
    return path.outsideDensity + kPatchLight.pdf(path, ws, nullptr);
}

void PathTracer::connect(Path& path, const LightSample& s) const {
    bool skyLater = s.skyLater;
    if (!(s.pdf > 0) || (!skyLater && maxComponent(s.Le) <= 0)) return;
    const Vertex& v = path.v;
    const Vec3 f = path.evalCos(v, s.wi);
    if (maxComponent(f) <= 0) return;
    if (s.throughShell && patches_.shadedByShell(path.spawn(v, s.wi), s.wi)) return;
    // The light samples' roulette (PathParams::lightFloor), at surface vertices: a
    // sensor's own samples count in its cells, on another scale.
    Vec3 Le = s.Le;
    double survival = 1;
    if (path.lightFloor > 0 && v.isSurface()) {
        if (skyLater) Le = daylight_->Le(s.wi), skyLater = false;
        const double c = luminance(path.throughput * f * Le) / s.pdf;
        if (c < path.lightFloor) {
            survival = c / path.lightFloor;
            if (!(path.samples.rng().uniform() < survival)) return;
        }
    }
    double T = transmittance(path.spawn(v, s.wi), s.wi, v.isSurface() ? s.maxT : s.maxT - kRayEpsilon, s.target, path.stats,
                             path.params.footprint);
    if (T <= 0) return;
    T /= survival;
    if (skyLater) Le = daylight_->Le(s.wi);
    StrategyDensities d;
    d.light = s.pdf, d.bsdf = path.pdfOf(v, s.wi);
    // The sun's and the sky's light at a vertex a two-bounce strategy could reach.
    if (s.source == LightBudget::kSun && path.arrivalDensity > 0) {
        const double b = otherSunDensity(path, s.wi);
        if (b > 0) d.arrival = path.arrivalDensity, d.twoBounce = b, d.twoBounceLight = s.pdf * path.sunOpen;
    } else if (s.source == LightBudget::kSky && path.outsideDensity > 0) {
        d.arrival = path.arrivalDensity, d.twoBounce = path.outsideDensity, d.twoBounceLight = s.pdf;
    }
    path.add(s.wi, path.throughput * f * Le * (T * misWeight(Strategy::Light, d) / s.pdf), s.source, path.depth);
}

void PathTracer::estimateDirect(Path& path) const {
    const Vertex& v = path.v;
    // The portals' view first: whether the sky's sample goes outside decides whether
    // the sun strategy draws a sample for it.
    path.view = nullptr;
    if (sky_.active()) {
        if (path.depth == 0) {
            path.views[path.current] = &sky_.viewFromSensor(v.p);
        } else {
            sky_.view(v.p, path.scratch[path.current]);
            path.views[path.current] = &path.scratch[path.current];
        }
        path.view = path.views[path.current];
    }
    // A sensor draws no light sample it cannot see (the estimate is unchanged).
    path.skyHere = path.view && (v.isSurface() || sky_.seenBy(*path.view, path.sensor));
    path.outside = path.skyHere && exteriorSun_ && path.view->active;
    path.sunHere = v.isSurface() || path.sensorSeesSun;
    path.sunAtZ = EnvironmentSample();
    for (const LightStrategy* strategy : kStrategies) strategy->sample(path);
}

bool PathTracer::scatter(Path& path, Vec3& d) const {
    const Vertex& v = path.v;
    Vec3 weight;
    double pdf = 0;
    bool delta = false;
    if (!v.isSurface()) {
        // A delta sensor draws no random numbers for its one direction.
        const Sensor& sensor = path.sensor;
        SensorSample s = sensor.isDelta() ? sensor.sample({0, 0}) : sensor.sample(path.samples.get2D(PathSamples::Direction));
        d = s.wi, weight = Vec3(s.weight, s.weight, s.weight), pdf = s.pdf, delta = s.delta;
    } else {
        const double uLobe = path.samples.get1D(PathSamples::Lobe);
        auto s = v.bsdf->sample(v.wo, uLobe, path.samples.get2D(PathSamples::Direction));
        if (!s) return false;
        d = v.shading.toWorld(s->wi);
        // Reflection must stay on the arrival side of the geometric surface and
        // transmission cross it (as evalCos() requires of light samples).
        if (s->isTransmission ? dot(d, v.ng) >= 0 : dot(d, v.ng) <= 0) return false;
        weight = s->weight, pdf = s->pdf, delta = s->isDelta;
    }
    path.throughput = path.throughput * weight;
    if (maxComponent(path.throughput) <= 0) return false;
    if (path.depth == 0) path.firstWeight = maxComponent(path.throughput);
    if (!delta) {
        path.lastPdf = pdf;
        path.lastSunOpen = path.sunOpen;
        path.lastPoint = v.p;
        path.lastAtSensor = !v.isSurface();
        path.lastPatched = SunPatchStrategy::samplesAt(path);
        if (path.lastPatched) path.lastOrigin = {v.p, v.ng, v.bsdf->hasDiffuseTransmission(), true};
        path.lastOutside = exteriorSun_ && path.views[path.current]->active;
        if (sky_.active()) path.current ^= 1;  // views[current ^ 1] is now the last non-delta vertex's
    }
    path.lastDelta = delta;

    // Russian roulette: the path goes on with probability min(0.95, throughput / (level
    // x the first vertex's)).
    if (path.depth >= options_.rouletteDepth) {
        double q = std::min(0.95, maxComponent(path.throughput) / (options_.rouletteLevel * path.firstWeight));
        if (path.samples.get1D(PathSamples::Roulette) >= q) return false;
        path.throughput = path.throughput * (1 / q);
    }
    return true;
}

void PathTracer::addEscaped(Path& path, const Vec3& d) const {
    if (!daylight_) return;
    // Depth 0 is the sensor's own ray, through panes and off mirrors.
    const bool hidden = path.depth == 0 && path.sensor.hidesSources();
    const Vec3 sky = daylight_->Le(d), sun = hidden ? Vec3() : daylight_->sunLe(d);
    double wSky = 1;
    if (!path.lastDelta) {
        StrategyDensities s;
        s.light = kSkyLight.pdf(path, d, nullptr), s.bsdf = path.lastPdf;
        if (path.outsideDensity > 0) s.arrival = path.arrivalDensity, s.twoBounce = path.outsideDensity, s.twoBounceLight = s.light;
        wSky = misWeight(Strategy::Bsdf, s);
    }
    double wSun = 1;
    if (!path.lastDelta && maxComponent(sun) > 0) {
        StrategyDensities s;
        s.light = kSunLight.pdf(path, d, nullptr), s.bsdf = path.lastPdf;
        const double b = path.arrivalDensity > 0 ? otherSunDensity(path, d) : 0;
        if (b > 0) s.arrival = path.arrivalDensity, s.twoBounce = b, s.twoBounceLight = daylight_->sunPdf(d);
        wSun = misWeight(Strategy::Bsdf, s);
    }
    path.L += path.throughput * (sky * wSky + sun * wSun);
    if (path.params.budget) {
        path.params.budget->credit(LightBudget::kSky, path.depth, luminance(path.throughput * sky * wSky));
        path.params.budget->credit(LightBudget::kSun, path.depth, luminance(path.throughput * sun * wSun));
    }
    if (path.params.daylight) {
        path.params.daylight->add(LightBudget::kSky, d, path.depth, luminance(path.throughput * sky * wSky));
        path.params.daylight->add(LightBudget::kSun, d, path.depth, luminance(path.throughput * sun * wSun));
    }
}

void PathTracer::addEmitterHit(Path& path, const Hit& hit, const Vec3& d) const {
    if (path.params.footprint) path.params.footprint->usedEmitterChoice = true;  // the MIS weight reads it
    const double Le = path.depth == 0 && path.sensor.hidesSources() ? 0.0 : emitters_.emitted(size_t(hit.index), d);
    if (!(Le > 0)) return;
    double w = 1;
    if (!path.lastDelta) {
        StrategyDensities s;
        s.light = kEmitterLight.pdf(path, d, &hit), s.bsdf = path.lastPdf;
        w = misWeight(Strategy::Bsdf, s);
    }
    path.L += path.throughput * Vec3(Le, Le, Le) * w;
    if (path.params.budget) path.params.budget->credit(hit.index, path.depth, luminance(path.throughput * Vec3(Le, Le, Le) * w));
}

bool PathTracer::follow(Path& path, Vec3 d, bool* hitEmitterFirst) const {
    Vertex& v = path.v;
    Vec3 o = path.spawn(v, d);
    path.seeThrough = path.seeThrough || (v.isSurface() && v.bsdf->hasDiffuseTransmission());
    for (int crossings = 0; crossings < 32; ++crossings) {
        ++path.stats.closest;
        auto hit = rt_.intersect({o, d, 0, kInf, kAllMask, path.seeThrough});
        if (path.params.footprint) path.params.footprint->add(o, d, 0, hit ? hit->t : kInf);
        if (!hit) {
            addEscaped(path, d);
            return false;
        }
        if (hit->kind == HitKind::Emitter) {
            if (hitEmitterFirst && path.depth == 0 && crossings == 0) *hitEmitterFirst = true;
            addEmitterHit(path, *hit, d);
            return false;  // emitters absorb what reaches them
        }
        const Bsdf& bsdf = bsdfs_[hit->material];
        if (bsdf.passesStraight()) {
            // A thin pane: pass straight through (not a scattering event, so the MIS
            // state of the last vertex stays) or reflect (a delta event).
            const PaneResponse r = bsdf.glass().response(std::abs(dot(d, hit->geometricNormal)));
            double scatter = r.reflectance + r.transmittance;
            if (scatter <= 0) return false;
            path.throughput = path.throughput * scatter;
            if (path.samples.rng().uniform() * scatter < r.transmittance) {
                o = offsetAlong(hit->point, hit->geometricNormal, d);
            } else {
                d = reflect(-d, hit->geometricNormal);
                o = offsetAlong(hit->point, hit->geometricNormal, d);
                path.lastDelta = true;
            }
            path.seeThrough = true;
            continue;
        }
        // A scattering surface: the next vertex. Surfaces are two-sided.
        v = surfaceVertex(*hit, bsdf, -d);
        path.arrivalDensity = path.outsideDensity = 0;
        path.arrivalFrom.valid = false;
        if (!path.lastDelta && (path.lastPatched || path.lastOutside)) {
            const Vec3 e = v.p - path.lastPoint;
            const double d2 = dot(e, e);
            if (d2 > 0) {
                const double toArea = std::abs(dot(v.ng, d)) / d2;
                path.arrivalDensity = path.lastPdf * toArea;
                if (path.lastPatched) path.arrivalFrom = path.lastOrigin;
                if (path.lastOutside && !sky_.inRoom(v.p)) path.outsideDensity = kSkyLight.pdf(path, d, nullptr) * toArea;
            }
        }
        return true;
    }
    return false;
}

double PathTracer::sample(const Sensor& sensor, PathSamples& samples, RayStats& stats, const PathParams& params,
                          bool* hitEmitterFirst, SensorLight* sensorLight) const {
    if (sensorLight) sensorLight->count = 0;
    const Vec3 origin = sensor.position();
    if (Vec3 exit; sealedAt(origin, &exit)) {
        // Its value depends on the box around it and on the luminaires (one might move
        // into the box): the way out to the box's face meets the box's triangles, so
        // the path cache traces it again when the box moves, and when a luminaire does.
        if (params.footprint) {
            params.footprint->add(origin, exit - origin, 0, 1);
            params.footprint->usedEmitterChoice = !emitters_.empty();
        }
        return 0;
    }
    thread_local SkyLight::View scratch[2];
    Path path(*this, sensor, samples, stats, params, sensorLight);
    path.v.p = path.lastPoint = origin;
    path.views[0] = path.views[1] = &kNoView;
    path.scratch = scratch;
    path.sensorSeesSun = daylight_ && daylight_->hasSun() && sensor.maySee(daylight_->sunConeAxis(), daylight_->sunConeCos());
    for (size_t i = 0; i < emitters_.size() && !path.sensorSeesEmitters; ++i) {
        // The cone round the sphere that holds the luminaire (all of it, from within).
        const Vec3 toCentre = emitters_[i].center - origin;
        const double distance = length(toCentre), reach = emitters_[i].reach;
        path.sensorSeesEmitters = !(distance > reach) ||
                                  sensor.maySee(toCentre / distance, std::sqrt(1 - (reach / distance) * (reach / distance)));
    }
    // Next-event estimation at every non-delta vertex, BSDF sampling to the next.
    for (; path.depth < options_.maxDepth; ++path.depth) {
        samples.setDepth(path.depth);
        const bool deltaVertex = path.v.isSurface() ? path.v.bsdf->isDelta() : sensor.isDelta();
        path.sunOpen = 1;
        if (!deltaVertex) estimateDirect(path);
        Vec3 d;
        if (!scatter(path, d) || !follow(path, d, hitEmitterFirst)) break;
    }
    return luminance(path.L);
}

}  // namespace luxplan
