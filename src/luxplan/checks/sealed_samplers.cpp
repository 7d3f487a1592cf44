// Samplers that measure inside a closed opaque box, where the scene file places them.
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/pathtracer/sealed_boxes.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

std::vector<Diagnostic> sealedSamplers(const Scene& scene) {
    std::vector<Diagnostic> out;
    if (scene.samplers.empty()) return out;
    const std::vector<Transform> world = worldTransforms(scene, initialLayout(scene));
    const SealedBoxes sealed(scene, world, EmitterSet(scene, world, EmitterSelection::PowerDistance));
    if (sealed.empty()) return out;
    for (const LightSamplerSpec& s : scene.samplers) {
        const Transform frame = s.entity >= 0 ? world[size_t(s.entity)] : Transform();
        const std::vector<Vec3> points = measurementPoints(s, frame);
        int inside = 0;
        Vec3 first, exit;
        for (const Vec3& p : points)
            if (sealed.contain(p, exit)) first = inside ? first : p, ++inside;
        if (!inside) continue;
        const std::string where = s.entity >= 0 ? " (where \"" + scene.entities[size_t(s.entity)].path + "\" stands)" : "";
        out.push_back({scene.file.string(), s.jsonPath,
                       "sampler \"" + s.name + "\" measures inside a closed opaque box" + where + ": " +
                           std::to_string(inside) + " of its " + std::to_string(points.size()) + " points, e.g. " + pointText(first) +
                           ", where no light reaches (they read 0)"});
    }
    return out;
}

}  // namespace luxplan
