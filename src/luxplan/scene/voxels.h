// Solid voxelization of closed meshes, for the overlap constraint (the paper's
// Eq. 6 counts shared voxels). Built once per object at load time, in its frame.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/scene/mesh.h>

namespace luxplan {

// A regular grid over `bounds`, nx*ny*nz cells (not necessarily cubic: the cell
// count per axis is chosen so the cells fit the bounds exactly).
struct VoxelGrid {
    Bounds3 bounds;
    int nx = 0, ny = 0, nz = 0;
    std::vector<uint8_t> occupied;  // x fastest, then y, then z
    size_t count = 0;               // occupied cells

    bool empty() const { return count == 0; }
    Vec3 cellSize() const { Vec3 s = bounds.size(); return {s.x / nx, s.y / ny, s.z / nz}; }
    double cellVolume() const { Vec3 c = cellSize(); return c.x * c.y * c.z; }
    double volume() const { return double(count) * cellVolume(); }
    size_t index(int i, int j, int k) const { return (size_t(k) * ny + j) * nx + i; }
    Vec3 cellCenter(int i, int j, int k) const;
    // Whether the point lies in an occupied cell.
    bool contains(const Vec3& p) const;
};

// Voxelizes the solid enclosed by `mesh` (a union of closed parts; overlapping parts
// are fine). Along each column of cell centres the winding number of the crossings
// decides inside (non-zero) from outside. `cell` is the target cell size in metres;
// at most `maxCells` cells per axis.
VoxelGrid voxelizeSolid(const TriangleMesh& mesh, double cell = 0.02, int maxCells = 256);

}  // namespace luxplan
