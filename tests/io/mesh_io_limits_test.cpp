// Meshes that once crashed, hung or were wrongly accepted (issue 15): each is refused
// with FILE:LINE (OBJ) or FILE: /json/path (glTF), never read past its arrays, and no
// FIFO or device is ever opened.
#include <gtest/gtest.h>

#include <cstring>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include <luxplan/core/error.h>
#include <luxplan/core/limits.h>
#include <luxplan/io/mesh_io.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

// The error text of loading `file`, or "" (and a failure) if it loads.
std::string meshError(const std::filesystem::path& file) {
    try {
        io::loadMeshFile(file, 0);
    } catch (const IoError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error for " << file;
    return "";
}

TEST(MeshIoLimits, ObjFaceIndexOutOfRangeNamesTheLine) {
    test::TempDir dir;
    auto obj = dir.write("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 100000000\n");
    EXPECT_EQ(meshError(obj), obj.string() + ":4: face vertex index 100000000 is out of range: the file has 3 vertices "
                                             "(indices 1 to 3, or -1 for the last)");
    obj = dir.write("ninetynine.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n# a comment\nf 1 2 99\n");
    EXPECT_EQ(meshError(obj).rfind(obj.string() + ":5: face vertex index 99 is out of range", 0), 0u);
    obj = dir.write("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
    EXPECT_EQ(meshError(obj).rfind(obj.string() + ":4: face vertex index -4 is out of range", 0), 0u);
    obj = dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    EXPECT_EQ(meshError(obj).rfind(obj.string() + ":4: face vertex index 0 is out of range", 0), 0u);
    obj = dir.write("word.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n");
    EXPECT_EQ(meshError(obj), obj.string() + ":4: face vertex \"x/1\" is not an index");
}

TEST(MeshIoLimits, ObjOfFacesOnly) {
    test::TempDir dir;
    auto obj = dir.write("faces.obj", "f 1 2 3\nf 1 2 3\n");  // 16 bytes
    EXPECT_EQ(meshError(obj).rfind(obj.string() + ":1: face vertex index 1 is out of range: the file has 0 vertices", 0), 0u);
}

TEST(MeshIoLimits, ObjNonFiniteVertex) {
    test::TempDir dir;
    for (const char* bad : {"nan", "inf", "-inf", "1e400"}) {
        auto obj = dir.write("bad.obj", std::string("v 0 0 0\nv 1 ") + bad + " 0\nv 0 1 0\nf 1 2 3\n");
        EXPECT_EQ(meshError(obj), obj.string() + ":2: vertex coordinate \"" + bad + "\" is not a finite number");
    }
}

TEST(MeshIoLimits, ObjValidIndicesStillLoad) {
    test::TempDir dir;
    auto obj = dir.write("ok.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nf 1/1/1 2//2 3\n");
    EXPECT_EQ(io::loadMeshFile(obj, 0).triangleCount(), 3u);
}

TEST(MeshIoLimits, FifoAndDevicesAreNeverOpened) {
    test::TempDir dir;
    auto fifo = dir.path() / "pipe.obj";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(meshError(fifo), "not a regular file (a folder, FIFO or device cannot be read)");
    // A material library that is a FIFO (it would block for ever) or a device.
    ASSERT_EQ(mkfifo((dir.path() / "pipe.mtl").c_str(), 0600), 0);
    auto obj = dir.write("m.obj", "mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(meshError(obj), obj.string() + ":1: mtllib \"pipe.mtl\" is not a regular file");
    obj = dir.write("z.obj", "mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(meshError(obj), obj.string() + ":1: mtllib \"/dev/zero\" is not a regular file");
    // A missing library is no error: materials come from the scene.
    obj = dir.write("n.obj", "mtllib none.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(io::loadMeshFile(obj, 0).triangleCount(), 1u);
}

// ---- glTF ----

std::string base64(const std::vector<unsigned char>& d) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < d.size(); i += 3) {
        uint32_t n = uint32_t(d[i]) << 16 | (i + 1 < d.size() ? uint32_t(d[i + 1]) << 8 : 0) | (i + 2 < d.size() ? d[i + 2] : 0);
        out += k[n >> 18 & 63];
        out += k[n >> 12 & 63];
        out += i + 1 < d.size() ? k[n >> 6 & 63] : '=';
        out += i + 2 < d.size() ? k[n & 63] : '=';
    }
    return out;
}

// One triangle: three float VEC3 positions (36 bytes) then three uint16 indices.
json triangleGltf(std::vector<uint16_t> indices = {0, 1, 2}) {
    std::vector<float> p = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<unsigned char> bytes(36 + 2 * indices.size());
    std::memcpy(bytes.data(), p.data(), 36);
    std::memcpy(bytes.data() + 36, indices.data(), 2 * indices.size());
    json g = json::parse(R"({
      "asset": {"version": "2.0"},
      "buffers": [{"byteLength": 0, "uri": ""}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 0}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5123, "count": 0, "type": "SCALAR"}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "nodes": [{"mesh": 0}],
      "scenes": [{"nodes": [0]}],
      "scene": 0
    })");
    g["buffers"][0]["byteLength"] = bytes.size();
    g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bytes);
    g["bufferViews"][1]["byteLength"] = 2 * indices.size();
    g["accessors"][1]["count"] = indices.size();
    return g;
}

