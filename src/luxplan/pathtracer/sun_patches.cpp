#include <luxplan/pathtracer/sun_patches.h>

#include <algorithm>
#include <cmath>

#include <luxplan/materials/bsdf.h>
#include <luxplan/scene/room.h>

namespace luxplan {

SunPatches::SunPatches(const Scene& scene, bool enabled) : enabled_(enabled) {
    const RoomShell* room = scene.room();
    if (!room) return;
    shell_ = room->box;
    // A translucent or glass wall lets light through where no opening is, and an
    // invisible room (one that only collides) has no shell in the ray-tracing scene.
    opaqueShell_ = true;
    for (const auto& g : scene.geometry)
        if (g.room && g.invisible) opaqueShell_ = false;
    for (uint32_t m : {room->floorMaterial, room->wallMaterial, room->ceilingMaterial}) {
        const Bsdf bsdf = makeBsdf(scene.materials[m]);
        if (bsdf.passesStraight() || bsdf.hasDiffuseTransmission()) opaqueShell_ = false;
    }
    // The same millimetre of slack as the sky's portals: hit points on the shell lie a
    // float ulp either side of the box.
    room_ = Bounds3(room->box.lo - Vec3(1e-3, 1e-3, 1e-3), room->box.hi + Vec3(1e-3, 1e-3, 1e-3));
    const Vec3 centre = (room->box.lo + room->box.hi) * 0.5;
    for (const Opening& o : room->openings) {
        // Opaque and translucent panels let no sunbeam straight through.
        if (o.material && !makeBsdf(scene.materials[*o.material]).passesStraight()) continue;
        const Rect3 rect = openingQuad(room->box, o);
        Vec3 n = rect.normal();
        if (dot(n, rect.center() - centre) < 0) n = -n;
        const double lengthU = length(rect.edgeU), lengthV = length(rect.edgeV);
        openings_.push_back({RectTarget(rect), n, rect.area(), rect.edgeU / lengthU, rect.edgeV / lengthV, lengthU, lengthV});
    }
}

double SunPatches::projectedArea(const Vec3& ws) const {
    double total = 0;
    for (const Entrance& o : openings_) total += o.area * std::max(0.0, dot(o.outward, ws));
    return total;
}

bool SunPatches::sampleEntry(const Vec3& ws, Vec2 u, Vec3& entry) const {
    const double total = projectedArea(ws);
    if (!(total > 0)) return false;
    double target = u.x * total, acc = 0;
    for (const Entrance& o : openings_) {
        const double w = o.area * std::max(0.0, dot(o.outward, ws));
        if (w > 0 && target < acc + w) {
            const double x = std::min((target - acc) / w, 1 - 1e-12);
            entry = o.target.rect().corner + o.target.rect().edgeU * x + o.target.rect().edgeV * u.y;
            return true;
        }
        acc += w;
    }
    return false;
}

Vec3 SunPatches::beamEnd(const Vec3& p, const Vec3& beam) const {
    double t = kInf;
    for (int i = 0; i < 3; ++i) {
        if (beam[i] > 0) t = std::min(t, (room_.hi[i] - p[i]) / beam[i]);
        else if (beam[i] < 0) t = std::min(t, (room_.lo[i] - p[i]) / beam[i]);
    }
    return p + beam * std::max(t, 0.0);
}

bool SunPatches::shadedByShell(const Vec3& p, const Vec3& ws) const {
    if (!opaqueShell_) return false;
    for (int i = 0; i < 3; ++i)
        if (!(p[i] > shell_.lo[i] && p[i] < shell_.hi[i])) return false;
    for (const Entrance& o : openings_)
        if (dot(o.outward, ws) > 0 && o.target.intersect(p, ws) > 0) return false;
    return true;
}

bool SunPatches::shadesCone(const Vec3& p, double offset, const Vec3& axis, double halfAngle) const {
    if (!opaqueShell_) return false;
    for (int i = 0; i < 3; ++i)  // every q strictly inside the box
        if (!(p[i] - offset > shell_.lo[i] && p[i] + offset < shell_.hi[i])) return false;
    // |w - axis| <= halfAngle (a chord is shorter than its arc).
    const double delta = halfAngle;
    for (const Entrance& o : openings_) {
        const Vec3& n = o.outward;
        const double nc = dot(n, axis);
        if (nc + delta <= 0) continue;  // every w points away from this opening's plane
        const double least = nc - delta;  // n . w for every w in the cone
        if (!(least > 1e-3)) return false;
        const Rect3& r = o.target.rect();
        const double depth = dot(n, r.corner - p);  // p's distance to the opening's plane
        if (!(depth > offset)) return false;
        // Where the axis from p meets the plane, and how far the cone's rays from any q
        // meet it from there: |w / (n.w) - axis / (n.axis)| <= delta / least + delta / (least nc),
        // and a start moved by `offset` moves the meeting by at most offset (1 + 1 / least).
        // (Two divisions, independent of each other: this runs at nearly every surface vertex.)
        const double overNc = 1 / nc, overLeast = 1 / least;
        const Vec3 hit = p + axis * (depth * overNc);
        const double spread = (depth * delta * (1 + overNc) + offset * (least + 1)) * overLeast;
        const double margin = spread * (1 + 1e-6) + 1e-7 * (1 + std::abs(hit.x) + std::abs(hit.y) + std::abs(hit.z));
        const double a = dot(hit - r.corner, o.unitU), b = dot(hit - r.corner, o.unitV);
        if (a < -margin || a > o.lengthU + margin || b < -margin || b > o.lengthV + margin) continue;  // misses it
        return false;
    }
    return true;
}

double SunPatches::density(const Vec3& y, const Vec3& n, const Vec3& ws) const {
    if (!room_.contains(y)) return 0;
    for (const Entrance& o : openings_) {
        if (dot(o.outward, ws) <= 0 || o.target.intersect(y, ws) <= 0) continue;
        // From inside the (convex) room a ray leaves through one opening at most.
        return std::abs(dot(n, ws)) / projectedArea(ws);
    }
    return 0;
}

}  // namespace luxplan
