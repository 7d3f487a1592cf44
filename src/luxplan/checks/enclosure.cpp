// Emitters enclosed by opaque geometry: rays from the emitter in every direction it
// emits, each tested for what it meets first.
#include <luxplan/checks/scene_warnings.h>

#include <cmath>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/rt/embree_scene.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {

// Directions spread evenly over the sphere (a Fibonacci lattice).
std::vector<Vec3> sphereDirections(int n) {
    std::vector<Vec3> out;
    const double golden = kPi * (3 - std::sqrt(5.0));
    for (int k = 0; k < n; ++k) {
        double z = 1 - (2 * k + 1.0) / n, r = std::sqrt(std::max(0.0, 1 - z * z));
        out.push_back({r * std::cos(golden * k), r * std::sin(golden * k), z});
    }
    return out;
}

bool related(const Scene& scene, int a, int b) {
    for (int e = a; e >= 0; e = scene.entities[size_t(e)].parent)
        if (e == b) return true;
    for (int e = b; e >= 0; e = scene.entities[size_t(e)].parent)
        if (e == a) return true;
    return false;
}

}  // namespace

std::vector<Diagnostic> enclosedEmitters(const Scene& scene) {
    std::vector<Diagnostic> out;
    if (scene.emitters.empty()) return out;
    const Layout layout = initialLayout(scene);
    const std::vector<Transform> world = worldTransforms(scene, layout);
    const EmbreeScene rt(scene, layout);
    const std::vector<Vec3> directions = sphereDirections(kEnclosureRays);
    const unsigned surfaces = kOpaqueMask | kGlassMask | kPaneMask;  // everything but the emitters
    for (const Emitter& e : scene.emitters) {
        const Transform& frame = e.entity >= 0 ? world[size_t(e.entity)] : Transform();
        std::shared_ptr<const EmitterShape> shape = e.shape->transformed(frame);
        const std::optional<Vec3> normal = shape->normal();
        // A flat emitter lights its front only: rays from just in front of it.
        const Vec3 origin = shape->center() + (normal ? *normal * 1e-3 : Vec3());
        std::string by;
        bool enclosed = true;
        for (Vec3 d : directions) {
            if (normal && dot(d, *normal) <= 0) continue;
            auto hit = rt.intersect({origin, d, 0, kInf, surfaces});
            bool own = hit && isOpaque(scene.materials[hit->material]) &&
                       (e.entity >= 0 ? hit->kind == HitKind::Entity && related(scene, hit->index, e.entity)
                                      : hit->kind == HitKind::Static && !scene.geometry[size_t(hit->index)].room);
            if (!own) {
                enclosed = false;
                break;
            }
            if (by.empty()) by = hit->kind == HitKind::Entity ? scene.entities[size_t(hit->index)].path
                                                               : scene.geometry[size_t(hit->index)].name;
        }
        if (!enclosed) continue;
        out.push_back({scene.file.string(), e.jsonPath,
                       "emitter \"" + e.name + "\" is enclosed by opaque geometry of \"" + by +
                           "\" (every ray from it meets an opaque surface of it): it lights nothing; open it or give it "
                           "a translucent material"});
    }
    return out;
}

}  // namespace luxplan
