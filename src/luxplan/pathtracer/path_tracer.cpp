#include <luxplan/pathtracer/path_tracer.h>

#include <algorithm>
#include <atomic>
#include <optional>

#include <luxplan/core/warp.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/scene/room.h>

namespace luxplan {
namespace {

constexpr double kRayEpsilon = 1e-4;  // metres; scenes are rooms, not microns

const SkyLight::View kNoView;  // before a vertex has sampled the sky

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

// A surface vertex where the sunlit patches were sampled, as the MIS weights of the
// paths it continues need it: the strategy skips the beams whose far end (SunPatches::
// beamEnd) lies behind an opaque vertex's surface, without tracing them.
struct PatchOrigin {
    Vec3 p, ng;
    bool translucent = false;
    bool valid = false;  // the path arrived from a vertex where the patches were sampled
    bool faces(const Vec3& beamEnd) const { return translucent || dot(ng, beamEnd - p) > 0; }
};

// `n` with its zero components +0. Touching parts (a lamp shade's four walls) have
// coincident faces: the same plane with opposite normals. A ray that meets the plane
// hits either face, as the order of the BVH of the moment decides, and turned to the
// side the path came from the two normals agree but in the signs of their zeros, which
// Frame::fromNormal reads (its basis turns half a turn). With +0 the path scatters the
// same whichever face it hit, and so a path kept by the path cache matches the one
// traced afresh after a move has rebuilt the BVH (lightsamplers/path_cache.h).
Vec3 positiveZeros(const Vec3& n) { return n + Vec3(0, 0, 0); }  // -0 + 0 = +0

// The vertex at a surface hit, seen from direction wo (unit, away from the surface).
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

// The power heuristic for the sun's light at a vertex y reached from a surface vertex
// x, among three strategies for the same path x -> y -> sun: BSDF sampling at x then
// the sun sampled at y (densities a * pSunAtY), the sunlit patch sampled from x (b *
// pSun, the period's own density: the patch draws its sun from all the disks), BSDF
// sampling at x then at y (a * pBsdf), with a the area density of x's BSDF sample at y
// and b the patch's (sun_patches.h). pSunAtY is y's own sun density, which counts only
// the disks the shell lets through from y (open_sun_disks.h). `own` is the numerator's
// pair. The same for the sky's light at a surface outside the room, with the portal's
// density as b and the sky's as both light densities.
double sunWeight(double ownFirst, double ownSecond, double a, double b, double pSunAtY, double pSun, double pBsdf) {
    const double own = ownFirst * ownSecond;
    const double sum = (a * pSunAtY) * (a * pSunAtY) + (b * pSun) * (b * pSun) + (a * pBsdf) * (a * pBsdf);
    return sum > 0 ? own * own / sum : 0;
}

// Whether the sun may light a visible static surface outside the room's box (a
// millimetre of slack) on a side that an opening sees: for some triangle outside,
// some corner of an opening the sky is sampled through and some sun disk on the
// same side of its plane (either side for a translucent surface, the outer side for a
// box). Without one the outside strategy finds nothing (the morning sun on the far
// side of a facade).
bool sunlitOutside(const Scene& scene, const DaylightEnvironment& daylight, const std::vector<Bsdf>& bsdfs) {
    const RoomShell* room = scene.room();
    if (!room) return false;
    std::vector<Vec3> corners;
    for (const Opening& o : room->openings) {
        if (o.material && !bsdfs[*o.material].passesStraight()) continue;
        const Rect3 r = openingQuad(room->box, o);
        for (const Vec3& c : {r.corner, r.corner + r.edgeU, r.corner + r.edgeV, r.corner + r.edgeU + r.edgeV}) corners.push_back(c);
    }
    const Bounds3 box(room->box.lo - Vec3(1e-3, 1e-3, 1e-3), room->box.hi + Vec3(1e-3, 1e-3, 1e-3));
    for (const StaticItem& item : scene.geometry) {
        if (item.room || item.invisible) continue;
        const TriangleMesh& mesh = item.mesh;
        const bool closed = item.kind == StaticKind::Box;  // wound outwards: its inner side is never seen
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
            if (box.contains(a) && box.contains(b) && box.contains(c)) continue;
            const Vec3 n = cross(b - a, c - a);
            bool seen[2] = {false, false}, lit[2] = {false, false};  // [front, back]
            for (const Vec3& corner : corners) {
                const double side = dot(n, corner - a);
                if (side != 0) seen[side > 0 ? 0 : 1] = true;
            }
            const double rim = length(n) * std::sin(kSunHalfAngle);  // a disk's edge reaches past its centre
            for (const SunDisk& disk : daylight.sunDisks()) {
                const double side = dot(n, disk.direction);
                lit[0] = lit[0] || side > -rim;
                lit[1] = lit[1] || side < rim;
            }
            const bool translucent = bsdfs[mesh.materials[t]].hasDiffuseTransmission();
            if (translucent ? (seen[0] || seen[1]) && (lit[0] || lit[1]) : (seen[0] && lit[0]) || (!closed && seen[1] && lit[1]))
                return true;
        }
    }
    return false;
}

}  // namespace

