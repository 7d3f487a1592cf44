// The footprint rule: footprint corners against the room's floor and against
// footprint-bound regions.
#include <luxplan/constraints/footprint.h>

#include <algorithm>
#include <cmath>

#include <luxplan/constraints/relational.h>

namespace luxplan {
namespace {

// Distance from p to the rectangle [lo, hi] (0 inside).
double outside(Vec2 p, Vec2 lo, Vec2 hi) {
    double dx = std::max({lo.x - p.x, p.x - hi.x, 0.0}), dy = std::max({lo.y - p.y, p.y - hi.y, 0.0});
    return std::sqrt(dx * dx + dy * dy);
}

double footprintPenalty(double excess) {
    double x = excess / kFootprintScale;
    return 1 + x * x;
}

}  // namespace

FootprintEvaluator::FootprintEvaluator(const Scene& scene, const EntityInfo& info) : scene_(&scene), info_(&info) {
    for (const StaticItem& g : scene.geometry)
        if (g.room) rooms_.push_back(g.room->box);
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& e = scene.entities[i];
        if (!info.canMove(int(i)) || info.geometrySubtree(int(i)).empty()) continue;
        bool parentHolds = e.parent >= 0 && scene.entities[size_t(e.parent)].inRoom;
        if (!rooms_.empty() && e.inRoom && !parentHolds) roomEntities_.push_back(int(i));
        if (std::any_of(e.regions.begin(), e.regions.end(), [](const Region& r) { return r.bound == RegionBound::Footprint; }))
            regionEntities_.push_back(int(i));
    }
}

std::vector<Vec2> FootprintEvaluator::corners(const std::vector<Transform>& world, int entity,
                                              const Transform& frameFromWorld) const {
    std::vector<Vec2> out;
    for (int o : info_->geometrySubtree(entity)) {
        const Bounds3& b = info_->localBounds(o);
        Transform toFrame = frameFromWorld * world[size_t(o)];
        for (Vec2 c : {Vec2(b.lo.x, b.lo.y), Vec2(b.hi.x, b.lo.y), Vec2(b.hi.x, b.hi.y), Vec2(b.lo.x, b.hi.y)}) {
            Vec3 p = toFrame.applyPoint({c.x, c.y, 0});
            out.push_back({p.x, p.y});
        }
    }
    return out;
}

std::vector<FootprintTerm> FootprintEvaluator::evaluate(const std::vector<Transform>& world) const {
    std::vector<FootprintTerm> terms;
    static const Transform identity;
    for (int e : roomEntities_) {
        double excess = 0;
        for (Vec2 c : corners(world, e, identity)) {
            double d = kInf;
            for (const Bounds3& r : rooms_) d = std::min(d, outside(c, {r.lo.x, r.lo.y}, {r.hi.x, r.hi.y}));
            excess = std::max(excess, d);
        }
        if (excess > kFootprintTolerance) terms.push_back({e, FootprintBound::Room, -1, excess, footprintPenalty(excess)});
    }
    for (int e : regionEntities_) {
        const Entity& entity = scene_->entities[size_t(e)];
        const Transform parentFromWorld = entity.parent < 0 ? identity : world[size_t(entity.parent)].inverse();
        const Transform local = parentFromWorld * world[size_t(e)];
        const double rotation = wrapDegrees(degrees(std::atan2(local.m[3], local.m[0])));
        const Vec2 origin(local.t.x, local.t.y);
        // The least excess over the footprint regions holding the placement; none if an
        // origin region holds it.
        FootprintTerm best{e, FootprintBound::Region, -1, kInf, 0};
        bool held = false;
        std::vector<Vec2> points;
        for (size_t k = 0; k < entity.regions.size() && !held; ++k) {
            const Region& r = entity.regions[k];
            if (!regionContains(r, origin, rotation, kRegionTolerance)) continue;
            if (r.bound == RegionBound::Origin) {
                held = true;
                break;
            }
            if (points.empty()) points = corners(world, e, parentFromWorld);
            double excess = 0;
            for (Vec2 c : points) excess = std::max(excess, outside(c, r.lo, r.hi));
            if (excess <= kFootprintTolerance) held = true;
            else if (excess < best.excess) best.region = int(k), best.excess = excess;
        }
        if (held || best.region < 0) continue;
        best.penalty = footprintPenalty(best.excess);
        terms.push_back(best);
    }
    return terms;
}

std::string describe(const Scene& scene, const FootprintTerm& t) {
    const Entity& e = scene.entities[size_t(t.entity)];
    std::string s = "footprint \"" + e.path + "\" / ";
    if (t.bound == FootprintBound::Room) {
        std::string room;
        for (const StaticItem& g : scene.geometry)
            if (g.room) room = room.empty() ? "room \"" + g.name + "\"" : std::string("the rooms");
        s += room + ": " + describeNumber(t.excess) + " m outside";
    } else {
        s += "region " + std::to_string(t.region) + " (" + e.jsonPath + "/placement/regions/" + std::to_string(t.region) +
             "): " + describeNumber(t.excess) + " m outside";
    }
    return s + ", P = " + describeNumber(t.penalty);
}

}  // namespace luxplan
