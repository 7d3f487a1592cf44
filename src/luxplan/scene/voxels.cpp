#include <luxplan/scene/voxels.h>

#include <algorithm>

namespace luxplan {

Vec3 VoxelGrid::cellCenter(int i, int j, int k) const {
    Vec3 c = cellSize();
    return bounds.lo + Vec3((i + 0.5) * c.x, (j + 0.5) * c.y, (k + 0.5) * c.z);
}

bool VoxelGrid::contains(const Vec3& p) const {
    if (count == 0 || !bounds.contains(p)) return false;
    Vec3 c = cellSize();
    int i = std::min(nx - 1, int((p.x - bounds.lo.x) / c.x));
    int j = std::min(ny - 1, int((p.y - bounds.lo.y) / c.y));
    int k = std::min(nz - 1, int((p.z - bounds.lo.z) / c.z));
    return occupied[index(i, j, k)] != 0;
}


VoxelGrid voxelizeSolid(const TriangleMesh& mesh, double cell, int maxCells) {
    VoxelGrid g;
    g.bounds = mesh.bounds();
    if (g.bounds.empty()) return g;
    Vec3 size = g.bounds.size();
    auto cells = [&](double extent) { return std::clamp(int(std::ceil(extent / cell - 1e-9)), 1, maxCells); };
    g.nx = cells(size.x), g.ny = cells(size.y), g.nz = cells(size.z);
    // A flat mesh (zero thickness) encloses no volume.
    if (size.x <= 0 || size.y <= 0 || size.z <= 0) {
        g.nx = std::max(g.nx, 1), g.ny = std::max(g.ny, 1), g.nz = std::max(g.nz, 1);
        g.occupied.assign(size_t(g.nx) * g.ny * g.nz, 0);
        return g;
    }
    g.occupied.assign(size_t(g.nx) * g.ny * g.nz, 0);
    Vec3 c = g.cellSize();

    // Crossings of every vertical column through cell centres: (z, +1 entering / -1 leaving).
    // Columns are nudged by an irrational fraction of a cell so that they never pass
    // exactly through a shared edge (which would count one crossing twice).
    const double nudgeX = 1.1e-6 * c.x, nudgeY = 1.3e-6 * c.y;
    std::vector<std::vector<std::pair<double, int>>> columns(size_t(g.nx) * g.ny);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3& a = mesh.positions[mesh.triangles[t][0]];
        const Vec3& b = mesh.positions[mesh.triangles[t][1]];
        const Vec3& d = mesh.positions[mesh.triangles[t][2]];
        double area2 = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);  // twice the signed xy area
        if (area2 == 0) continue;                                               // vertical: never crossed
        int sign = area2 < 0 ? +1 : -1;  // normal pointing down: a column going up enters the solid
        double lox = std::min({a.x, b.x, d.x}), hix = std::max({a.x, b.x, d.x});
        double loy = std::min({a.y, b.y, d.y}), hiy = std::max({a.y, b.y, d.y});
        int i0 = std::max(0, int(std::floor((lox - g.bounds.lo.x) / c.x - 0.5)));
        int i1 = std::min(g.nx - 1, int(std::ceil((hix - g.bounds.lo.x) / c.x - 0.5)));
        int j0 = std::max(0, int(std::floor((loy - g.bounds.lo.y) / c.y - 0.5)));
        int j1 = std::min(g.ny - 1, int(std::ceil((hiy - g.bounds.lo.y) / c.y - 0.5)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                double px = g.bounds.lo.x + (i + 0.5) * c.x + nudgeX, py = g.bounds.lo.y + (j + 0.5) * c.y + nudgeY;
                // Barycentric coordinates of (px, py) in the projected triangle.
                double w0 = ((b.x - px) * (d.y - py) - (b.y - py) * (d.x - px)) / area2;
                double w1 = ((d.x - px) * (a.y - py) - (d.y - py) * (a.x - px)) / area2;
                double w2 = 1 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                columns[size_t(j) * g.nx + i].push_back({w0 * a.z + w1 * b.z + w2 * d.z, sign});
            }
    }
    // Each column's runs of cells inside: a cell belongs with every crossing at or below
    // its centre. The runs are then written layer by layer, in the grid's own order (a
    // column's cells lie nx * ny apart: written column by column, a large solid would
    // wait on memory at every cell).
    auto centreZ = [&](int k) { return g.bounds.lo.z + (k + 0.5) * c.z; };
    auto firstCellAbove = [&](double z) {  // the lowest cell whose centre is at or above z
        int k = std::clamp(int(std::ceil((z - g.bounds.lo.z) / c.z - 0.5)), 0, g.nz);
        while (k > 0 && centreZ(k - 1) >= z) --k;
        while (k < g.nz && centreZ(k) < z) ++k;
        return k;
    };
    struct Run {
        int from, to;  // cells [from, to)
    };
    std::vector<Run> runs;
    std::vector<size_t> firstRun(columns.size() + 1, 0);
    for (size_t col = 0; col < columns.size(); ++col) {
        auto& hits = columns[col];
        firstRun[col] = runs.size();
        if (hits.empty()) continue;
        std::sort(hits.begin(), hits.end());
        int winding = 0;
        for (size_t h = 0; h < hits.size(); ++h) {
            winding += hits[h].second;
            const int from = firstCellAbove(hits[h].first);
            const int to = h + 1 < hits.size() ? firstCellAbove(hits[h + 1].first) : g.nz;
            if (winding == 0 || from >= to) continue;
            if (runs.size() > firstRun[col] && runs.back().to == from)
                runs.back().to = to;
            else
                runs.push_back({from, to});
        }
    }
    firstRun[columns.size()] = runs.size();
    std::vector<size_t> next(firstRun.begin(), firstRun.end() - 1);  // per column: its first run not yet past
    for (int k = 0; k < g.nz; ++k) {
        uint8_t* layer = g.occupied.data() + g.index(0, 0, k);
        for (size_t col = 0; col < columns.size(); ++col) {
            size_t& r = next[col];
            while (r < firstRun[col + 1] && runs[r].to <= k) ++r;
            if (r < firstRun[col + 1] && runs[r].from <= k) {
                layer[col] = 1;
                ++g.count;
            }
        }
    }
    return g;
}

}  // namespace luxplan