PathTracer::PathTracer(const EmbreeScene& rt, const DaylightEnvironment* daylight, const PathTracerOptions& options)
    : rt_(rt), daylight_(daylight), options_(options), sky_(rt.scene(), daylight, options.portals),
      // Glass inside the room would bend no beam but would have to be crossed one hit
      // at a time both ways; such scenes keep BSDF sampling alone for the patches.
      patches_(rt.scene(), options.sunPatches && daylight && daylight->hasSun() && !rt.hasGlass()),
      sunDisks_(options.openSunDisks ? OpenSunDisks(daylight, patches_) : OpenSunDisks()),
      panes_(rt.scene()) {
    for (const Material& m : rt.scene().materials) bsdfs_.push_back(makeBsdf(m));
    exteriorSun_ = options.exteriorSun && options.portals && daylight && daylight->hasSun() && daylight->hasSky() &&
                   !rt.hasGlass() && sunlitOutside(rt.scene(), *daylight, bsdfs_);
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

double PathTracer::transmittance(const Vec3& origin, const Vec3& w, double tMax, int target, RayStats& stats) const {
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
    if (stats.footprint) stats.footprint->addOcclusion(origin, w, 0, opaqueEnd, blockers, blocked);
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
    const double lightFloor = samples.lightFloor();
    const Vec3 origin = sensor.position();
    if (Vec3 exit; sealedAt(origin, &exit)) {
        // Its value depends on the box around it and on the luminaires (one might move
        // into the box): the way out to the box's face meets the box's triangles, so
        // the path cache traces it again when the box moves, and when a luminaire does.
        if (stats.footprint) {
            stats.footprint->add(origin, exit - origin, 0, 1);
            stats.footprint->usedEmitterChoice = !emitters_.empty();
        }
        return 0;
    }
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

    // A light sample the sensor cannot see adds nothing: none is drawn (a glare
    // frustum facing away from the sun and the windows).
    const bool sensorSeesSun = daylight_ && daylight_->hasSun() && sensor.maySee(daylight_->sunConeAxis(), daylight_->sunConeCos());
    bool sensorSeesEmitters = false;
    for (size_t i = 0; i < emitters_.size() && !sensorSeesEmitters; ++i) {
        // The cone round the sphere that holds the luminaire (all of it, from within).
        const Vec3 toCentre = emitters_[i].center - origin;
        const double distance = length(toCentre), reach = emitters_[i].reach;
        sensorSeesEmitters = !(distance > reach) ||
                             sensor.maySee(toCentre / distance, std::sqrt(1 - (reach / distance) * (reach / distance)));
    }
    bool lastDelta = false;
    double lastPdf = 0;
    // The share of the sun's disks open from this vertex and the last non-delta one
    // (OpenSunDisks; 1 where no sun sample was asked for: no sun light can come there).
    double sunOpen = 1, lastSunOpen = 1;
    Vec3 lastPoint = origin;
    bool lastAtSensor = true;  // lastPoint is the sensor's (its emitter view applies)
    const bool sky = sky_.active();
    // This vertex's view of the sky's portals and the last non-delta vertex's. A View
    // is large (16 spherical rectangles): a path neither zeroes nor copies one. The
    // sensor's is its thread's cached view, a surface's is set up in this thread's scratch.
    thread_local SkyLight::View scratch[2];
    const SkyLight::View* views[2] = {&kNoView, &kNoView};
    int current = 0;
    double firstWeight = 0;
    // The area density at the current vertex of the BSDF sample that reached it from a
    // surface vertex where the sunlit patches were sampled (0 otherwise): the patch
    // strategy could have made the same path, and the sun's MIS weights count it.
    double arrivalDensity = 0;
    PatchOrigin arrivalFrom, lastOrigin;
    bool lastPatched = false;
    // The patch strategy's area density at patch point y (normal ng) for sun direction
    // ws, had it been sampled from `from`.
    auto patchDensity = [&](const PatchOrigin& from, const Vec3& y, const Vec3& ng, const Vec3& ws) {
        return from.faces(patches_.beamEnd(y, -ws)) ? patches_.density(y, ng, ws) : 0.0;
    };
    // The same for the sunlit surfaces outside: at a vertex outside the room reached
    // through an opening, the area density with which the last vertex's portal sample
    // could have reached it (0 otherwise; never non-zero where a patch's is, which
    // lies in the room). lastOutside: the last non-delta vertex took that strategy.
    double outsideDensity = 0;
    bool lastOutside = false;
    // The density at this vertex of the other way to its sun light, a sunlit patch or a
    // surface outside (0: BSDF sampling and the sun's own sampling only).
    auto otherSunDensity = [&](const Vec3& ws) {
        return outsideDensity + (arrivalFrom.valid ? patchDensity(arrivalFrom, v.p, v.ng, ws) : 0.0);
    };

    // The sunlit patches (sun_patches.h): one patch point y per path, drawn at the first
    // surface vertex (a sun direction, a point of an opening, the sunbeam through it to
    // y) and connected to every later surface vertex that faces the beam, each
    // connection weighed against the two BSDF ways to the same path (sunWeight). Every
    // vertex's estimate is unbiased on its own, since y is drawn independently of the
    // path; drawing it once costs the beam and y's view of the sun once per path.
    struct PatchLight {
        bool drawn = false, traced = false, lit = false;
        EnvironmentSample sun;
        Vec3 entry, beamEnd;
        std::optional<Hit> hit;
        double density = 0, toSun = -1;  // toSun < 0: not asked yet
        double openAtY = 0;  // the open disks' share at y (OpenSunDisks), once asked
    } patch;
    int depth = 0;
    auto patchesHere = [&]() { return patches_.active() && v.isSurface(); };
    auto addSunPatch = [&]() {
        if (!patch.drawn) {
            patch.drawn = true;
            const double uDisk = samples.get1D(PathSamples::PatchSunDisk);
            patch.sun = daylight_->sampleSun(uDisk, samples.get2D(PathSamples::PatchSunPoint));
            const Vec2 uEntry = samples.get2D(PathSamples::PatchEntry);
            patch.lit = patch.sun.pdf > 0 && patches_.sampleEntry(patch.sun.wi, uEntry, patch.entry);
            if (patch.lit) patch.beamEnd = patches_.beamEnd(patch.entry, -patch.sun.wi);
        }
        if (!patch.lit) return;
        const PatchOrigin here{v.p, v.ng, v.bsdf->hasDiffuseTransmission()};
        if (!here.faces(patch.beamEnd)) return;
        const Vec3 ws = patch.sun.wi;
        if (!patch.traced) {
            patch.traced = true;
            ++stats.closest;
            patch.hit = rt_.intersect({patch.entry, -ws, 0, kInf, kOpaqueMask | kEmitterMask});
            if (stats.footprint) stats.footprint->add(patch.entry, -ws, 0, patch.hit ? patch.hit->t : kInf);
            const Hit* h = patch.hit ? &*patch.hit : nullptr;
            patch.lit = h && h->kind != HitKind::Emitter && patches_.inRoom(h->point);
            // Zero when the beam grazed an opening's edge.
            if (patch.lit) patch.density = patches_.density(h->point, h->geometricNormal, ws);
            patch.lit = patch.density > 0;
            if (!patch.lit) return;
        }
        const Hit& h = *patch.hit;
        const Vec3 toPatch = h.point - v.p;
        const double d2 = dot(toPatch, toPatch);
        if (!(d2 > 0)) return;
        const double dist = std::sqrt(d2);
        const Vec3 wi = toPatch / dist;
        const Vec3 fx = evalCos(v, wi);
        if (maxComponent(fx) <= 0) return;
        const Vertex y = surfaceVertex(h, bsdfs_[h.material], -wi);
        const Vec3 fy = evalCos(y, ws);
        if (maxComponent(fy) <= 0) return;
        const double b = patch.density, pSun = patch.sun.pdf;
        const double cosY = std::abs(dot(y.ng, wi));
        // y's own sun sample would count only the disks the shell lets through from y
        // (from its shadow ray's origin, offset towards the sun: the same whichever side
        // of y's surface the path comes from).
        if (!(patch.openAtY > 0)) patch.openAtY = sunDisks_.at(y.p, &y.ng, kRayEpsilon).share;
        const double w = sunWeight(b, pSun, pdfOf(v, wi) * cosY / d2, b, pSun / patch.openAtY, pSun, pdfOf(y, ws));
        if (!(w > 0)) return;
        if (patch.toSun < 0) {
            patch.toSun = transmittance(spawn(y, ws), ws, kInf, -1, stats);
            patch.lit = patch.toSun > 0;
            if (!patch.lit) return;
        }
        // Between the two surfaces, each end offset from its own: a ray from x's offset
        // point to y itself would meet y's surface first when x is near it.
        const Vec3 from = spawn(v, wi), to = spawn(y, -wi);
        const Vec3 span = to - from;
        const double gap = std::sqrt(dot(span, span));
        if (!(gap > 0) || dot(span, wi) <= 0) return;
        const double connection = transmittance(from, span / gap, gap, -1, stats);
        if (connection <= 0) return;
        const Vec3 contribution = throughput * fx * fy * patch.sun.Le * (cosY / d2 * connection * patch.toSun * w / (pSun * b));
        if (stats.budget) stats.budget->credit(LightBudget::kSun, depth, luminance(contribution));
        L += contribution;
    };

    // Once through a see-through surface, a path may run inside parts whose faces
    // coincide with another material's (a glass top resting on a wooden leg, and so
    // into the leg): its rays' ties then go by a fixed order, so that it is the same
    // path after any move (EmbreeScene::intersect; a second query per ray, which paths
    // that never meet glass or a translucent surface do not pay).
    bool seeThrough = false;
    for (; depth < options_.maxDepth; ++depth) {
        samples.setDepth(depth);
        bool deltaVertex = v.isSurface() ? v.bsdf->isDelta() : sensor.isDelta();

        // ---- next-event estimation (skipped at delta vertices) ----
        sunOpen = 1;
        if (!deltaVertex) {
            // `throughShell`: the direction must leave through an opening (the sun's: a
            // direction that leaves the box through an opaque wall is blocked whatever the
            // layout), tested once the surface is known to face it.
            // `skyLater`: a sky sample whose radiance, positive wherever it points
            // (DaylightEnvironment::radiancePositive), is looked up only once the shadow
            // ray has found the way open (most are blocked, by furniture).
            auto addLight = [&](const Vec3& wi, const Vec3& sampledLe, double lightPdf, double maxT, int target, int source,
                                bool throughShell = false, bool skyLater = false) {
                if (!(lightPdf > 0) || (!skyLater && maxComponent(sampledLe) <= 0)) return;
                Vec3 f = evalCos(v, wi);
                if (maxComponent(f) <= 0) return;
                if (throughShell && patches_.shadedByShell(spawn(v, wi), wi)) return;
                // The light samples' roulette (PathSamples::setLightFloor), at surface
                // vertices: a sensor's own samples count in its cells, on another scale.
                Vec3 Le = sampledLe;
                double survival = 1;
                if (lightFloor > 0 && v.isSurface()) {
                    if (skyLater) Le = daylight_->Le(wi), skyLater = false;
                    const double c = luminance(throughput * f * Le) / lightPdf;
                    if (c < lightFloor) {
                        survival = c / lightFloor;
                        if (!(samples.rng().uniform() < survival)) return;
                    }
                }
                double T = transmittance(spawn(v, wi), wi, v.isSurface() ? maxT : maxT - kRayEpsilon, target, stats);
                if (T <= 0) return;
                T /= survival;
                if (skyLater) Le = daylight_->Le(wi);
                const double bsdfPdf = pdfOf(v, wi);
                double w = powerHeuristic(1, lightPdf, 1, bsdfPdf);
                if (source == LightBudget::kSun && arrivalDensity > 0) {
                    const double b = otherSunDensity(wi);
                    if (b > 0) w = sunWeight(arrivalDensity, lightPdf, arrivalDensity, b, lightPdf, lightPdf * sunOpen, bsdfPdf);
                } else if (source == LightBudget::kSky && outsideDensity > 0) {
                    w = sunWeight(arrivalDensity, lightPdf, arrivalDensity, outsideDensity, lightPdf, lightPdf, bsdfPdf);
                }
                Vec3 contribution = throughput * f * Le * (T * w / lightPdf);
                if (stats.budget) stats.budget->credit(source, depth, luminance(contribution));
                if (depth == 0 && sensorLight) {
                    sensorLight->wi[sensorLight->count] = wi;
                    sensorLight->value[sensorLight->count++] = luminance(contribution);
                } else {
                    L += contribution;
                }
            };
            // The sky's portal sample, followed to what it meets (exteriorSun_): open sky,
            // as addLight would take it, or a surface z outside the room, whose light
            // from the sun and the sky it takes (samples drawn independently of the
            // portal's). A path here -> z -> light BSDF sampling here also makes, then
            // the light's sampling or BSDF sampling at z: the power heuristic over the three.
            auto addSkyOrOutside = [&](const EnvironmentSample& s, const EnvironmentSample& sunAtZ) {
                if (!(s.pdf > 0)) return;
                const Vec3 f = evalCos(v, s.wi);
                if (maxComponent(f) <= 0) return;
                const Vec3 from = spawn(v, s.wi);
                const unsigned blockers = kOpaqueMask | kEmitterMask;
                // Most of these samples are blocked inside the room (by furniture), where
                // what blocks them does not matter: an any-hit query up to the room's
                // walls says so, and a move across that part of the ray changes the path
                // only if it changes that answer (the path cache asks it again).
                const double inside = sky_.inRoomUntil(from, s.wi);
                ++stats.shadow;
                const bool blocked = rt_.occluded({from, s.wi, 0, inside, blockers});
                if (stats.footprint) stats.footprint->addOcclusion(from, s.wi, 0, inside, blockers, blocked);
                if (blocked) return;
                ++stats.closest;
                const std::optional<Hit> z = rt_.intersect({from, s.wi, inside, kInf, blockers, seeThrough});
                if (stats.footprint) {
                    if (z) stats.footprint->add(from, s.wi, inside, z->t);
                    else stats.footprint->addOcclusion(from, s.wi, inside, kInf, blockers, false);
                }
                Vec3 contribution;
                int creditDepth = depth;
                if (!z) {
                    if (maxComponent(s.Le) <= 0) return;
                    const double T = panes_.transmittance(from, s.wi, kInf);
                    if (T <= 0) return;
                    contribution = throughput * f * s.Le * (T * powerHeuristic(1, s.pdf, 1, pdfOf(v, s.wi)) / s.pdf);
                } else {
                    if (z->kind == HitKind::Emitter || sky_.inRoom(z->point)) return;
                    const double T = panes_.transmittance(from, s.wi, z->t);
                    if (T <= 0) return;
                    const Vertex outside = surfaceVertex(*z, bsdfs_[z->material], -s.wi);
                    const double a = pdfOf(v, s.wi);
                    // Light arriving at z from direction wl (sampled with density pl),
                    // weighed against the two BSDF ways to the same path.
                    auto lightAtZ = [&](const Vec3& wl, const Vec3& Le, double pl) {
                        if (!(pl > 0) || maxComponent(Le) <= 0) return;
                        const Vec3 fz = evalCos(outside, wl);
                        if (maxComponent(fz) <= 0) return;
                        const double V = transmittance(spawn(outside, wl), wl, kInf, -1, stats);
                        if (V <= 0) return;
                        // z lies outside the room: every disk is open from it.
                        const double w = sunWeight(s.pdf, pl, a, s.pdf, pl, pl, pdfOf(outside, wl));
                        contribution += throughput * f * fz * Le * (T * V * w / (s.pdf * pl));
                    };
                    // The sun (this vertex's sun sample), then the sky and the ground, which
                    // light a facade too (a sample of the map, as a vertex outside samples
                    // it, from the path's own stream).
                    lightAtZ(sunAtZ.wi, sunAtZ.Le, sunAtZ.pdf);
                    const double u0 = samples.rng().uniform();
                    const EnvironmentSample skyAtZ = daylight_->sampleSky({u0, samples.rng().uniform()});
                    lightAtZ(skyAtZ.wi, skyAtZ.Le, skyAtZ.pdf);
                    if (maxComponent(contribution) <= 0) return;
                    creditDepth = depth + 1;  // reflected off z, not direct
                }
                if (stats.budget) stats.budget->credit(LightBudget::kSky, creditDepth, luminance(contribution));
                if (depth == 0 && sensorLight) {
                    sensorLight->wi[sensorLight->count] = s.wi;
                    sensorLight->value[sensorLight->count++] = luminance(contribution);
                } else {
                    L += contribution;
                }
            };
            if (!emitters_.empty()) {
                // The choice reads every luminaire, and so does a sensor's test of them:
                // a moved one changes the path either way.
                if (stats.footprint) stats.footprint->usedEmitterChoice = true;
                if (v.isSurface() || sensorSeesEmitters) {
                    const double uChoice = samples.get1D(PathSamples::EmitterChoice);
                    const Vec2 uPoint = samples.get2D(PathSamples::EmitterPoint);
                    // Every path of a sampler point starts at it: its thread's view of the
                    // luminaires from there (the same numbers, set up once).
                    EmitterSample s = v.isSurface() ? emitters_.sample(v.p, uChoice, uPoint)
                                                    : emitters_.sample(emitters_.viewFrom(v.p), uChoice, uPoint);
                    if (s.pdf > 0 && s.Lv > 0) addLight(s.wi, Vec3(s.Lv, s.Lv, s.Lv), s.pdf, s.distance, s.emitter, s.emitter);
                }
            }
            // The portals' view first: whether the sky's sample goes outside decides
            // whether it needs this vertex's sun sample.
            const SkyLight::View* view = nullptr;
            if (sky) {
                if (depth == 0) {
                    views[current] = &sky_.viewFromSensor(v.p);
                } else {
                    sky_.view(v.p, scratch[current]);
                    views[current] = &scratch[current];
                }
                view = views[current];
            }
            // A sensor draws no light sample it cannot see (the estimate is unchanged).
            const bool skyHere = sky && (v.isSurface() || sky_.seenBy(*view, sensor));
            const bool outside = skyHere && exteriorSun_ && view->active;  // the sky's sample lights z with the sun's
            const bool sunHere = v.isSurface() || sensorSeesSun;
            EnvironmentSample sun, sunAtZ;
            if (daylight_ && daylight_->hasSun() && (sunHere || outside)) {
                const double uDisk = samples.get1D(PathSamples::SunDisk);
                const Vec2 uPoint = samples.get2D(PathSamples::SunPoint);
                // The exterior strategy lights the surface outside with the period's own
                // choice of disk (every disk is open from out there).
                if (outside) sunAtZ = daylight_->sampleSun(uDisk, uPoint);
                // A surface that only reflects, with every sun direction behind it, would
                // find the sample unlit (evalCos): its numbers are drawn all the same, so
                // that every later one stays, but the direction is not.
                const bool behind = v.isSurface() && !v.bsdf->hasDiffuseTransmission() && daylight_->sunBehind(v.ng);
                if (sunHere && !behind) {
                    // The disk among those the shell may let through from the shadow ray's
                    // origin (OpenSunDisks), and its density over their share. At a
                    // surface whose plane the disk's cone does not cross, that origin is
                    // spawn()'s, the same for every direction of the disk (a point of the
                    // floor or a wall: on the shell itself, its origin is just inside);
                    // else within kRayEpsilon.
                    const OpenSunDisks::Open open = sunDisks_.at(v.p, v.isSurface() ? &v.ng : nullptr, kRayEpsilon);
                    sunOpen = open.share;
                    const size_t disk = sunDisks_.active() ? sunDisks_.choose(open, uDisk) : daylight_->sunDiskOf(uDisk);
                    bool walled = disk == OpenSunDisks::kNone;
                    if (!walled && (!sunDisks_.active() || sunDisks_.grouped(disk))) {
                        // Its own cone untested: where the shell blocks it whole, no
                        // direction is made (the sample would find no opening:
                        // addLight's shadedByShell).
                        const Vec3& axis = daylight_->sunDisks()[disk].direction;
                        const double halfAngle = kSunHalfAngle * (1 + 1e-6) + 1e-9;
                        Vec3 from = v.p;
                        double within = kRayEpsilon;
                        if (v.isSurface() && std::abs(dot(axis, v.ng)) > halfAngle) from = offsetAlong(v.p, v.ng, axis), within = 0;
                        walled = patches_.shadesCone(from, within, axis, halfAngle);
                    }
                    if (!walled) {
                        sun = daylight_->sampleSunDisk(disk, uPoint);
                        sun.pdf /= open.share;
                    }
                    addLight(sun.wi, sun.Le, sun.pdf, kInf, -1, LightBudget::kSun, true);
                }
            }
            if (skyHere) {
                const bool later = !outside && view->active && daylight_->radiancePositive();
                EnvironmentSample s = sky_.sample(*view, v.p, samples.get2D(PathSamples::SkyPoint), !later);
                if (outside) addSkyOrOutside(s, sunAtZ);
                else addLight(s.wi, s.Le, s.pdf, kInf, -1, LightBudget::kSky, false, later);
            }
            if (patchesHere()) addSunPatch();
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
            lastSunOpen = sunOpen;
            lastPoint = v.p;
            lastAtSensor = !v.isSurface();
            lastPatched = patchesHere();
            if (lastPatched) lastOrigin = {v.p, v.ng, v.bsdf->hasDiffuseTransmission(), true};
            lastOutside = exteriorSun_ && views[current]->active;
            if (sky) current ^= 1;  // views[current ^ 1] is now the last non-delta vertex's
        }
        lastDelta = delta;

        // ---- Russian roulette ----
        if (depth >= options_.rouletteDepth) {
            double q = std::min(0.95, maxComponent(throughput) / (options_.rouletteLevel * firstWeight));
            if (samples.get1D(PathSamples::Roulette) >= q) break;
            throughput = throughput * (1 / q);
        }

        // ---- follow the ray, passing through glass panes ----
        Vec3 o = spawn(v, d);
        seeThrough = seeThrough || (v.isSurface() && v.bsdf->hasDiffuseTransmission());
        bool scattered = false;
        for (int crossings = 0; crossings < 32 && !scattered; ++crossings) {
            ++stats.closest;
            auto hit = rt_.intersect({o, d, 0, kInf, kAllMask, seeThrough});
            if (stats.footprint) stats.footprint->add(o, d, 0, hit ? hit->t : kInf);
            if (!hit) {
                if (daylight_) {
                    // Depth 0 is the sensor's own ray, through panes and off mirrors.
                    const bool hidden = depth == 0 && sensor.hidesSources();
                    Vec3 sky = daylight_->Le(d), sun = hidden ? Vec3() : daylight_->sunLe(d);
                    double wSky = 1;
                    if (!lastDelta) {
                        const double pSky = sky_.pdf(*views[current ^ 1], lastPoint, d);
                        wSky = outsideDensity > 0 ? sunWeight(arrivalDensity, lastPdf, arrivalDensity, outsideDensity, pSky, pSky, lastPdf)
                                                  : powerHeuristic(1, lastPdf, 1, pSky);
                    }
                    double wSun = 1;
                    if (!lastDelta && maxComponent(sun) > 0) {
                        // The last vertex's own sun sample would have chosen among its open disks.
                        const double pSun = daylight_->sunPdf(d), pSunThere = pSun / lastSunOpen;
                        const double b = arrivalDensity > 0 ? otherSunDensity(d) : 0;
                        wSun = b > 0 ? sunWeight(arrivalDensity, lastPdf, arrivalDensity, b, pSunThere, pSun, lastPdf)
                                     : powerHeuristic(1, lastPdf, 1, pSunThere);
                    }
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
                    const size_t e = size_t(hit->index);
                    double w = lastDelta ? 1
                                         : powerHeuristic(1, lastPdf, 1,
                                                          lastAtSensor ? emitters_.pdf(e, emitters_.viewFrom(lastPoint), hit->point)
                                                                       : emitters_.pdf(e, lastPoint, hit->point));
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
                seeThrough = true;
                continue;
            }
            // A scattering surface: the next vertex. Surfaces are two-sided.
            v = surfaceVertex(*hit, bsdf, -d);
            arrivalDensity = outsideDensity = 0;
            arrivalFrom.valid = false;
            if (!lastDelta && (lastPatched || lastOutside)) {
                const Vec3 e = v.p - lastPoint;
                const double d2 = dot(e, e);
                if (d2 > 0) {
                    const double toArea = std::abs(dot(v.ng, d)) / d2;
                    arrivalDensity = lastPdf * toArea;
                    if (lastPatched) arrivalFrom = lastOrigin;
                    if (lastOutside && !sky_.inRoom(v.p)) outsideDensity = sky_.pdf(*views[current ^ 1], lastPoint, d) * toArea;
                }
            }
            scattered = true;
        }
        if (!scattered) break;
    }
    return luminance(L);
}

}  // namespace luxplan
