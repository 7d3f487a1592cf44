#include <luxplan/pathtracer/light_strategies.h>

#include <cmath>

namespace luxplan {

bool SunPatchStrategy::samplesAt(const Path& path) { return path.tracer.patches_.active() && path.v.isSurface(); }

// Every vertex's estimate is unbiased on its own, since y is drawn independently of the
// path; drawing it once costs the beam and y's view of the sun once per path. Each
// connection is weighed against the two BSDF ways to the same path (misWeight).
void SunPatchStrategy::sample(Path& path) const {
    if (!samplesAt(path)) return;
    const PathTracer& tracer = path.tracer;
    const SunPatches& patches = tracer.patches_;
    Path::PatchLight& patch = path.patch;
    RayStats& stats = path.stats;
    PathFootprint* footprint = path.params.footprint;
    const Vertex& v = path.v;
    if (!patch.drawn) {
        patch.drawn = true;
        const double uDisk = path.samples.get1D(PathSamples::PatchSunDisk);
        patch.sun = tracer.daylight_->sampleSun(uDisk, path.samples.get2D(PathSamples::PatchSunPoint));
        const Vec2 uEntry = path.samples.get2D(PathSamples::PatchEntry);
        patch.lit = patch.sun.pdf > 0 && patches.sampleEntry(patch.sun.wi, uEntry, patch.entry);
        if (patch.lit) patch.beamEnd = patches.beamEnd(patch.entry, -patch.sun.wi);
    }
    if (!patch.lit) return;
    const PatchOrigin here{v.p, v.ng, v.bsdf->hasDiffuseTransmission()};
    if (!here.faces(patch.beamEnd)) return;
    const Vec3 ws = patch.sun.wi;
    if (!patch.traced) {
        patch.traced = true;
        ++stats.closest;
        patch.hit = tracer.rt_.intersect({patch.entry, -ws, 0, kInf, kOpaqueMask | kEmitterMask});
        if (footprint) footprint->add(patch.entry, -ws, 0, patch.hit ? patch.hit->t : kInf);
        const Hit* h = patch.hit ? &*patch.hit : nullptr;
        patch.lit = h && h->kind != HitKind::Emitter && patches.inRoom(h->point);
        // Zero when the beam grazed an opening's edge.
        if (patch.lit) patch.density = patches.density(h->point, h->geometricNormal, ws);
        patch.lit = patch.density > 0;
        if (!patch.lit) return;
    }
    const Hit& h = *patch.hit;
    const Vec3 toPatch = h.point - v.p;
    const double d2 = dot(toPatch, toPatch);
    if (!(d2 > 0)) return;
    const double dist = std::sqrt(d2);
    const Vec3 wi = toPatch / dist;
    const Vec3 fx = path.evalCos(v, wi);
    if (maxComponent(fx) <= 0) return;
    const Vertex y = surfaceVertex(h, tracer.bsdfs_[h.material], -wi);
    const Vec3 fy = path.evalCos(y, ws);
    if (maxComponent(fy) <= 0) return;
    const double b = patch.density, pSun = patch.sun.pdf;
    const double cosY = std::abs(dot(y.ng, wi));
    // y's own sun sample would count only the disks the shell lets through from y (from
    // its shadow ray's origin, offset towards the sun: the same whichever side of y's
    // surface the path comes from).
    if (!(patch.openAtY > 0)) patch.openAtY = tracer.sunDisks_.at(y.p, &y.ng, kRayEpsilon).share;
    StrategyDensities d;
    d.light = pSun / patch.openAtY, d.bsdf = path.pdfOf(y, ws);
    d.arrival = path.pdfOf(v, wi) * cosY / d2, d.twoBounce = b, d.twoBounceLight = pSun;
    const double w = misWeight(Strategy::TwoBounce, d);
    if (!(w > 0)) return;
    if (patch.toSun < 0) {
        patch.toSun = tracer.transmittance(path.spawn(y, ws), ws, kInf, -1, stats, footprint);
        patch.lit = patch.toSun > 0;
        if (!patch.lit) return;
    }
    // Between the two surfaces, each end offset from its own: a ray from x's offset point
    // to y itself would meet y's surface first when x is near it.
    const Vec3 from = path.spawn(v, wi), to = path.spawn(y, -wi);
    const Vec3 span = to - from;
    const double gap = std::sqrt(dot(span, span));
    if (!(gap > 0) || dot(span, wi) <= 0) return;
    const double connection = tracer.transmittance(from, span / gap, gap, -1, stats, footprint);
    if (connection <= 0) return;
    path.add(wi, path.throughput * fx * fy * patch.sun.Le * (cosY / d2 * connection * patch.toSun * w / (pSun * b)),
             LightBudget::kSun, path.depth, &patch.sun.wi);
}

// The patch strategy's area density at the current vertex for sun direction wi, had it
// been drawn from the vertex the path arrived from.
double SunPatchStrategy::pdf(const Path& path, const Vec3& wi, const Hit* /*hit*/) const {
    const PatchOrigin& from = path.arrivalFrom;
    if (!from.valid) return 0;
    const SunPatches& patches = path.tracer.patches_;
    return from.faces(patches.beamEnd(path.v.p, -wi)) ? patches.density(path.v.p, path.v.ng, wi) : 0.0;
}

}  // namespace luxplan
