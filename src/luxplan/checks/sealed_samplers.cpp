// Samplers that measure inside a closed opaque box, where the scene file places them,
// or that lie on one and look into it.
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/sealed_boxes.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {

// How close to a box's face a point counts as on it: within a sensor's ray offset
// (0.1 mm), so that its rays start on the far side.
constexpr double kOnFace = 5e-5;

}  // namespace

std::vector<Diagnostic> sealedSamplers(const Scene& scene) {
    std::vector<Diagnostic> out;
    if (scene.samplers.empty()) return out;
    const std::vector<Transform> world = worldTransforms(scene, initialLayout(scene));
    const SealedBoxes sealed(scene, world, EmitterSet(scene, world, EmitterSelection::PowerDistance));
    if (sealed.empty()) return out;
    for (const LightSamplerSpec& s : scene.samplers) {
        const Transform frame = s.entity >= 0 ? world[size_t(s.entity)] : Transform();
        const std::vector<Vec3> points = measurementPoints(s, frame);
        // A point on a face sees past it along its directions (a sensor's rays start
        // 0.1 mm along themselves): looking into the box, it sees the dark inside.
        const std::optional<Vec3> facing = s.type->facing(frame);
        const bool allRound = s.type->looksAllRound();
        int inside = 0, onFace = 0;
        Vec3 first, firstOnFace, exit, outward;
        for (const Vec3& p : points) {
            if (sealed.contain(p, exit)) {
                first = inside ? first : p, ++inside;
            } else if ((facing || allRound) && sealed.onFace(p, kOnFace, outward) &&
                       (allRound || dot(*facing, outward) < -1e-9)) {
                firstOnFace = onFace ? firstOnFace : p, ++onFace;
            }
        }
        const std::string where = s.entity >= 0 ? " (where \"" + scene.entities[size_t(s.entity)].path + "\" stands)" : "";
        const std::string count = " of its " + std::to_string(points.size()) + " points, e.g. ";
        if (inside)
            out.push_back({scene.file.string(), s.jsonPath,
                           "sampler \"" + s.name + "\" measures inside a closed opaque box" + where + ": " + std::to_string(inside) +
                               count + pointText(first) + ", where no light reaches (they read 0)"});
        if (onFace)
            out.push_back({scene.file.string(), s.jsonPath,
                           "sampler \"" + s.name + "\" lies on a closed opaque box" + where +
                               (allRound ? " and looks all round: " : " and faces into it: ") + std::to_string(onFace) + count +
                               pointText(firstOnFace) +
                               (allRound ? ", where half of its directions see the box's dark inside"
                                         : ", where it measures the box's dark inside (they read 0)")});
    }
    return out;
}

}  // namespace luxplan
