// The sky as a light, sampled through the room's openings (window portals). Inside
// the room every sky direction that can reach a point passes through one opening, so
// sampling the openings' spherical rectangles (Ureña et al. 2013, core/spherical_rect.h)
// wastes no samples on walls; outside, the sky map's own importance sampling is used.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/core/spherical_rect.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class SkyLight {
public:
    // A portal is chosen with a cheap weight (area x cos / distance^2 at its centre,
    // capped at 2 pi), then, when that weight is above kSphericalAbove, a direction
    // uniform in its spherical rectangle: pdf = P(portal) / solid angle; farther away, a
    // point uniform on its area: pdf = P(portal) d^2 / (area |cos|), which is nearly
    // uniform in solid angle there and needs no trigonometry. Only the rectangles a
    // vertex samples or an escaping ray passes through are set up (four acos each);
    // the view of a sampler point, shared by all its paths, sets up all. Openings
    // beyond kMaxPortals are not sampled directly (BSDF sampling still finds them, so
    // the estimate stays unbiased).
    static constexpr int kMaxPortals = 16;
    // Where d^2 / cos varies over a portal by more than about a third (a square seen
    // face on from less than its side away), the spherical rectangle.
    static constexpr double kSphericalAbove = 0.5;
    struct View {
        bool active = false;  // the vertex is inside the room: sample the portals
        int count = 0;
        Vec3 point;
        double weight[kMaxPortals] = {};
        bool spherical[kMaxPortals] = {};
        double weightTotal = 0;
        mutable SphericalRect rects[kMaxPortals];
        mutable bool built[kMaxPortals] = {};
        // A sensor's view only: a cone around the directions through each portal
        // (coneCos <= 0: none narrower than a hemisphere).
        Vec3 coneAxis[kMaxPortals];
        double coneCos[kMaxPortals] = {};
    };

    SkyLight() = default;
    // `daylight` may be null (night); `portals` false samples the sky map everywhere.
    SkyLight(const Scene& scene, const DaylightEnvironment* daylight, bool portals);

    bool active() const { return daylight_ && daylight_->hasSky(); }
    // Whether p is in the room, a millimetre of slack around its box (where a view is
    // active); false without a room.
    bool inRoom(const Vec3& p) const { return hasRoom_ && room_.contains(p); }
    // How far the ray p + t w, from a point inside the room, stays inside it: every
    // point before that distance is inRoom() (it is measured to half the slack, so
    // that the hits Embree places there in float are too); 0 without a room.
    double inRoomUntil(const Vec3& p, const Vec3& w) const;
    // The openings as seen from a path's first vertex: cached per thread, since every
    // path of a sampler point starts at the same place. The view stays valid until the
    // thread's next call.
    const View& viewFromSensor(const Vec3& p) const;
    // The openings as seen from a later vertex: rectangles set up on demand.
    void view(const Vec3& p, View& view) const { compute(p, view, false); }
    // Density (per solid angle) of sample() for direction w from the view's point p.
    double pdf(const View& view, const Vec3& p, const Vec3& w) const;
    // Whether sample() from a sensor's view may draw a direction the sensor sees.
    bool seenBy(const View& view, const Sensor& sensor) const;
    // `radiance` false: Le is left unset where the view is active (the caller looks it
    // up once it needs it, DaylightEnvironment::Le(wi)).
    EnvironmentSample sample(const View& view, const Vec3& p, Vec2 u, bool radiance = true) const;

private:
    void compute(const Vec3& p, View& view, bool buildAll) const;
    const SphericalRect& rect(const View& view, int i) const;

    const DaylightEnvironment* daylight_ = nullptr;
    bool portals_ = true;
    struct Portal {
        RectTarget target;
        Vec3 areaNormal;  // edgeU x edgeV: the opening's normal times its area
        Vec3 normal;      // unit
        double area = 0;
    };
    std::vector<Portal> openings_;
    Bounds3 room_;
    Bounds3 roomForRays_;  // the box with half of room_'s slack (inRoomUntil)
    bool hasRoom_ = false;
    uint64_t id_ = 0;  // unique per light, keys the per-thread view cache
};

}  // namespace luxplan
