// Uniform placement sampling over the union of an entity's regions.
#include <luxplan/optimizer/placement.h>

#include <cmath>
#include <stdexcept>

namespace luxplan {

Placement sampleInRegion(const Entity& entity, int index, double z, Rng& rng) {
    const Region& r = entity.regions.at(size_t(index));
    Placement p;
    p.region = index;
    p.position = Vec3(r.lo.x + rng.uniform() * (r.hi.x - r.lo.x), r.lo.y + rng.uniform() * (r.hi.y - r.lo.y), z);
    if (r.continuousRotation) {
        double span = std::min(r.rotationMaxDeg - r.rotationMinDeg, 360.0);
        p.rotationDeg = r.rotationMinDeg + rng.uniform() * span;
    } else {
        std::vector<double> rotations = distinctRotations(r);
        p.rotationDeg = rotations.empty() ? entity.rotationDeg : rotations[rng.uniformInt(uint32_t(rotations.size()))];
    }
    return p;
}

Placement samplePlacement(const Entity& entity, double z, Rng& rng) {
    if (entity.regions.empty()) throw std::invalid_argument("samplePlacement: entity \"" + entity.path + "\" is fixed");
    double total = 0;
    for (const Region& r : entity.regions) total += regionMeasure(r);
    double u = rng.uniform() * total;
    int chosen = int(entity.regions.size()) - 1;
    for (size_t i = 0; i < entity.regions.size(); ++i) {
        u -= regionMeasure(entity.regions[i]);
        if (u < 0) {
            chosen = int(i);
            break;
        }
    }
    return sampleInRegion(entity, chosen, z, rng);
}

Layout sampleLayout(const Scene& scene, const Layout& base, Rng& rng) {
    Layout layout = base;
    for (size_t i = 0; i < scene.entities.size(); ++i)
        if (scene.entities[i].movable())
            layout.placements[i] = samplePlacement(scene.entities[i], base.placements[i].position.z, rng);
    return layout;
}

}  // namespace luxplan
