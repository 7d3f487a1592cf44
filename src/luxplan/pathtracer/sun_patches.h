// The sunlit patches of a room as a light: a strategy for the sun's light that has
// bounced once inside the room. A desk lit by the morning sun's patch on the floor sees
// it by way of the ceiling (desk -> ceiling -> floor -> sun), and BSDF sampling at the
// ceiling finds the patch only when its direction happens to land there. This strategy
// draws the patch point instead: a sun direction, then a point uniform on the openings'
// area as the sun sees it (each opening by its projected area), then the first surface
// the sunbeam through that point meets in the room. The point's density on that surface
// is |cos| / (projected area of the openings): the beam's cross-section is kept, so
// it is the same all over the patch. The path tracer connects the patch point to a
// vertex and to the sun, and weighs it against BSDF sampling by MIS.
#pragma once

#include <vector>

#include <luxplan/core/spherical_rect.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class SunPatches {
public:
    SunPatches() = default;
    // Uses the room's openings that let sunlight through unscattered (open, or clear
    // panes). Inactive without a room, or when `enabled` is false (shadedByShell()
    // works either way).
    SunPatches(const Scene& scene, bool enabled);

    bool active() const { return enabled_ && !openings_.empty(); }
    // True when p is strictly inside the room's box and p + t ws leaves it through the
    // shell outside every opening that lets sunlight through, the shell being opaque:
    // such a ray is blocked whatever the layout, with no ray traced. p is the shadow
    // ray's origin, offset from its surface: a vertex on the shell's outer face (a path
    // that went out of a window) then lies outside the box.
    bool shadedByShell(const Vec3& p, const Vec3& ws) const;
    // True only when shadedByShell(q, w) holds for every q within `offset` of p and
    // every unit w within `halfAngle` (radians) of the unit `axis`: a sun disk whose
    // every sample is blocked there (conservative: false when unsure).
    bool shadesCone(const Vec3& p, double offset, const Vec3& axis, double halfAngle) const;
    // The area of the openings that face `ws` (towards the sun) projected across it.
    double projectedArea(const Vec3& ws) const;
    // A point on an opening facing `ws`, uniform in projected area (the opening chosen
    // by u.x, which is then reused within it). False when no opening faces the sun.
    bool sampleEntry(const Vec3& ws, Vec2 u, Vec3& entry) const;
    // The area density, at y on a surface with normal n, of the first hit of the ray
    // from sampleEntry's point along -ws: |n . ws| / projectedArea(ws) when y lies in
    // the room and y + t ws leaves it through an opening; 0 when this strategy cannot
    // produce y.
    double density(const Vec3& y, const Vec3& n, const Vec3& ws) const;
    // Whether y is inside the room (where sampled patch points must lie).
    bool inRoom(const Vec3& y) const { return room_.contains(y); }
    // Where the sunbeam through p, travelling along `beam` (away from the sun), leaves
    // the room's box: the same point for every p on the beam inside the room, and a
    // stand-in for where it lands, for a vertex to tell without a ray whether the beam
    // can light anything it faces.
    Vec3 beamEnd(const Vec3& p, const Vec3& beam) const;

    // The openings that let sunlight through unscattered, and whether the rest of the
    // shell is opaque (open_sun_disks.h tests many cones against them at once).
    struct Entrance {
        RectTarget target;
        Vec3 outward;  // unit
        double area = 0;
        Vec3 unitU, unitV;  // the rectangle's edges as unit vectors, and their lengths
        double lengthU = 0, lengthV = 0;
    };
    const std::vector<Entrance>& entrances() const { return openings_; }
    bool opaqueShell() const { return opaqueShell_; }
    const Bounds3& shell() const { return shell_; }

private:
    std::vector<Entrance> openings_;
    Bounds3 room_;
    Bounds3 shell_;  // the room's box itself
    bool enabled_ = false;
    bool opaqueShell_ = false;
};

}  // namespace luxplan
