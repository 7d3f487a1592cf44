// The footprint rule, a hard geometric limit beside the paper's terms: an entity's
// footprint is the floor projection of the bounding box of each object's parts (its
// own and every descendant's, each box turned with its object). It must stay inside
// the room (Entity::inRoom, by default for every top-level entity) and inside a
// region whose bound is the footprint (RegionBound::Footprint). Proposals still draw
// the origin; a footprint beyond its bound rejects the layout.
#pragma once

#include <string>
#include <vector>

#include <luxplan/constraints/entity_info.h>

namespace luxplan {

// How far (m) a footprint corner may lie outside its bound: float error in composed
// transforms, not a design margin (as kRegionTolerance).
inline constexpr double kFootprintTolerance = 1e-6;
// The distance (m) over which a footprint's violation grows by 1 (the repair of an
// infeasible start descends on it, geometry_cost.h).
inline constexpr double kFootprintScale = 0.01;

enum class FootprintBound { Room, Region };

// A footprint beyond its bound.
struct FootprintTerm {
    int entity = -1;
    FootprintBound bound = FootprintBound::Room;
    int region = -1;     // Region: the index into the entity's regions it was held to
    double excess = 0;   // m: how far the farthest corner lies outside
    // 1 + (excess / kFootprintScale)^2: above 1, so it rejects; the excess over 1 is
    // the violation.
    double penalty = 0;
};

class FootprintEvaluator {
public:
    // Entities held to the room: those with inRoom whose parent has not (the parent's
    // footprint holds its members'), that can move and have geometry, in a scene with a
    // room. Entities held to regions: movable ones with a footprint-bound region.
    FootprintEvaluator(const Scene& scene, const EntityInfo& info);

    // Every footprint beyond its bound under `world` (worldTransforms()). A placement
    // in an origin-bound region, or in none of its regions (a flat run's member out of
    // its group's reach), is not held to a region.
    std::vector<FootprintTerm> evaluate(const std::vector<Transform>& world) const;

    // The footprint's corners in `frameFromWorld`'s frame (z dropped): four per object.
    std::vector<Vec2> corners(const std::vector<Transform>& world, int entity, const Transform& frameFromWorld) const;

private:
    const Scene* scene_;
    const EntityInfo* info_;
    std::vector<Bounds3> rooms_;
    std::vector<int> roomEntities_, regionEntities_;
};

// e.g. `footprint "sofa" / room "room": 0.23 m outside, P = 530` or
// `footprint "shelf" / region 2 (/entities/1/placement/regions/2): ...`.
std::string describe(const Scene& scene, const FootprintTerm& term);

}  // namespace luxplan
