// The glass panes of the room's openings, crossed analytically. Every shadow ray
// towards the sun or the sky from inside a daylit room leaves through a window: a
// closest-hit query to find its pane and another beyond it cost two rays for what
// a rectangle test and the pane's Fresnel transmittance give exactly. Embree keeps
// the panes under their own ray mask (kPaneMask), so shadow rays search only the
// other glass in the scene (glass furniture), if any.
#pragma once

#include <vector>

#include <luxplan/core/spherical_rect.h>
#include <luxplan/materials/bsdf.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class OpeningPanes {
public:
    OpeningPanes() = default;
    explicit OpeningPanes(const Scene& scene);

    // The product of the transmittances of every pane that p + t w (w unit) crosses
    // for 0 < t < tMax (1 if none).
    double transmittance(const Vec3& p, const Vec3& w, double tMax) const;

private:
    struct Pane {
        RectTarget rect;
        Vec3 normal;  // unit
        Bsdf bsdf;
    };
    std::vector<Pane> panes_;
};

}  // namespace luxplan
