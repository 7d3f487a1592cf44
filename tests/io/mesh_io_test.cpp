// OBJ and glTF import: geometry, orientation (glTF y-up to z-up) and errors.
#include <gtest/gtest.h>

#include <luxplan/core/error.h>
#include <luxplan/io/mesh_io.h>
#include <luxplan/scene/voxels.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

const std::filesystem::path kData = LUXPLAN_TEST_DATA;

TEST(MeshIo, ObjCube) {
    TriangleMesh m = io::loadMeshFile(kData / "cube.obj", 5);
    EXPECT_EQ(m.triangleCount(), 12u);
    EXPECT_NEAR(m.area(), 6.0, 1e-9);
    EXPECT_EQ(m.materials.front(), 5u);
    EXPECT_NEAR(voxelizeSolid(m, 0.05).volume(), 1.0, 0.02);  // outward winding: a solid
}

TEST(MeshIo, GltfCubeIsTurnedZUp) {
    TriangleMesh m = io::loadMeshFile(kData / "cube.gltf", 0);
    EXPECT_EQ(m.triangleCount(), 12u);
    Bounds3 b = m.bounds();
    // The node moves the cube +1 along glTF's y (up), which is luxplan's z.
    EXPECT_NEAR(b.lo.z, 0.0, 1e-6);
    EXPECT_NEAR(b.hi.z, 2.0, 1e-6);
    EXPECT_NEAR(b.center().y, 0.0, 1e-6);
    EXPECT_NEAR(voxelizeSolid(m, 0.05).volume(), 8.0, 0.16);
}

TEST(MeshIo, Errors) {
    test::TempDir dir;
    auto expectError = [](const std::filesystem::path& p, const std::string& fragment) {
        try {
            io::loadMeshFile(p, 0);
            ADD_FAILURE() << "no error for " << p;
        } catch (const IoError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    expectError(dir.path() / "missing.obj", "no such file");
    expectError(dir.write("model.stl", "solid x"), "unsupported mesh format \".stl\"");
    expectError(dir.write("empty.obj", "# nothing\n"), "holds no triangles");
    expectError(dir.write("broken.gltf", "{ not json"), "");
}

}  // namespace
}  // namespace luxplan