TEST(MeshIoLimits, GltfTriangleLoads) {
    test::TempDir dir;
    EXPECT_EQ(io::loadMeshFile(dir.write("t.gltf", triangleGltf().dump()), 0).triangleCount(), 1u);
}

TEST(MeshIoLimits, GltfScalarPositionAccessor) {
    test::TempDir dir;
    json g = triangleGltf();
    g["accessors"][0]["type"] = "SCALAR";
    auto file = dir.write("scalar.gltf", g.dump());
    EXPECT_EQ(meshError(file), file.string() + ": /accessors/0: the POSITION accessor of /meshes/0/primitives/0 has type "
                                               "SCALAR (expected VEC3)");
}

TEST(MeshIoLimits, GltfBufferViewPastItsBuffer) {
    test::TempDir dir;
    json g = triangleGltf();
    g["bufferViews"][0]["byteLength"] = 4000;
    auto file = dir.write("view.gltf", g.dump());
    std::string e = meshError(file);
    // tinygltf may catch it first; either way the file is refused and named.
    EXPECT_EQ(e.rfind(file.string() + ":", 0), 0u) << e;
    g = triangleGltf();
    g["accessors"][0]["count"] = 300;  // 300 vertices from a 36-byte view
    file = dir.write("accessor.gltf", g.dump());
    e = meshError(file);
    EXPECT_EQ(e.rfind(file.string() + ":", 0), 0u) << e;
    EXPECT_NE(e.find("past the end"), std::string::npos) << e;
}

TEST(MeshIoLimits, GltfIndexOutOfRange) {
    test::TempDir dir;
    auto file = dir.write("index.gltf", triangleGltf({0, 1, 99}).dump());
    EXPECT_EQ(meshError(file), file.string() + ": /accessors/1: index 99 (element 2) is out of range: POSITION /accessors/0 "
                                               "has 3 vertices");
}

TEST(MeshIoLimits, GltfNodesThatShareChildren) {
    // Two nodes per level, each the parent of both nodes of the next level: 2^40
    // instances of the last level's mesh from an 80-node file.
    test::TempDir dir;
    json g = triangleGltf();
    const int levels = 40;
    g["nodes"] = json::array();
    for (int l = 0; l < levels; ++l)
        for (int k = 0; k < 2; ++k) {
            json node = json::object();
            if (l + 1 < levels) node["children"] = {2 * (l + 1), 2 * (l + 1) + 1};
            else node["mesh"] = 0;
            g["nodes"].push_back(node);
        }
    g["scenes"] = {{{"nodes", {0}}}};
    auto file = dir.write("dag.gltf", g.dump());
    std::string e = meshError(file);
    EXPECT_NE(e.find("node instances"), std::string::npos) << e;
    EXPECT_NE(e.find("exceed the limit of " + std::to_string(limits::kMaxGltfNodeInstances)), std::string::npos) << e;
    EXPECT_EQ(e.rfind(file.string() + ": /nodes/", 0), 0u) << e;
}

TEST(MeshIoLimits, GltfBufferUriThatIsAFifoOrDevice) {
    test::TempDir dir;
    ASSERT_EQ(mkfifo((dir.path() / "pipe.bin").c_str(), 0600), 0);
    for (const char* uri : {"pipe.bin", "/dev/zero"}) {
        json g = triangleGltf();
        g["buffers"][0]["uri"] = uri;
        auto file = dir.write("b.gltf", g.dump());
        std::string e = meshError(file);
        EXPECT_EQ(e.rfind(file.string() + ": ", 0), 0u) << e;
        // An absolute uri is not found under the glTF's folder; a FIFO there is refused.
        if (std::string(uri) == "pipe.bin") {
            EXPECT_NE(e.find("not a regular file"), std::string::npos) << e;
        }
    }
}

}  // namespace
}  // namespace luxplan
