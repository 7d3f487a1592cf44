// rt/coincident_faces.h: which faces of a mesh lie in one plane with an overlapping
// face of another material (where EmbreeScene breaks ties by a fixed order).
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/rt/coincident_faces.h>

namespace luxplan {
namespace {

int flaggedOf(const TriangleMesh& mesh, const std::vector<char>& flags, uint32_t material) {
    int n = 0;
    for (size_t t = 0; t < flags.size(); ++t) n += flags[t] && mesh.materials[t] == material;
    return n;
}

TEST(CoincidentFacesOfOtherMaterials, AFlushCoreFlagsTheTopsItShares) {
    // A 0.6 m block (material 0) with a 0.3 m core (material 1) flush at the top and the
    // bottom: the core's top and bottom (two triangles each) and the block's top and
    // bottom (whose triangles' boxes overlap the core's) are flagged, no side.
    TriangleMesh mesh;
    addBox(mesh, Bounds3({-0.3, -0.3, 0}, {0.3, 0.3, 0.4}), 0);
    addBox(mesh, Bounds3({-0.15, -0.15, 0}, {0.15, 0.15, 0.4}), 1);
    const std::vector<char> flags = coincidentFacesOfOtherMaterials(mesh);
    ASSERT_EQ(flags.size(), mesh.triangles.size());
    EXPECT_EQ(flaggedOf(mesh, flags, 1), 4);
    EXPECT_EQ(flaggedOf(mesh, flags, 0), 4);
    for (size_t t = 0; t < flags.size(); ++t)
        if (flags[t]) {
            EXPECT_NEAR(std::abs(mesh.geometricNormal(t).z), 1.0, 1e-12);
        }
}

TEST(CoincidentFacesOfOtherMaterials, OnlyTwoMaterialsOverlappingInAPlaneAreFlagged) {
    // Of one material: the same surface either way (path_tracer.cpp's +0 handles it).
    TriangleMesh same;
    addBox(same, Bounds3({-0.3, -0.3, 0}, {0.3, 0.3, 0.4}), 0);
    addBox(same, Bounds3({-0.15, -0.15, 0}, {0.15, 0.15, 0.4}), 0);
    for (char f : coincidentFacesOfOtherMaterials(same)) EXPECT_FALSE(f);
    // Two materials side by side: their tops lie in one plane but meet only along an
    // edge (not flagged); the faces where they touch are one plane and are.
    TriangleMesh edge;
    addBox(edge, Bounds3({0, 0, 0}, {1, 1, 1}), 0);
    addBox(edge, Bounds3({1, 0, 0}, {2, 1, 1}), 1);
    const std::vector<char> touching = coincidentFacesOfOtherMaterials(edge);
    for (size_t t = 0; t < touching.size(); ++t) {
        const bool shared = std::abs(edge.geometricNormal(t).x) > 0.5 && edge.positions[edge.triangles[t][0]].x == 1;
        EXPECT_EQ(touching[t] != 0, shared) << "triangle " << t;
    }
    EXPECT_EQ(flaggedOf(edge, touching, 0) + flaggedOf(edge, touching, 1), 4);
    // A glass top 0.1 mm above its leg: two planes, no tie.
    TriangleMesh gap;
    addBox(gap, Bounds3({-0.5, -0.3, 0.7401}, {0.5, 0.3, 0.75}), 1);
    addBox(gap, Bounds3({-0.025, -0.025, 0}, {0.025, 0.025, 0.74}), 0);
    for (char f : coincidentFacesOfOtherMaterials(gap)) EXPECT_FALSE(f);
    // Resting on it: the leg's top and the slab's bottom triangles above it.
    TriangleMesh resting;
    addBox(resting, Bounds3({-0.5, -0.3, 0.74}, {0.5, 0.3, 0.75}), 1);
    addBox(resting, Bounds3({-0.025, -0.025, 0}, {0.025, 0.025, 0.74}), 0);
    const std::vector<char> flags = coincidentFacesOfOtherMaterials(resting);
    EXPECT_EQ(flaggedOf(resting, flags, 0), 2);
    EXPECT_EQ(flaggedOf(resting, flags, 1), 2);
}

}  // namespace
}  // namespace luxplan
