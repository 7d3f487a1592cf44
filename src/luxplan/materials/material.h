// A surface material as the scene file describes it (docs/scene-format.md, "materials").
// Reflectances are linear RGB in [0,1]; photometric results use their luminance.
#pragma once

#include <string>

#include <luxplan/core/math.h>

namespace luxplan {

enum class MaterialType { Diffuse, Glossy, Glass, Mirror, Translucent };

struct Material {
    std::string name;
    MaterialType type = MaterialType::Diffuse;
    // diffuse: Lambertian albedo. glossy: specular reflectance at normal incidence
    // (the coat's F0). mirror: reflectance. translucent: Lambertian reflectance on the
    // side the light arrives from. Unused by glass.
    Vec3 reflectance{0.5, 0.5, 0.5};
    // glossy only: albedo of the diffuse base under the coat.
    Vec3 base{0.0, 0.0, 0.0};
    // glossy only: GGX alpha (the microfacet roughness, not squared again), in (0, 1].
    double roughness = 0.1;
    // glass only: transmittance of the thin pane at normal incidence, in [0, 1].
    double transmittance = 0.88;
    // translucent only: Lambertian transmittance to the other side (reflectance +
    // diffuseTransmittance <= 1 per channel).
    Vec3 diffuseTransmittance{0.0, 0.0, 0.0};
};

// Whether light never crosses the surface (not glass, not translucent).
inline bool isOpaque(const Material& m) {
    return m.type == MaterialType::Diffuse || m.type == MaterialType::Glossy || m.type == MaterialType::Mirror;
}

}  // namespace luxplan
