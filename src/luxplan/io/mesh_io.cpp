#include <luxplan/io/mesh_io.h>

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <luxplan/core/error.h>

namespace luxplan::io {
namespace {

TriangleMesh loadObj(const std::filesystem::path& file, uint32_t material) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = file.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        throw IoError(why.empty() ? "cannot parse OBJ" : why);
    }
    const auto& attrib = reader.GetAttrib();
    TriangleMesh mesh;
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
        mesh.positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
    for (const auto& shape : reader.GetShapes()) {
        size_t offset = 0;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            size_t n = shape.mesh.num_face_vertices[f];
            if (n == 3) {
                auto idx = [&](size_t k) { return shape.mesh.indices[offset + k].vertex_index; };
                if (idx(0) < 0 || idx(1) < 0 || idx(2) < 0) throw IoError("face with a negative vertex index");
                mesh.addTriangle(uint32_t(idx(0)), uint32_t(idx(1)), uint32_t(idx(2)), material);
            }
            offset += n;
        }
    }
    return mesh;
}

// A glTF node's local matrix (column-major 4x4 or TRS) as a Transform.
Transform nodeTransform(const tinygltf::Node& node) {
    Transform t;
    if (node.matrix.size() == 16) {
        const auto& m = node.matrix;  // column-major
        t.m = {m[0], m[4], m[8], m[1], m[5], m[9], m[2], m[6], m[10]};
        t.t = {m[12], m[13], m[14]};
        return t;
    }
    if (node.scale.size() == 3) t = Transform::scale(Vec3(node.scale[0], node.scale[1], node.scale[2]));
    if (node.rotation.size() == 4) {
        double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
        Transform r;
        r.m = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
               2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
               2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
        t = r * t;
    }
    if (node.translation.size() == 3) t.t = {node.translation[0], node.translation[1], node.translation[2]};
    return t;
}

// Reads accessor element `i` component `c` as a double, whatever its component type.
double accessorValue(const tinygltf::Model& model, const tinygltf::Accessor& acc, size_t i, int c) {
    const auto& view = model.bufferViews.at(acc.bufferView);
    const auto& buffer = model.buffers.at(view.buffer);
    int components = tinygltf::GetNumComponentsInType(acc.type);
    int size = tinygltf::GetComponentSizeInBytes(acc.componentType);
    size_t stride = view.byteStride ? view.byteStride : size_t(components * size);
    size_t at = view.byteOffset + acc.byteOffset + i * stride + size_t(c) * size;
    if (at + size > buffer.data.size()) throw IoError("accessor reads past the end of its buffer");
    const unsigned char* p = buffer.data.data() + at;
    switch (acc.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t u; std::memcpy(&u, p, 4); return u; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t u; std::memcpy(&u, p, 2); return u; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
        default: throw IoError("unsupported accessor component type " + std::to_string(acc.componentType));
    }
}

void addGltfNode(const tinygltf::Model& model, int nodeIndex, const Transform& parent, uint32_t material,
                 TriangleMesh& out, int depth) {
    if (depth > 64) throw IoError("node hierarchy deeper than 64 (a cycle?)");
    const auto& node = model.nodes.at(nodeIndex);
    Transform world = parent * nodeTransform(node);
    if (node.mesh >= 0) {
        for (const auto& prim : model.meshes.at(node.mesh).primitives) {
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;
            auto pos = prim.attributes.find("POSITION");
            if (pos == prim.attributes.end()) continue;
            const auto& pa = model.accessors.at(pos->second);
            TriangleMesh part;
            for (size_t i = 0; i < pa.count; ++i)
                part.positions.push_back(
                    {accessorValue(model, pa, i, 0), accessorValue(model, pa, i, 1), accessorValue(model, pa, i, 2)});
            if (prim.indices >= 0) {
                const auto& ia = model.accessors.at(prim.indices);
                for (size_t i = 0; i + 2 < ia.count; i += 3) {
                    uint32_t a = uint32_t(accessorValue(model, ia, i, 0)), b = uint32_t(accessorValue(model, ia, i + 1, 0)),
                             c = uint32_t(accessorValue(model, ia, i + 2, 0));
                    if (std::max({a, b, c}) >= pa.count) throw IoError("triangle index out of range");
                    part.addTriangle(a, b, c, material);
                }
            } else {
                for (uint32_t i = 0; i + 2 < pa.count; i += 3) part.addTriangle(i, i + 1, i + 2, material);
            }
            out.append(part, world);
        }
    }
    for (int child : node.children) addGltfNode(model, child, world, material, out, depth + 1);
}

TriangleMesh loadGltf(const std::filesystem::path& file, uint32_t material, bool binary) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                     : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        throw IoError(err.empty() ? "cannot parse glTF" : err);
    }
    // glTF is y-up; luxplan is z-up.
    Transform yUpToZUp;
    yUpToZUp.m = {1, 0, 0, 0, 0, -1, 0, 1, 0};
    TriangleMesh mesh;
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int s = model.defaultScene >= 0 ? model.defaultScene : 0;
        roots = model.scenes.at(s).nodes;
    } else {
        for (size_t i = 0; i < model.nodes.size(); ++i) roots.push_back(int(i));
    }
    for (int n : roots) addGltfNode(model, n, yUpToZUp, material, mesh, 0);
    return mesh;
}

}  // namespace

TriangleMesh loadMeshFile(const std::filesystem::path& file, uint32_t material) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw IoError("no such file");
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    TriangleMesh mesh;
    try {
        if (ext == ".obj") mesh = loadObj(file, material);
        else if (ext == ".gltf") mesh = loadGltf(file, material, false);
        else if (ext == ".glb") mesh = loadGltf(file, material, true);
        else throw IoError("unsupported mesh format \"" + ext + "\" (use .obj, .gltf or .glb)");
    } catch (const std::out_of_range&) {
        throw IoError("malformed glTF: an index refers to nothing");
    }
    if (mesh.empty()) throw IoError("holds no triangles");
    return mesh;
}

}  // namespace luxplan::io
