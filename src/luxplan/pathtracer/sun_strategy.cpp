#include <luxplan/pathtracer/light_strategies.h>

namespace luxplan {

void SunStrategy::sample(Path& path) const {
    const PathTracer& tracer = path.tracer;
    const DaylightEnvironment* daylight = tracer.daylight_;
    if (!daylight || !daylight->hasSun() || !(path.sunHere || path.outside)) return;
    const Vertex& v = path.v;
    const double uDisk = path.samples.get1D(PathSamples::SunDisk);
    const Vec2 uPoint = path.samples.get2D(PathSamples::SunPoint);
    // The exterior strategy lights the surface outside with the period's own choice of
    // disk (every disk is open from out there).
    if (path.outside) path.sunAtZ = daylight->sampleSun(uDisk, uPoint);
    // A surface that only reflects, with every sun direction behind it, would find the
    // sample unlit (evalCos): its numbers are drawn all the same, so that every later
    // one stays, but the direction is not.
    const bool behind = v.isSurface() && !v.bsdf->hasDiffuseTransmission() && daylight->sunBehind(v.ng);
    if (!path.sunHere || behind) return;
    // The disk among those the shell may let through from the shadow ray's origin
    // (OpenSunDisks), and its density over their share. At a surface whose plane the
    // disk's cone does not cross, that origin is spawn()'s, the same for every direction
    // of the disk (a point of the floor or a wall: on the shell itself, its origin is
    // just inside); else within kRayEpsilon.
    const OpenSunDisks& disks = tracer.sunDisks_;
    const OpenSunDisks::Open open = disks.at(v.p, v.isSurface() ? &v.ng : nullptr, kRayEpsilon);
    path.sunOpen = open.share;
    const size_t disk = disks.active() ? disks.choose(open, uDisk) : daylight->sunDiskOf(uDisk);
    bool walled = disk == OpenSunDisks::kNone;
    if (!walled && (!disks.active() || disks.grouped(disk))) {
        // Its own cone untested: where the shell blocks it whole, no direction is made
        // (the sample would find no opening: connect()'s shadedByShell).
        const Vec3& axis = daylight->sunDisks()[disk].direction;
        const double halfAngle = kSunHalfAngle * (1 + 1e-6) + 1e-9;
        Vec3 from = v.p;
        double within = kRayEpsilon;
        if (v.isSurface() && std::abs(dot(axis, v.ng)) > halfAngle) from = offsetAlong(v.p, v.ng, axis), within = 0;
        walled = tracer.patches_.shadesCone(from, within, axis, halfAngle);
    }
    if (walled) return;
    EnvironmentSample sun = daylight->sampleSunDisk(disk, uPoint);
    sun.pdf /= open.share;
    LightSample light;
    light.wi = sun.wi, light.Le = sun.Le, light.pdf = sun.pdf;
    light.source = LightBudget::kSun, light.throughShell = true;
    tracer.connect(path, light);
}

double SunStrategy::pdf(const Path& path, const Vec3& wi, const Hit* /*hit*/) const {
    // The last vertex's own sun sample would have chosen among its open disks.
    return path.tracer.daylight_->sunPdf(wi) / path.lastSunOpen;
}

}  // namespace luxplan
