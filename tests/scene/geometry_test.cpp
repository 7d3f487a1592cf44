// Room shell, furniture presets and solid voxels against their analytic areas and volumes.
#include <gtest/gtest.h>

#include <algorithm>

#include <luxplan/scene/presets.h>
#include <luxplan/scene/room.h>
#include <luxplan/scene/voxels.h>

namespace luxplan {
namespace {

RoomShell testRoom() {
    RoomShell room;
    room.box = Bounds3({0, 0, 0}, {6, 4, 3});
    room.floorMaterial = 0, room.wallMaterial = 1, room.ceilingMaterial = 2;
    Opening window;
    window.wall = Wall::South, window.offset = 1.5, window.width = 2.0, window.sill = 0.9, window.height = 1.5;
    window.material = 3u;
    Opening door;
    door.wall = Wall::East, door.offset = 0.5, door.width = 1.0, door.sill = 0, door.height = 2.1;
    Opening skylight;
    skylight.wall = Wall::Ceiling, skylight.center = {3, 2}, skylight.size = {1, 0.5};
    skylight.material = 3u;
    room.openings = {window, door, skylight};
    return room;
}

TEST(RoomShell, SurfaceAreasAccountForOpenings) {
    TriangleMesh m = buildRoomShell(testRoom());
    EXPECT_NEAR(m.area(0), 24.0, 1e-9);                           // floor
    EXPECT_NEAR(m.area(1), 2 * 6 * 3 + 2 * 4 * 3 - 3.0 - 2.1, 1e-9);  // walls minus window and door
    EXPECT_NEAR(m.area(2), 24.0 - 0.5, 1e-9);                     // ceiling minus skylight
    EXPECT_NEAR(m.area(3), 3.0 + 0.5, 1e-9);                      // panes of the glazed openings
}

TEST(RoomShell, SurfacesFaceInwards) {
    TriangleMesh m = buildRoomShell(testRoom());
    Vec3 center(3, 2, 1.5);
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const auto& tri = m.triangles[t];
        Vec3 c = (m.positions[tri[0]] + m.positions[tri[1]] + m.positions[tri[2]]) / 3.0;
        EXPECT_GT(dot(m.geometricNormal(t), center - c), 0) << "triangle " << t;
    }
}

TEST(Voxels, BoxVolumeMatchesAnalytic) {
    for (Vec3 size : {Vec3(1.2, 0.8, 0.04), Vec3(0.33, 0.57, 1.91), Vec3(0.05, 0.05, 0.7)}) {
        TriangleMesh m;
        addBox(m, Bounds3(Vec3(0.1, -0.2, 0.3), Vec3(0.1, -0.2, 0.3) + size), 0);
        VoxelGrid g = voxelizeSolid(m, 0.02);
        double exact = size.x * size.y * size.z;
        EXPECT_NEAR(g.volume(), exact, 0.02 * exact) << size.x << " " << size.y << " " << size.z;
    }
}

TEST(Voxels, RotatedBoxVolumeWithinTwoPercent) {
    // A box turned 30 degrees about z and 20 about x: its faces cut the cells at angles.
    TriangleMesh box;
    addBox(box, Bounds3({-0.4, -0.25, -0.3}, {0.4, 0.25, 0.3}), 0);
    Transform tilt;
    double a = radians(20);
    tilt.m = {1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a)};
    TriangleMesh m;
    m.append(box, Transform::rotateZ(radians(30)) * tilt);
    VoxelGrid g = voxelizeSolid(m, 0.01);
    EXPECT_NEAR(g.volume(), 0.8 * 0.5 * 0.6, 0.02 * 0.24);
}

TEST(Voxels, OverlappingPartsCountOnce) {
    TriangleMesh m;
    addBox(m, Bounds3({0, 0, 0}, {1, 1, 1}), 0);
    addBox(m, Bounds3({0.5, 0, 0}, {1.5, 1, 1}), 0);
    VoxelGrid g = voxelizeSolid(m, 0.05);
    EXPECT_NEAR(g.volume(), 1.5, 0.02 * 1.5);
    EXPECT_TRUE(g.contains({0.75, 0.5, 0.5}));
    EXPECT_FALSE(g.contains({2, 0.5, 0.5}));
}

