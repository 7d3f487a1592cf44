// Overlap (the paper's Eq. 6): volume shared by the solid voxels of two entities,
// of an entity and static geometry, or outside the room shell, with a cache so a
// move recomputes only the pairs of the entities it moved. Between entities it is the
// paper's soft term; into walls, static geometry and blockers a hard limit
// (geometry_cost.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/terms.h>

namespace luxplan {

// Volume (m^3) of the solid of `a` inside the solid of `b`, each given by its voxel
// grid and world transform. Counts the cell centres of the finer grid (smaller cell
// volume; `a` on a tie) that fall in occupied cells of the other, times the finer
// cell volume; only cells inside the intersection of the two world bounds are visited.
double sharedVolume(const VoxelGrid& a, const Transform& worldFromA, const VoxelGrid& b, const Transform& worldFromB);

// Volume (m^3) of the solid whose cell centres lie outside every room box (world
// frame): what an entity pushes into (or through) the room shell.
double volumeOutside(const VoxelGrid& grid, const Transform& worldFromGrid, const std::vector<Bounds3>& rooms);

// The sides of a room box, as bits: the west (x min), east, south (y min), north
// walls, the floor and the ceiling.
enum class RoomSide { West, East, South, North, Floor, Ceiling };
inline constexpr unsigned wallBit(RoomSide s) { return 1u << unsigned(s); }
// The sides of `room` that `box` reaches past.
unsigned sidesCrossed(const Bounds3& room, const Bounds3& box);
// "the west wall", "the west wall and the floor"; "the walls" for none.
std::string describeSides(unsigned sides);

class OverlapEvaluator {
public:
    // A candidate overlap: its reference (between entities the paper's V_ref,
    // Scene::overlap.tolerance times the smaller volume; against the walls and static
    // items the hard limit Scene::overlap.wallTolerance) and the current shared volume.
    struct Pair {
        OverlapTarget target = OverlapTarget::Entity;
        int a = -1;  // entity
        int b = -1;  // entity, geometry index, or -1 for the walls
        double reference = 0;
        double volume = 0;
        unsigned walls = 0;  // the walls: the sides of the room `a`'s box crosses (wallBit())

        bool hard() const { return target != OverlapTarget::Entity; }
    };

    // Candidates: every two entities with solid voxels that are not ancestor and
    // descendant (members of one group included) and of which at least one can
    // move; every such movable entity against every static item with voxels
    // (boxes, meshes, invisible blockers) and against the walls (when the scene has
    // a room). Pairs that can never move are left out: they cannot change.
    OverlapEvaluator(const Scene& scene, const EntityInfo& info);

    // Brings every pair volume up to date for `world`. Only pairs of entities whose
    // world transform differs from the last update are recomputed.
    void update(const std::vector<Transform>& world);
    // The last update becomes the state revert() returns to.
    void commit();
    // Undoes every update since the last commit (a rejected proposal).
    void revert();

    const std::vector<Pair>& pairs() const { return pairs_; }
    // Pair volumes computed by the last update (for tests and statistics).
    size_t recomputed() const { return recomputed_; }

private:
    struct EntityCache {
        Transform world, fromWorld;
        Bounds3 box;  // world bounds of the voxel grid
        bool valid = false;
    };
    double compute(const Pair& p) const;
    unsigned sides(const Pair& p) const;
    struct PairUndo {
        int pair;
        double volume;
        unsigned walls;
    };

    const Scene* scene_;
    std::vector<Bounds3> rooms_;
    std::vector<Pair> pairs_;
    std::vector<std::vector<int>> pairsOf_;  // per entity: indices into pairs_
    std::vector<EntityCache> cache_;         // per entity
    std::vector<std::pair<int, EntityCache>> entityUndo_;
    std::vector<PairUndo> pairUndo_;
    std::vector<uint64_t> stamp_;  // per pair: the update that last recomputed it
    uint64_t epoch_ = 0;
    size_t recomputed_ = 0;
};

}  // namespace luxplan
