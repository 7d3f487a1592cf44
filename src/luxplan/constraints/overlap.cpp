// Voxel overlap counting (Eq. 6) and its per-entity cache with undo.
#include <luxplan/constraints/overlap.h>

#include <algorithm>
#include <cmath>

namespace luxplan {
namespace {

Bounds3 intersect(const Bounds3& a, const Bounds3& b) {
    Bounds3 r;
    r.lo = max(a.lo, b.lo), r.hi = min(a.hi, b.hi);
    return r;
}

bool sameTransform(const Transform& a, const Transform& b) { return a.m == b.m && a.t == b.t; }

bool inside(const Bounds3& outer, const Bounds3& inner) {
    return inner.lo.x >= outer.lo.x && inner.lo.y >= outer.lo.y && inner.lo.z >= outer.lo.z &&
           inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

// Counts the occupied cells of `grid` within `worldRegion` whose centre, mapped by
// `toTarget` (grid frame -> target frame), satisfies `test`.
template <typename Test>
size_t countCells(const VoxelGrid& grid, const Transform& gridFromWorld, const Bounds3& worldRegion,
                  const Transform& toTarget, Test test) {
    if (grid.empty() || worldRegion.empty()) return 0;
    Bounds3 local = intersect(gridFromWorld.apply(worldRegion), grid.bounds);
    if (local.empty()) return 0;
    Vec3 c = grid.cellSize();
    auto range = [&](double lo, double hi, double origin, double cell, int n, int& i0, int& i1) {
        i0 = std::max(0, int(std::floor((lo - origin) / cell)));
        i1 = std::min(n - 1, int(std::floor((hi - origin) / cell)));
    };
    int i0, i1, j0, j1, k0, k1;
    range(local.lo.x, local.hi.x, grid.bounds.lo.x, c.x, grid.nx, i0, i1);
    range(local.lo.y, local.hi.y, grid.bounds.lo.y, c.y, grid.ny, j0, j1);
    range(local.lo.z, local.hi.z, grid.bounds.lo.z, c.z, grid.nz, k0, k1);
    size_t count = 0;
    for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j) {
            size_t row = grid.index(0, j, k);
            for (int i = i0; i <= i1; ++i)
                if (grid.occupied[row + i] && test(toTarget.applyPoint(grid.cellCenter(i, j, k)))) ++count;
        }
    return count;
}

double shared(const VoxelGrid& a, const Transform& worldFromA, const Transform& aFromWorld, const Bounds3& boxA,
              const VoxelGrid& b, const Transform& worldFromB, const Transform& bFromWorld, const Bounds3& boxB) {
    if (a.empty() || b.empty()) return 0;
    Bounds3 region = intersect(boxA, boxB);
    if (region.empty()) return 0;
    bool aFine = a.cellVolume() <= b.cellVolume();
    const VoxelGrid& fine = aFine ? a : b;
    const VoxelGrid& coarse = aFine ? b : a;
    const Transform& fineFromWorld = aFine ? aFromWorld : bFromWorld;
    Transform coarseFromFine = (aFine ? bFromWorld : aFromWorld) * (aFine ? worldFromA : worldFromB);
    size_t n = countCells(fine, fineFromWorld, region, coarseFromFine, [&](const Vec3& p) { return coarse.contains(p); });
    return double(n) * fine.cellVolume();
}

double outside(const VoxelGrid& grid, const Transform& worldFromGrid, const Transform& gridFromWorld, const Bounds3& box,
               const std::vector<Bounds3>& rooms) {
    if (grid.empty() || rooms.empty()) return 0;
    for (const Bounds3& r : rooms)
        if (inside(r, box)) return 0;
    // With one room, only the slabs of the box beyond its walls can hold outside cells.
    Bounds3 region = box;
    if (rooms.size() == 1) {
        const Bounds3& r = rooms[0];
        region = Bounds3();
        for (int axis = 0; axis < 3; ++axis) {
            if (box.lo[axis] < r.lo[axis]) {
                Bounds3 part = box;
                part.hi[axis] = std::min(box.hi[axis], r.lo[axis]);
                region.extend(part);
            }
            if (box.hi[axis] > r.hi[axis]) {
                Bounds3 part = box;
                part.lo[axis] = std::max(box.lo[axis], r.hi[axis]);
                region.extend(part);
            }
        }
    }
    size_t n = countCells(grid, gridFromWorld, region, worldFromGrid, [&](const Vec3& p) {
        for (const Bounds3& r : rooms)
            if (r.contains(p)) return false;
        return true;
    });
    return double(n) * grid.cellVolume();
}

}  // namespace

unsigned sidesCrossed(const Bounds3& room, const Bounds3& box) {
    unsigned sides = 0;
    const RoomSide low[3] = {RoomSide::West, RoomSide::South, RoomSide::Floor};
    const RoomSide high[3] = {RoomSide::East, RoomSide::North, RoomSide::Ceiling};
    for (int axis = 0; axis < 3; ++axis) {
        if (box.lo[axis] < room.lo[axis]) sides |= wallBit(low[axis]);
        if (box.hi[axis] > room.hi[axis]) sides |= wallBit(high[axis]);
    }
    return sides;
}

std::string describeSides(unsigned sides) {
    static const char* const names[6] = {"the west wall", "the east wall", "the south wall",
                                         "the north wall", "the floor", "the ceiling"};
    std::vector<std::string> parts;
    for (int s = 0; s < 6; ++s)
        if (sides & (1u << s)) parts.push_back(names[s]);
    if (parts.empty()) return "the walls";
    std::string out = parts[0];
    for (size_t i = 1; i < parts.size(); ++i) out += (i + 1 == parts.size() ? " and " : ", ") + parts[i];
    return out;
}

double sharedVolume(const VoxelGrid& a, const Transform& worldFromA, const VoxelGrid& b, const Transform& worldFromB) {
    return shared(a, worldFromA, worldFromA.inverse(), worldFromA.apply(a.bounds), b, worldFromB, worldFromB.inverse(),
                  worldFromB.apply(b.bounds));
}

double volumeOutside(const VoxelGrid& grid, const Transform& worldFromGrid, const std::vector<Bounds3>& rooms) {
    return outside(grid, worldFromGrid, worldFromGrid.inverse(), worldFromGrid.apply(grid.bounds), rooms);
}

OverlapEvaluator::OverlapEvaluator(const Scene& scene, const EntityInfo& info)
    : scene_(&scene), pairsOf_(scene.entities.size()), cache_(scene.entities.size()) {
    for (const StaticItem& g : scene.geometry)
        if (g.room) rooms_.push_back(g.room->box);
    std::vector<int> solid;
    for (size_t i = 0; i < scene.entities.size(); ++i)
        if (!scene.entities[i].voxels.empty()) solid.push_back(int(i));
    const double tolerance = scene.overlap.tolerance, hard = scene.overlap.wallTolerance;
    auto add = [&](Pair p) {
        pairsOf_[p.a].push_back(int(pairs_.size()));
        if (p.target == OverlapTarget::Entity) pairsOf_[p.b].push_back(int(pairs_.size()));
        pairs_.push_back(p);
    };
    for (size_t x = 0; x < solid.size(); ++x) {
        int a = solid[x];
        double va = scene.entities[a].voxels.volume();
        for (size_t y = x + 1; y < solid.size(); ++y) {
            int b = solid[y];
            if (info.related(a, b) || (!info.canMove(a) && !info.canMove(b))) continue;
            add({OverlapTarget::Entity, a, b, tolerance * std::min(va, scene.entities[b].voxels.volume())});
        }
        if (!info.canMove(a)) continue;
        for (size_t g = 0; g < scene.geometry.size(); ++g)
            if (!scene.geometry[g].voxels.empty()) add({OverlapTarget::Static, a, int(g), hard});
        if (!rooms_.empty()) add({OverlapTarget::Walls, a, -1, hard});
    }
    stamp_.assign(pairs_.size(), 0);
}

double OverlapEvaluator::compute(const Pair& p) const {
    const EntityCache& a = cache_[p.a];
    const VoxelGrid& ga = scene_->entities[p.a].voxels;
    switch (p.target) {
        case OverlapTarget::Entity: {
            const EntityCache& b = cache_[p.b];
            return shared(ga, a.world, a.fromWorld, a.box, scene_->entities[p.b].voxels, b.world, b.fromWorld, b.box);
        }
        case OverlapTarget::Static: {
            const VoxelGrid& gb = scene_->geometry[p.b].voxels;
            static const Transform identity;
            return shared(ga, a.world, a.fromWorld, a.box, gb, identity, identity, gb.bounds);
        }
        case OverlapTarget::Walls: return outside(ga, a.world, a.fromWorld, a.box, rooms_);
    }
    return 0;
}

unsigned OverlapEvaluator::sides(const Pair& p) const {
    // Against the room the entity's box overlaps most (the only one, usually).
    const Bounds3& box = cache_[p.a].box;
    const Bounds3* best = nullptr;
    double most = -1;
    for (const Bounds3& r : rooms_) {
        Vec3 s = max(Vec3(), min(r.hi, box.hi) - max(r.lo, box.lo));
        if (s.x * s.y * s.z > most) most = s.x * s.y * s.z, best = &r;
    }
    return best ? sidesCrossed(*best, box) : 0;
}

void OverlapEvaluator::update(const std::vector<Transform>& world) {
    ++epoch_;
    recomputed_ = 0;
    std::vector<int> dirty;
    for (size_t e = 0; e < cache_.size(); ++e) {
        if (pairsOf_[e].empty()) continue;
        EntityCache& c = cache_[e];
        if (c.valid && sameTransform(c.world, world[e])) continue;
        entityUndo_.push_back({int(e), c});
        c.world = world[e];
        c.fromWorld = world[e].inverse();
        c.box = world[e].apply(scene_->entities[e].voxels.bounds);
        c.valid = true;
        dirty.push_back(int(e));
    }
    for (int e : dirty)
        for (int p : pairsOf_[e]) {
            if (stamp_[p] == epoch_) continue;
            stamp_[p] = epoch_;
            pairUndo_.push_back({p, pairs_[p].volume, pairs_[p].walls});
            pairs_[p].volume = compute(pairs_[p]);
            if (pairs_[p].target == OverlapTarget::Walls) pairs_[p].walls = pairs_[p].volume > 0 ? sides(pairs_[p]) : 0;
            ++recomputed_;
        }
}

void OverlapEvaluator::commit() {
    entityUndo_.clear();
    pairUndo_.clear();
}

void OverlapEvaluator::revert() {
    for (auto it = pairUndo_.rbegin(); it != pairUndo_.rend(); ++it) {
        pairs_[it->pair].volume = it->volume;
        pairs_[it->pair].walls = it->walls;
    }
    for (auto it = entityUndo_.rbegin(); it != entityUndo_.rend(); ++it) cache_[it->first] = it->second;
    commit();
}

}  // namespace luxplan
