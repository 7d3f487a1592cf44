// Samplers that measure inside a closed opaque box, where the scene file places them,
// that lie on one and look into it, or just under a face they look out of.
#include <luxplan/checks/scene_warnings.h>

#include <cstdio>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/sealed_boxes.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {

// How close to a box's face a point counts as on it: within a sensor's ray offset
// (0.1 mm), so that its rays start on the far side.
constexpr double kOnFace = 5e-5;
// How deep under a face a point that looks out of it may lie: its rays start 0.1 mm
// along themselves, so those within acos(depth / 0.1 mm) of the face start inside the
// box, and cosine-weighted light loses (depth / 0.1 mm)^2 of itself: 1% at 0.01 mm.
constexpr double kUnderFace = 1e-5;

std::string millimetres(double metres) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g mm", metres * 1e3);
    return text;
}

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
        int inside = 0, onFace = 0, underFace = 0;
        Vec3 first, firstOnFace, firstUnderFace, exit, outward;
        double depth = 0, firstDepth = 0;
        for (const Vec3& p : points) {
            if (sealed.contain(p, exit)) {
                first = inside ? first : p, ++inside;
            } else if (sealed.nearestFace(p, kOnFace, outward, depth)) {
                if (allRound || (facing && dot(*facing, outward) < -1e-9)) {
                    firstOnFace = onFace ? firstOnFace : p, ++onFace;
                } else if (depth > kUnderFace) {
                    if (!underFace) firstUnderFace = p, firstDepth = depth;
                    ++underFace;
                }
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
        if (underFace)
            out.push_back({scene.file.string(), s.jsonPath,
                           "sampler \"" + s.name + "\" lies just inside a closed opaque box" + where + ", under the face it looks out of: " +
                               std::to_string(underFace) + count + pointText(firstUnderFace) + ", " + millimetres(firstDepth) +
                               " deep, where its rays start inside the box (they read low, and 0 from 0.1 mm down): place it on the face"});
    }
    return out;
}

}  // namespace luxplan
