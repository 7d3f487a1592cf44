#include <luxplan/pathtracer/panes.h>

#include <cmath>

#include <luxplan/scene/room.h>

namespace luxplan {

OpeningPanes::OpeningPanes(const Scene& scene) {
    const RoomShell* room = scene.room();
    if (!room) return;
    for (const Opening& o : room->openings) {
        if (!o.material) continue;  // an open hole
        Bsdf bsdf = makeBsdf(scene.materials[*o.material]);
        if (!bsdf.passesStraight()) continue;  // a closed opening: opaque, Embree's job
        const Rect3 rect = openingQuad(room->box, o);
        panes_.push_back({RectTarget(rect), rect.normal(), std::move(bsdf)});
    }
}

double OpeningPanes::transmittance(const Vec3& p, const Vec3& w, double tMax) const {
    double T = 1;
    for (const Pane& pane : panes_) {
        const double t = pane.rect.intersect(p, w);
        if (t > 0 && t < tMax) T *= pane.bsdf.straightTransmittance(std::abs(dot(w, pane.normal)));
    }
    return T;
}

}  // namespace luxplan