// voxelizeSolid writes runs of cells layer by layer; cell by cell, each centre's winding
// number over the column's crossings at or below it, gives the same grid, cell for cell.
VoxelGrid windingCellByCell(const TriangleMesh& mesh, const VoxelGrid& shape) {
    VoxelGrid g = shape;
    g.occupied.assign(g.occupied.size(), 0);
    g.count = 0;
    const Vec3 c = g.cellSize();
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double px = g.bounds.lo.x + (i + 0.5) * c.x + 1.1e-6 * c.x, py = g.bounds.lo.y + (j + 0.5) * c.y + 1.3e-6 * c.y;
            std::vector<std::pair<double, int>> hits;
            for (const auto& tri : mesh.triangles) {
                const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &d = mesh.positions[tri[2]];
                const double area2 = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
                if (area2 == 0) continue;
                const double w0 = ((b.x - px) * (d.y - py) - (b.y - py) * (d.x - px)) / area2;
                const double w1 = ((d.x - px) * (a.y - py) - (d.y - py) * (a.x - px)) / area2;
                const double w2 = 1 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                hits.push_back({w0 * a.z + w1 * b.z + w2 * d.z, area2 < 0 ? +1 : -1});
            }
            std::sort(hits.begin(), hits.end());
            for (int k = 0; k < g.nz; ++k) {
                const double z = g.bounds.lo.z + (k + 0.5) * c.z;
                int winding = 0;
                for (const auto& [hz, sign] : hits)
                    if (hz <= z) winding += sign;
                if (winding != 0) g.occupied[g.index(i, j, k)] = 1, ++g.count;
            }
        }
    return g;
}

TEST(Voxels, RunsEqualTheWindingCellByCell) {
    std::vector<std::pair<std::string, TriangleMesh>> meshes;
    for (const char* name : {"desk", "office_chair", "monitor", "stand_lamp", "sofa", "bookshelf"}) {
        const PresetInfo* p = findPreset(name);
        meshes.push_back({name, buildPreset(*p, p->defaultSize, {{p->slots.front(), 0}})});
    }
    TriangleMesh overlapping;
    addBox(overlapping, Bounds3({0, 0, 0}, {1, 1, 1}), 0);
    addBox(overlapping, Bounds3({0.5, 0.2, 0.3}, {1.5, 0.8, 1.6}), 0);  // overlaps and sticks out above
    addBox(overlapping, Bounds3({0.2, 0.2, 1.2}, {0.4, 0.4, 1.5}), 0);  // floats apart: two runs per column
    meshes.push_back({"overlapping boxes", overlapping});
    TriangleMesh turned;
    Transform tilt;
    const double a = radians(25);
    tilt.m = {1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a)};
    turned.append(meshes[0].second, Transform::rotateZ(radians(30)) * tilt);
    meshes.push_back({"a tilted desk", turned});
    for (const auto& [name, mesh] : meshes) {
        const VoxelGrid g = voxelizeSolid(mesh, 0.03);
        const VoxelGrid want = windingCellByCell(mesh, g);
        EXPECT_GT(g.count, 0u) << name;
        EXPECT_EQ(g.count, want.count) << name;
        EXPECT_TRUE(g.occupied == want.occupied) << name;
    }
}

TEST(Presets, EveryPresetFillsItsBoxAndHasVolume) {
    const std::vector<std::string> required = {"table", "chair", "desk", "office_chair", "monitor", "bookshelf", "sofa",
                                               "armchair", "coffee_table", "tv", "bed", "stand_lamp", "conference_table",
                                               "projection_screen"};
    for (const auto& name : required) {
        const PresetInfo* p = findPreset(name);
        ASSERT_NE(p, nullptr) << name;
        TriangleMesh m = buildPreset(*p, p->defaultSize, {{p->slots.front(), 0}});
        Bounds3 b = m.bounds();
        Vec3 s = p->defaultSize;
        EXPECT_NEAR(b.lo.x, -s.x / 2, 1e-9) << name;
        EXPECT_NEAR(b.hi.x, s.x / 2, 1e-9) << name;
        EXPECT_NEAR(b.lo.y, -s.y / 2, 1e-9) << name;
        EXPECT_NEAR(b.hi.y, s.y / 2, 1e-9) << name;
        EXPECT_NEAR(b.lo.z, 0, 1e-9) << name;
        EXPECT_NEAR(b.hi.z, s.z, 1e-9) << name;
        VoxelGrid g = voxelizeSolid(m, 0.02);
        EXPECT_GT(g.volume(), 0.0) << name;
        EXPECT_LT(g.volume(), s.x * s.y * s.z) << name;
    }
}

TEST(Presets, ScreenSlotTakesItsOwnMaterial) {
    const PresetInfo* p = findPreset("monitor");
    TriangleMesh m = buildPreset(*p, p->defaultSize, {{"body", 0}, {"screen", 7}});
    EXPECT_GT(m.area(7), 0.1);
    // The screen faces -y, the preset's front.
    for (size_t t = 0; t < m.triangleCount(); ++t)
        if (m.materials[t] == 7 && m.geometricNormal(t).y < -0.99) return;
    FAIL() << "no screen triangle faces -y";
}

}  // namespace
}  // namespace luxplan
