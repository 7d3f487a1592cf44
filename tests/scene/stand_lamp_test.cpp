// The stand_lamp preset: its shade is open at top and bottom (an emitter in it sees
// the ceiling and the floor) and its walls collide (they hold voxels).
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/scene/presets.h>
#include <luxplan/scene/voxels.h>

namespace luxplan {
namespace {

// Whether the vertical line through (x, y) crosses a triangle of `mesh` between z0 and z1.
bool crossedVertically(const TriangleMesh& mesh, double x, double y, double z0, double z1) {
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area == 0) continue;
        double w0 = ((b.x - x) * (c.y - y) - (b.y - y) * (c.x - x)) / area;
        double w1 = ((c.x - x) * (a.y - y) - (c.y - y) * (a.x - x)) / area;
        double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        double z = w0 * a.z + w1 * b.z + w2 * c.z;
        if (z > z0 && z < z1) return true;
    }
    return false;
}

TEST(StandLamp, TheShadeIsOpenAtTopAndBottomAndItsWallsCollide) {
    const PresetInfo* lamp = findPreset("stand_lamp");
    ASSERT_NE(lamp, nullptr);
    const Vec3 size = lamp->defaultSize;  // 0.35 x 0.35 x 1.6, the shade the top 0.32 m
    TriangleMesh m = buildPreset(*lamp, size, {{"body", 0}, {"shade", 1}});
    const double shadeFrom = size.z - 0.32;
    // From inside the shade, beside the pole, nothing above or below it up to the
    // base: straight up to the ceiling, straight down to the floor.
    for (Vec2 p : {Vec2(0.06, 0.06), Vec2(-0.12, 0.1), Vec2(0.15, -0.15)}) {
        EXPECT_FALSE(crossedVertically(m, p.x, p.y, shadeFrom, 10)) << p.x << " " << p.y;
        EXPECT_FALSE(crossedVertically(m, p.x, p.y, 0.031, shadeFrom)) << p.x << " " << p.y;
    }
    // The shade's walls, in the shade slot, hold solid voxels at their height.
    double shadeArea = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t)
        if (m.materials[t] == 1) {
            const Vec3 &a = m.positions[m.triangles[t][0]], &b = m.positions[m.triangles[t][1]],
                       &c = m.positions[m.triangles[t][2]];
            shadeArea += 0.5 * length(cross(b - a, c - a));
        }
    EXPECT_GT(shadeArea, 4 * 0.35 * 0.32);  // four walls, both faces
    VoxelGrid g = voxelizeSolid(m, 0.02);
    int shadeCells = 0;
    for (int k = 0; k < g.nz; ++k)
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (g.occupied[g.index(i, j, k)] && g.cellCenter(i, j, k).z > shadeFrom) ++shadeCells;
    // The four walls' ring of edge cells, all the way up: 4 (n - 1) columns of the grid.
    EXPECT_EQ(shadeCells, 4 * (g.nx - 1) * int(std::round(0.32 / g.cellSize().z)));
}

}  // namespace
}  // namespace luxplan
