// scene.glb as luxplan's own glTF import reads it (io/mesh_io.h): its y-up to z-up
// turn must give the scene's bounds back, under any layout. The scene is
// output/gltf_test.cpp's.
#include <gtest/gtest.h>

#include <luxplan/io/mesh_io.h>
#include <luxplan/output/gltf_export.h>
#include "support/scene_builder.h"
#include "support/shared_scenes.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

constexpr size_t kEmitterTriangles = 2 + 48 + 320;  // rect, disk, icosphere

// The bounds of everything visible under a layout, and its triangle count (emitters included).
std::pair<Bounds3, size_t> visibleGeometry(const Scene& scene, const Layout& layout) {
    std::vector<Transform> world = worldTransforms(scene, layout);
    Bounds3 bounds;
    size_t triangles = kEmitterTriangles;
    for (const StaticItem& item : scene.geometry) {
        if (item.invisible) continue;
        bounds.extend(item.mesh.bounds());
        triangles += item.mesh.triangleCount();
    }
    for (size_t i = 0; i < scene.entities.size(); ++i) {
        const Entity& ent = scene.entities[i];
        if (!ent.hasGeometry()) continue;
        TriangleMesh placed;
        placed.append(ent.mesh, world[i]);
        bounds.extend(placed.bounds());
        triangles += ent.mesh.triangleCount();
    }
    return {bounds, triangles};
}

void expectBounds(const Bounds3& b, const Bounds3& expected) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.lo[k], expected.lo[k], 1e-5) << k;
        EXPECT_NEAR(b.hi[k], expected.hi[k], 1e-5) << k;
    }
}

TEST(GlbImport, LuxplanImportGivesTheSceneBack) {
    test::TempDir dir;
    const Scene scene = test::furnishedRoom();
    const Layout layout = initialLayout(scene);
    const auto file = dir.path() / "scene.glb";
    writeGlb(file, scene, layout);
    auto [bounds, triangles] = visibleGeometry(scene, layout);
    TriangleMesh back = io::loadMeshFile(file, 0);
    EXPECT_EQ(back.triangleCount(), triangles);
    expectBounds(back.bounds(), bounds);

    // Another layout moves the desk (and its lamp) to the room's north-east, past the
    // pillar's bounds: the file's bounds follow.
    Layout moved = layout;
    int desk = scene.findEntity("desk1");
    ASSERT_GE(desk, 0);
    moved.placements[size_t(desk)].position = Vec3(4.6, 3.3, 0);
    moved.placements[size_t(desk)].rotationDeg = 0;
    auto other = dir.path() / "moved.glb";
    writeGlb(other, scene, moved);
    auto [movedBounds, movedTriangles] = visibleGeometry(scene, moved);
    TriangleMesh backMoved = io::loadMeshFile(other, 0);
    EXPECT_EQ(backMoved.triangleCount(), movedTriangles);
    expectBounds(backMoved.bounds(), movedBounds);
    EXPECT_GT(movedBounds.hi.x, bounds.hi.x);  // the desk now sticks out of the room
}

TEST(GlbImport, PartsAsChildNodesComeBackPlaced) {
    // Two box parts of one entity, turned 90 deg and moved: each part is a child node of
    // the entity's node, and the import composes the two transforms.
    test::TempDir dir;
    const Scene scene = test::SceneBuilder()
                            .material("wall", test::diffuse(0.5))
                            .room({0, 0, 0}, {5, 4, 3}, "wall", "wall", "wall")
                            .entity("table", {2, 1, 0}, 90)
                            .part({1.2, 0.6, 0.04}, "wall", Vec3(0, 0, 0.73))
                            .part({0.05, 0.05, 0.71}, "wall", Vec3(0.5, 0.2, 0.355))
                            .end()
                            .build();
    const Layout layout = initialLayout(scene);
    const auto file = dir.path() / "scene.glb";
    writeGlb(file, scene, layout);
    auto [bounds, triangles] = visibleGeometry(scene, layout);
    TriangleMesh back = io::loadMeshFile(file, 0);
    EXPECT_EQ(back.triangleCount(), triangles - kEmitterTriangles);
    expectBounds(back.bounds(), bounds);
    // The table alone (every point but the room's corners): the placed parts' bounds.
    TriangleMesh placed;
    placed.append(scene.entities[0].mesh, worldTransforms(scene, layout)[0]);
    Bounds3 tableBack;
    for (const auto& p : back.positions)
        if (!((p.x < 1e-4 || p.x > 5 - 1e-4) && (p.y < 1e-4 || p.y > 4 - 1e-4))) tableBack.extend(p);
    expectBounds(tableBack, placed.bounds());
}

}  // namespace
}  // namespace luxplan
