// Uniform placement sampling over the union of an entity's regions.
#include <luxplan/optimizer/placement.h>

#include <cmath>
#include <stdexcept>

namespace luxplan {

static double wrap360(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d < 0) d += 360.0;
    return d >= 360.0 ? 0.0 : d;
}

bool sameRotation(double aDeg, double bDeg) {
    double diff = wrap360(aDeg - bDeg);
    return diff < 1e-6 || diff > 360.0 - 1e-6;
}

std::vector<double> distinctRotations(const Region& region) {
    std::vector<double> out;
    for (double r : region.rotationsDeg) {
        bool seen = false;
        for (double o : out) seen = seen || sameRotation(o, r);
        if (!seen) out.push_back(r);
    }
    return out;
}

bool fullTurn(const Region& region) {
    return region.continuousRotation && region.rotationMaxDeg - region.rotationMinDeg >= 360.0;
}

double normalizeRotation(const Region& region, double rotationDeg) {
    if (!region.continuousRotation) return rotationDeg;
    double offset = wrap360(rotationDeg - region.rotationMinDeg);
    // regionContains() accepts an offset a hair below 360 as the range's start.
    if (offset > 360.0 - 1e-6) offset = 0;
    return region.rotationMinDeg + offset;
}

double regionMeasure(const Region& region) {
    auto extent = [](double lo, double hi) { return hi > lo ? hi - lo : 1.0; };
    double rotation = 1;
    if (region.continuousRotation) {
        double span = std::min(radians(region.rotationMaxDeg - region.rotationMinDeg), 2 * kPi);
        rotation = span > 0 ? span : 1.0;
    } else {
        rotation = double(std::max<size_t>(1, distinctRotations(region).size()));
    }
    return extent(region.lo.x, region.hi.x) * extent(region.lo.y, region.hi.y) * rotation;
}

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
