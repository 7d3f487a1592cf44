// Luminaires and samplers outside the room, where the scene file places them; and
// samplers on the room's shell that look out through it.
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/room.h>

namespace luxplan {
namespace {

// A point on the shell (a luminaire flush with the ceiling) is inside.
constexpr double kSlack = 1e-3;

bool inside(const std::vector<Bounds3>& rooms, const Vec3& p) {
    for (const Bounds3& r : rooms)
        if (Bounds3(r.lo - Vec3(kSlack, kSlack, kSlack), r.hi + Vec3(kSlack, kSlack, kSlack)).contains(p)) return true;
    return false;
}

const char* const kFaceNames[3][2] = {{"west wall", "east wall"}, {"south wall", "north wall"}, {"floor", "ceiling"}};

// Whether p lies in one of the room's openings (on its wall's plane, within kSlack).
bool inAnOpening(const RoomShell& room, const Vec3& p) {
    for (const Opening& o : room.openings) {
        const Rect3 q = openingQuad(room.box, o);
        const Vec3 d = p - q.corner, n = q.normal();
        const double u = dot(d, q.edgeU) / dot(q.edgeU, q.edgeU), v = dot(d, q.edgeV) / dot(q.edgeV, q.edgeV);
        if (std::abs(dot(d, n)) <= kSlack && u >= 0 && u <= 1 && v >= 0 && v <= 1) return true;
    }
    return false;
}

// The face of the room's box that p lies on (within kSlack) and that a sampler looking
// along `facing` (or all round, without one) sees out through, as {axis, side}; none
// where p is off the shell or in an opening.
std::optional<std::array<int, 2>> faceLookedOutThrough(const RoomShell& room, const Vec3& p, const std::optional<Vec3>& facing) {
    const Bounds3& b = room.box;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const double plane = side ? b.hi[axis] : b.lo[axis];
            const double outward = !facing ? 1.0 : side ? (*facing)[axis] : -(*facing)[axis];
            if (std::abs(p[axis] - plane) > kSlack || outward <= 1e-9) continue;
            bool onFace = true;
            for (int other = 0; other < 3; ++other)
                if (other != axis && (p[other] < b.lo[other] - kSlack || p[other] > b.hi[other] + kSlack)) onFace = false;
            if (onFace && !inAnOpening(room, p)) return std::array<int, 2>{axis, side};
        }
    return std::nullopt;
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
    // A point on the shell sees past it (a sensor's rays start 0.1 mm along
    // themselves), so one that faces out, or looks all round, measures light from
    // outside the room.
    for (const LightSamplerSpec& s : scene.samplers) {
        const std::optional<Vec3> facing = s.type->facing(frame(s.entity));
        const bool allRound = s.type->looksAllRound();
        if (!facing && !allRound) continue;
        for (const Vec3& p : measurementPoints(s, frame(s.entity))) {
            std::optional<std::array<int, 2>> face;
            for (const StaticItem& g : scene.geometry)
                if (g.room && !face) face = faceLookedOutThrough(*g.room, p, allRound ? std::nullopt : facing);
            if (!face) continue;
            const std::string on = "sampler \"" + s.name + "\" lies on the room's " + kFaceNames[(*face)[0]][(*face)[1]] + where(s.entity);
            out.push_back({scene.file.string(), s.jsonPath,
                           allRound ? on + " and looks all round, at " + pointText(p) +
                                          ": half of its directions see outside the room"
                                    : on + " and faces out through it, at " + pointText(p) +
                                          ": it measures the light outside the room"});
            break;
        }
    }
    return out;
}

}  // namespace luxplan
