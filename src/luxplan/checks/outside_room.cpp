// Luminaires and samplers outside the room, where the scene file places them.
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace {

// A point on the shell (a luminaire flush with the ceiling) is inside.
constexpr double kSlack = 1e-3;

bool inside(const std::vector<Bounds3>& rooms, const Vec3& p) {
    for (const Bounds3& r : rooms)
        if (Bounds3(r.lo - Vec3(kSlack, kSlack, kSlack), r.hi + Vec3(kSlack, kSlack, kSlack)).contains(p)) return true;
    return false;
}

}  // namespace

std::vector<Diagnostic> outsideTheRoom(const Scene& scene) {
    std::vector<Diagnostic> out;
    std::vector<Bounds3> rooms;
    for (const StaticItem& g : scene.geometry)
        if (g.room) rooms.push_back(g.room->box);
    if (rooms.empty()) return out;
    const std::vector<Transform> world = worldTransforms(scene, initialLayout(scene));
    auto frame = [&](int entity) { return entity >= 0 ? world[size_t(entity)] : Transform(); };
    auto where = [&](int entity) { return entity >= 0 ? " (where \"" + scene.entities[size_t(entity)].path + "\" stands)" : ""; };

    for (const Emitter& e : scene.emitters) {
        Vec3 c = frame(e.entity).applyPoint(e.shape->center());
        if (!inside(rooms, c))
            out.push_back({scene.file.string(), e.jsonPath,
                           "luminaire \"" + e.name + "\" is outside the room, at " + pointText(c) + where(e.entity) +
                               ": it lights the room only through its openings"});
    }
    for (const LightSamplerSpec& s : scene.samplers) {
        const std::vector<Vec3> points = measurementPoints(s, frame(s.entity));
        int outside = 0;
        const Vec3* first = nullptr;
        for (const Vec3& p : points)
            if (!inside(rooms, p)) first = first ? first : &p, ++outside;
        if (outside)
            out.push_back({scene.file.string(), s.jsonPath,
                           "sampler \"" + s.name + "\" measures outside the room" + where(s.entity) + ": " +
                               std::to_string(outside) + " of its " + std::to_string(points.size()) + " points, e.g. " +
                               pointText(*first)});
    }
    return out;
}

}  // namespace luxplan
