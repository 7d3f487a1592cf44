#include <luxplan/scene/layout.h>

namespace luxplan {

static double wrapDegrees(double d) {
    d = std::fmod(d, 360.0);
    return d < 0 ? d + 360.0 : d;
}

bool regionContains(const Region& r, Vec2 xy, double rotationDeg, double eps) {
    if (xy.x < r.lo.x - eps || xy.x > r.hi.x + eps || xy.y < r.lo.y - eps || xy.y > r.hi.y + eps) return false;
    if (r.continuousRotation) {
        if (r.rotationMaxDeg - r.rotationMinDeg >= 360) return true;
        double from = wrapDegrees(r.rotationMinDeg), span = r.rotationMaxDeg - r.rotationMinDeg;
        double offset = wrapDegrees(rotationDeg - from);
        return offset <= span + 1e-6 || offset >= 360 - 1e-6;
    }
    for (double a : r.rotationsDeg) {
        double diff = wrapDegrees(rotationDeg - a);
        if (diff < 1e-6 || diff > 360 - 1e-6) return true;
    }
    return false;
}

int findRegion(const Entity& e, Vec2 xy, double rotationDeg) {
    for (size_t i = 0; i < e.regions.size(); ++i)
        if (regionContains(e.regions[i], xy, rotationDeg)) return int(i);
    return -1;
}

Layout initialLayout(const Scene& scene) {
    Layout layout;
    for (const Entity& e : scene.entities) {
        Placement p;
        p.position = e.position;
        p.rotationDeg = e.rotationDeg;
        p.region = findRegion(e, {e.position.x, e.position.y}, e.rotationDeg);
        layout.placements.push_back(p);
    }
    return layout;
}

Transform localTransform(const Placement& p) { return Transform::placement(p.position, p.rotationDeg); }

std::vector<Transform> worldTransforms(const Scene& scene, const Layout& layout) {
    std::vector<Transform> world(scene.entities.size());
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        Transform local = localTransform(layout.placements[i]);
        int parent = scene.entities[i].parent;
        world[i] = parent >= 0 ? world[parent] * local : local;
    }
    return world;
}

}  // namespace luxplan
