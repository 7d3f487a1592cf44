#include <luxplan/pathtracer/light_strategies.h>

#include <cmath>

#include <luxplan/scene/room.h>

namespace luxplan {

void SkyStrategy::sample(Path& path) const {
    if (!path.skyHere) return;
    const PathTracer& tracer = path.tracer;
    const bool later = !path.outside && path.view->active && tracer.daylight_->radiancePositive();
    const EnvironmentSample s = tracer.sky_.sample(*path.view, path.v.p, path.samples.get2D(PathSamples::SkyPoint), !later);
    if (path.outside) {
        sampleOutside(path, s);
        return;
    }
    LightSample light;
    light.wi = s.wi, light.Le = s.Le, light.pdf = s.pdf;
    light.source = LightBudget::kSky, light.skyLater = later;
    tracer.connect(path, light);
}

double SkyStrategy::pdf(const Path& path, const Vec3& wi, const Hit* /*hit*/) const {
    return path.tracer.sky_.pdf(*path.views[path.current ^ 1], path.lastPoint, wi);
}

// The sky's portal sample, followed to what it meets: open sky, as connect() would take
// it, or a surface z outside the room, whose light from the sun and the sky it takes
// (samples drawn independently of the portal's). A path here -> z -> light BSDF
// sampling here also makes, then the light's sampling or BSDF sampling at z: the power
// heuristic over the three.
void SkyStrategy::sampleOutside(Path& path, const EnvironmentSample& s) const {
    if (!(s.pdf > 0)) return;
    const PathTracer& tracer = path.tracer;
    const Vertex& v = path.v;
    RayStats& stats = path.stats;
    PathFootprint* footprint = path.params.footprint;
    const Vec3 f = path.evalCos(v, s.wi);
    if (maxComponent(f) <= 0) return;
    const Vec3 from = path.spawn(v, s.wi);
    const unsigned blockers = kOpaqueMask | kEmitterMask;
    // Most of these samples are blocked inside the room (by furniture), where what
    // blocks them does not matter: an any-hit query up to the room's walls says so, and
    // a move across that part of the ray changes the path only if it changes that
    // answer (the path cache asks it again).
    const double inside = tracer.sky_.inRoomUntil(from, s.wi);
    ++stats.shadow;
    const bool blocked = tracer.rt_.occluded({from, s.wi, 0, inside, blockers});
    if (footprint) footprint->addOcclusion(from, s.wi, 0, inside, blockers, blocked);
    if (blocked) return;
    ++stats.closest;
    const std::optional<Hit> z = tracer.rt_.intersect({from, s.wi, inside, kInf, blockers, path.seeThrough});
    if (footprint) {
        if (z) footprint->add(from, s.wi, inside, z->t);
        else footprint->addOcclusion(from, s.wi, inside, kInf, blockers, false);
    }
    if (!z) {
        if (maxComponent(s.Le) <= 0) return;
        const double T = tracer.panes_.transmittance(from, s.wi, kInf);
        if (T <= 0) return;
        StrategyDensities d;
        d.light = s.pdf, d.bsdf = path.pdfOf(v, s.wi);
        path.add(s.wi, path.throughput * f * s.Le * (T * misWeight(Strategy::Light, d) / s.pdf), LightBudget::kSky, path.depth);
        return;
    }
    if (z->kind == HitKind::Emitter || tracer.sky_.inRoom(z->point)) return;
    const double T = tracer.panes_.transmittance(from, s.wi, z->t);
    if (T <= 0) return;
    const Vertex outside = surfaceVertex(*z, tracer.bsdfs_[z->material], -s.wi);
    const double a = path.pdfOf(v, s.wi);
    Vec3 contribution;
    // Light arriving at z from direction wl (sampled with density pl), weighed against
    // the two BSDF ways to the same path.
    auto lightAtZ = [&](const Vec3& wl, const Vec3& Le, double pl) {
        if (!(pl > 0) || maxComponent(Le) <= 0) return;
        const Vec3 fz = path.evalCos(outside, wl);
        if (maxComponent(fz) <= 0) return;
        const double V = tracer.transmittance(path.spawn(outside, wl), wl, kInf, -1, stats, footprint);
        if (V <= 0) return;
        // z lies outside the room: every disk is open from it.
        StrategyDensities d;
        d.light = pl, d.bsdf = path.pdfOf(outside, wl);
        d.arrival = a, d.twoBounce = s.pdf, d.twoBounceLight = pl;
        contribution += path.throughput * f * fz * Le * (T * V * misWeight(Strategy::TwoBounce, d) / (s.pdf * pl));
    };
    // The sun (this vertex's sun sample), then the sky and the ground, which light a
    // facade too (a sample of the map, as a vertex outside samples it, from the path's
    // own stream).
    lightAtZ(path.sunAtZ.wi, path.sunAtZ.Le, path.sunAtZ.pdf);
    const double u0 = path.samples.rng().uniform();
    const EnvironmentSample skyAtZ = tracer.daylight_->sampleSky({u0, path.samples.rng().uniform()});
    lightAtZ(skyAtZ.wi, skyAtZ.Le, skyAtZ.pdf);
    if (maxComponent(contribution) <= 0) return;
    path.add(s.wi, contribution, LightBudget::kSky, path.depth + 1);  // reflected off z, not direct
}

// Some triangle outside, some corner of an opening the sky is sampled through and some
// sun disk on the same side of its plane (either side for a translucent surface, the
// outer side for a box); the room's box has a millimetre of slack. Without one the
// outside strategy finds nothing (the morning sun on the far side of a facade).
bool SkyStrategy::sunlitOutside(const Scene& scene, const DaylightEnvironment& daylight, const std::vector<Bsdf>& bsdfs) {
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

}  // namespace luxplan
