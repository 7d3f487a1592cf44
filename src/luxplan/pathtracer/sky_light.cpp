#include <luxplan/pathtracer/sky_light.h>

#include <algorithm>
#include <atomic>

#include <luxplan/materials/bsdf.h>
#include <luxplan/scene/room.h>

namespace luxplan {

SkyLight::SkyLight(const Scene& scene, const DaylightEnvironment* daylight, bool portals)
    : daylight_(daylight), portals_(portals) {
    static std::atomic<uint64_t> nextId{1};
    id_ = nextId++;
    if (const RoomShell* room = scene.room()) {
        hasRoom_ = true;
        // Hit points on the shell lie on the box boundary, half of them a float ulp
        // outside: a millimetre of slack keeps them on the portal side.
        room_ = Bounds3(room->box.lo - Vec3(1e-3, 1e-3, 1e-3), room->box.hi + Vec3(1e-3, 1e-3, 1e-3));
        roomForRays_ = Bounds3(room->box.lo - Vec3(5e-4, 5e-4, 5e-4), room->box.hi + Vec3(5e-4, 5e-4, 5e-4));
        for (const Opening& o : room->openings) {
            // An opening closed by an opaque panel (a door, a shutter) lets no sky in, and
            // a translucent one no sky seen straight through it (its light reaches the room
            // by scattering at the pane: BSDF sampling finds it).
            if (o.material && !makeBsdf(scene.materials[*o.material]).passesStraight()) continue;
            const Rect3 r = openingQuad(room->box, o);
            const Vec3 areaNormal = cross(r.edgeU, r.edgeV);
            const double area = length(areaNormal);
            openings_.push_back({RectTarget(r), areaNormal, areaNormal / area, area});
        }
    }
}

const SkyLight::View& SkyLight::viewFromSensor(const Vec3& p) const {
    // Every path of a sampler point starts at the same place: keep the last view of
    // each thread (measureSamplers runs a point's paths on one thread in a row).
    thread_local uint64_t cachedLight = 0;
    thread_local View cachedView;
    if (cachedLight != id_ || !(cachedView.point == p)) {
        compute(p, cachedView, true);
        cachedLight = id_;
    }
    return cachedView;
}

void SkyLight::compute(const Vec3& p, View& view, bool buildAll) const {
    view.active = portals_ && hasRoom_ && !openings_.empty() && room_.contains(p);
    view.point = p;
    view.count = 0;
    view.weightTotal = 0;
    if (!view.active) return;
    for (const Portal& portal : openings_) {
        const Rect3& r = portal.target.rect();
        if (view.count == kMaxPortals) break;
        const int i = view.count++;
        // Area x cos / d^2 = |n . d| / d^3 with n = edgeU x edgeV (|n| = area).
        Vec3 d = r.corner + (r.edgeU + r.edgeV) * 0.5 - p;
        double d2 = dot(d, d);
        double w = d2 > 0 ? std::abs(dot(portal.areaNormal, d)) / (d2 * std::sqrt(d2)) : 2 * kPi;
        view.weight[i] = std::min(w, 2 * kPi);
        view.weightTotal += view.weight[i];
        view.spherical[i] = w > kSphericalAbove;
        view.built[i] = false;
        if (buildAll && view.spherical[i]) rect(view, i);
        if (buildAll) {
            // The directions to a convex rectangle lie in the spherical cap around its
            // centre's direction that holds its corners (a cap under a hemisphere is
            // convex, and the edges are great-circle arcs).
            view.coneCos[i] = -1;
            const Vec3 toCentre = r.corner + (r.edgeU + r.edgeV) * 0.5 - p;
            if (dot(toCentre, toCentre) > 0) {
                const Vec3 axis = normalize(toCentre);
                double cosine = 1;
                for (const Vec3& c : {r.corner, r.corner + r.edgeU, r.corner + r.edgeV, r.corner + r.edgeU + r.edgeV}) {
                    const Vec3 toCorner = c - p;
                    const double l = length(toCorner);
                    cosine = l > 0 ? std::min(cosine, dot(axis, toCorner) / l) : -1;
                }
                view.coneAxis[i] = axis;
                view.coneCos[i] = cosine > 0 ? cosine : -1;  // a wider cap is not convex
            }
        }
    }
}

double SkyLight::inRoomUntil(const Vec3& p, const Vec3& w) const {
    if (!hasRoom_) return 0;
    double until = kInf;
    for (int a = 0; a < 3; ++a) {
        if (w[a] > 0) until = std::min(until, (roomForRays_.hi[a] - p[a]) / w[a]);
        else if (w[a] < 0) until = std::min(until, (roomForRays_.lo[a] - p[a]) / w[a]);
    }
    return std::max(0.0, until);
}

bool SkyLight::seenBy(const View& view, const Sensor& sensor) const {
    if (!view.active) return true;  // the sky map over the whole sphere
    for (int i = 0; i < view.count; ++i)
        if (view.weight[i] > 0 && sensor.maySee(view.coneAxis[i], view.coneCos[i])) return true;
    return false;
}

const SphericalRect& SkyLight::rect(const View& view, int i) const {
    if (!view.built[i]) {
        view.rects[i] = SphericalRect(openings_[size_t(i)].target.rect(), view.point);
        view.built[i] = true;
    }
    return view.rects[i];
}

double SkyLight::pdf(const View& view, const Vec3& p, const Vec3& w) const {
    if (!active()) return 0;
    if (!view.active) return daylight_->skyPdf(w);
    if (view.weightTotal <= 0) return 0;
    for (int i = 0; i < view.count; ++i) {
        if (!(view.weight[i] > 0)) continue;
        const double t = openings_[size_t(i)].target.intersect(p, w);
        if (t <= 0) continue;
        const double chosen = view.weight[i] / view.weightTotal;
        if (!view.spherical[i]) {
            const double cosine = std::abs(dot(openings_[size_t(i)].normal, w));
            return cosine > 0 ? chosen * t * t / (openings_[size_t(i)].area * cosine) : 0;
        }
        double omega = rect(view, i).solidAngle();
        return omega > 0 ? chosen / omega : 0;
    }
    return 0;
}

EnvironmentSample SkyLight::sample(const View& view, const Vec3& p, Vec2 u, bool radiance) const {
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
    const double pChosen = view.weight[chosen] / view.weightTotal;
    if (!view.spherical[chosen]) {
        const Portal& portal = openings_[size_t(chosen)];
        const Rect3& o = portal.target.rect();
        const Vec3 d = o.corner + o.edgeU * u.x + o.edgeV * u.y - p;
        const double d2 = dot(d, d);
        if (!(d2 > 0)) return s;
        const double dist = std::sqrt(d2);
        s.wi = d / dist;
        const double cosine = std::abs(dot(portal.normal, s.wi));
        if (!(cosine > 0)) return s;
        if (radiance) s.Le = daylight_->Le(s.wi);
        s.pdf = pChosen * d2 / (portal.area * cosine);
        return s;
    }
    const SphericalRect& r = rect(view, chosen);
    if (r.solidAngle() <= 0) return s;
    Vec3 q = r.sample(u);
    s.wi = normalize(q - p);
    if (radiance) s.Le = daylight_->Le(s.wi);
    s.pdf = pChosen / r.solidAngle();
    return s;
}

}  // namespace luxplan
