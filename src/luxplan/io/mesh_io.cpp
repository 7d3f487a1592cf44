#include <luxplan/io/mesh_io.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <luxplan/core/error.h>
#include <luxplan/core/limits.h>

namespace luxplan::io {
namespace {

namespace fs = std::filesystem;

// Why `file` may not be read, or "": it must be a regular file (never a FIFO, which
// would block, or a device such as /dev/zero, which never ends) within the size limit.
std::string unreadable(const fs::path& file, std::uintmax_t maxBytes) {
    std::error_code ec;
    auto status = fs::status(file, ec);
    if (ec || !fs::exists(status)) return "no such file";
    if (!fs::is_regular_file(status)) return "not a regular file (a folder, FIFO or device cannot be read)";
    auto size = fs::file_size(file, ec);
    if (ec) return "cannot read its size";
    if (size > maxBytes)
        return "file of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(maxBytes) + " bytes";
    return "";
}

std::string readWhole(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw FileError(file.string(), "", "cannot open the file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// ---- OBJ ----

std::string_view trimLeft(std::string_view s) {
    size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    return s.substr(i);
}

// Splits on blanks.
std::vector<std::string_view> tokens(std::string_view s) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
        size_t j = i;
        while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
        if (j > i) out.push_back(s.substr(i, j - i));
        i = j;
    }
    return out;
}

// Calls fn(line number, line without its end) for each line of `text`.
template <class Fn>
void forEachLine(const std::string& text, Fn fn) {
    size_t start = 0;
    int line = 1;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view l(text.data() + start, end - start);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        fn(line, trimLeft(l));
        start = end + 1;
        ++line;
    }
}

// What tinyobjloader does not check, with FILE:LINE: every face's vertex index refers
// to a vertex of the file, every vertex is finite, every mtllib names a regular file
// (it is never read: materials come from the scene), and the triangle count is within
// limits::kMaxMeshTriangles, all before tinyobjloader builds anything.
void checkObj(const std::string& text, const fs::path& file) {
    const std::string name = file.string();
    int64_t total = 0;
    forEachLine(text, [&](int, std::string_view l) {
        if (l.size() > 1 && l[0] == 'v' && (l[1] == ' ' || l[1] == '\t')) ++total;
    });
    int64_t seen = 0;
    uint64_t triangles = 0;
    forEachLine(text, [&](int line, std::string_view l) {
        if (l.size() < 2 || (l[1] != ' ' && l[1] != '\t')) {
            if (l.rfind("mtllib", 0) != 0) return;
        }
        auto tok = tokens(l);
        if (tok.empty()) return;
        const std::string where = std::to_string(line);
        if (tok[0] == "v") {
            ++seen;
            for (size_t k = 1; k < tok.size() && k <= 3; ++k) {
                std::string t(tok[k]);
                double v = std::strtod(t.c_str(), nullptr);
                if (!std::isfinite(v)) throw FileError(name, where, "vertex coordinate \"" + t + "\" is not a finite number");
            }
        } else if (tok[0] == "f") {
            for (size_t k = 1; k < tok.size(); ++k) {
                std::string t(tok[k].substr(0, tok[k].find('/')));
                char* end = nullptr;
                errno = 0;
                long long idx = std::strtoll(t.c_str(), &end, 10);
                if (t.empty() || *end != '\0') throw FileError(name, where, "face vertex \"" + std::string(tok[k]) + "\" is not an index");
                // Negative indices count back from the last vertex read so far.
                long long resolved = idx < 0 && errno == 0 ? seen + idx + 1 : idx;
                if (errno != 0 || idx == 0 || resolved < 1 || resolved > total)
                    throw FileError(name, where, "face vertex index " + t + " is out of range: the file has " +
                                                     std::to_string(total) + " vertices (indices 1 to " +
                                                     std::to_string(total) + ", or -1 for the last)");
            }
            if (tok.size() >= 4) triangles += tok.size() - 3;
        } else if (tok[0] == "mtllib") {
            for (size_t k = 1; k < tok.size(); ++k) {
                fs::path mtl = file.parent_path() / std::string(tok[k]);
                std::error_code ec;
                if (fs::exists(mtl, ec) && !fs::is_regular_file(mtl, ec))
                    throw FileError(name, where, "mtllib \"" + std::string(tok[k]) + "\" is not a regular file");
            }
        }
    });
    if (triangles > limits::kMaxMeshTriangles)
        throw FileError(name, "", std::to_string(triangles) + " triangles exceed the limit of " +
                                      std::to_string(limits::kMaxMeshTriangles));
}

TriangleMesh loadObj(const fs::path& file, uint32_t material) {
    const std::string text = readWhole(file);
    checkObj(text, file);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // From memory, with no material library: tinyobjloader opens no other file.
    if (!reader.ParseFromString(text, "", config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        throw FileError(file.string(), "", why.empty() ? "cannot parse OBJ" : why);
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
                for (size_t k = 0; k < 3; ++k)
                    if (idx(k) < 0 || size_t(idx(k)) >= mesh.positions.size())
                        throw FileError(file.string(), "", "a face's vertex index is out of range");
                mesh.addTriangle(uint32_t(idx(0)), uint32_t(idx(1)), uint32_t(idx(2)), material);
            }
            offset += n;
        }
    }
    return mesh;
}

// ---- glTF ----

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

// One glTF file being read: every problem names the file and the JSON path of what
// is wrong (/accessors/3, /nodes/2).
class GltfReader {
public:
    GltfReader(const tinygltf::Model& model, std::string file, uint32_t material)
        : model_(model), file_(std::move(file)), material_(material) {}

    TriangleMesh read() {
        // glTF is y-up; luxplan is z-up.
        Transform yUpToZUp;
        yUpToZUp.m = {1, 0, 0, 0, 0, -1, 0, 1, 0};
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            int s = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (size_t(s) >= model_.scenes.size()) fail("/scene", "scene " + std::to_string(s) + " does not exist");
            roots = model_.scenes[size_t(s)].nodes;
        } else {
            for (size_t i = 0; i < model_.nodes.size(); ++i) roots.push_back(int(i));
        }
        for (int n : roots) addNode(n, yUpToZUp, 0, "/scenes");
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& message) const {
        throw FileError(file_, where, message);
    }

    // The accessor's bytes lie inside its bufferView, and that inside its buffer.
    // Returns the element stride.
    size_t checkAccessor(int index, const std::string& path) const {
        const auto& acc = model_.accessors[size_t(index)];
        if (acc.sparse.isSparse) fail(path, "sparse accessors are not supported");
        if (acc.bufferView < 0 || size_t(acc.bufferView) >= model_.bufferViews.size())
            fail(path, "bufferView " + std::to_string(acc.bufferView) + " does not exist");
        const std::string viewPath = "/bufferViews/" + std::to_string(acc.bufferView);
        const auto& view = model_.bufferViews[size_t(acc.bufferView)];
        if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
            fail(viewPath, "buffer " + std::to_string(view.buffer) + " does not exist");
        const size_t bufferBytes = model_.buffers[size_t(view.buffer)].data.size();
        if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset)
            fail(viewPath, "bytes [" + std::to_string(view.byteOffset) + ", " +
                               std::to_string(uint64_t(view.byteOffset) + view.byteLength) + ") lie past the end of buffer " +
                               std::to_string(view.buffer) + " (" + std::to_string(bufferBytes) + " bytes)");
        int components = tinygltf::GetNumComponentsInType(acc.type);
        int size = tinygltf::GetComponentSizeInBytes(acc.componentType);
        if (components <= 0 || size <= 0) fail(path, "unknown accessor type or component type");
        const size_t element = size_t(components) * size_t(size);
        const size_t stride = view.byteStride ? view.byteStride : element;
        if (acc.count == 0) return stride;
        // Overflow-safe: count <= byteLength before multiplying.
        if (acc.byteOffset > view.byteLength || acc.count > view.byteLength ||
            (acc.count - 1) * stride + element > view.byteLength - acc.byteOffset)
            fail(path, std::to_string(acc.count) + " elements of " + std::to_string(element) + " bytes from offset " +
                           std::to_string(acc.byteOffset) + " lie past the end of bufferView " +
                           std::to_string(acc.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
        return stride;
    }

    double value(const tinygltf::Accessor& acc, size_t stride, size_t i, int c) const {
        const auto& view = model_.bufferViews[size_t(acc.bufferView)];
        const auto& buffer = model_.buffers[size_t(view.buffer)];
        const int size = tinygltf::GetComponentSizeInBytes(acc.componentType);
        const unsigned char* p = buffer.data.data() + view.byteOffset + acc.byteOffset + i * stride + size_t(c) * size;
        switch (acc.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t u; std::memcpy(&u, p, 4); return u; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t u; std::memcpy(&u, p, 2); return u; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
            default: return 0;  // refused by the callers' checks
        }
    }

    int checkedIndex(int index, size_t count, const std::string& path, const char* what) const {
        if (index < 0 || size_t(index) >= count) fail(path, std::string(what) + " " + std::to_string(index) + " does not exist");
        return index;
    }

    void addPrimitive(const tinygltf::Primitive& prim, const std::string& primPath, const Transform& world) {
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) return;
        auto pos = prim.attributes.find("POSITION");
        if (pos == prim.attributes.end()) return;
        const int pi = checkedIndex(pos->second, model_.accessors.size(), primPath + "/attributes/POSITION", "accessor");
        const std::string posPath = "/accessors/" + std::to_string(pi);
        const auto& pa = model_.accessors[size_t(pi)];
        if (pa.type != TINYGLTF_TYPE_VEC3)
            fail(posPath, "the POSITION accessor of " + primPath + " has type " + typeName(pa.type) + " (expected VEC3)");
        if (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(posPath, "the POSITION accessor of " + primPath + " has component type " +
                              std::to_string(pa.componentType) + " (expected 5126, float)");
        const size_t posStride = checkAccessor(pi, posPath);
        TriangleMesh part;
        part.positions.reserve(pa.count);
        for (size_t i = 0; i < pa.count; ++i) {
            Vec3 p(value(pa, posStride, i, 0), value(pa, posStride, i, 1), value(pa, posStride, i, 2));
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                fail(posPath, "vertex " + std::to_string(i) + " is not a finite number");
            part.positions.push_back(p);
        }
        size_t triangles = 0;
        if (prim.indices >= 0) {
            const int ii = checkedIndex(prim.indices, model_.accessors.size(), primPath + "/indices", "accessor");
            const std::string indPath = "/accessors/" + std::to_string(ii);
            const auto& ia = model_.accessors[size_t(ii)];
            if (ia.type != TINYGLTF_TYPE_SCALAR) fail(indPath, "indices of type " + typeName(ia.type) + " (expected SCALAR)");
            if (ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT &&
                ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
                fail(indPath, "indices of component type " + std::to_string(ia.componentType) +
                                  " (expected an unsigned byte, short or int)");
            const size_t stride = checkAccessor(ii, indPath);
            triangles = ia.count / 3;
            checkTriangles(triangles);
            for (size_t i = 0; i + 2 < ia.count; i += 3) {
                uint32_t v[3];
                for (size_t k = 0; k < 3; ++k) {
                    double d = value(ia, stride, i + k, 0);
                    if (d >= double(pa.count))
                        fail(indPath, "index " + std::to_string(uint64_t(d)) + " (element " + std::to_string(i + k) +
                                          ") is out of range: POSITION " + posPath + " has " + std::to_string(pa.count) +
                                          " vertices");
                    v[k] = uint32_t(d);
                }
                part.addTriangle(v[0], v[1], v[2], material_);
            }
        } else {
            triangles = pa.count / 3;
            checkTriangles(triangles);
            for (uint32_t i = 0; i + 2 < pa.count; i += 3) part.addTriangle(i, i + 1, i + 2, material_);
        }
        mesh_.append(part, world);
    }

    void checkTriangles(size_t more) const {
        if (mesh_.triangleCount() + more > limits::kMaxMeshTriangles)
            fail("", std::to_string(mesh_.triangleCount() + more) + " triangles exceed the limit of " +
                         std::to_string(limits::kMaxMeshTriangles));
    }

    void addNode(int nodeIndex, const Transform& parent, int depth, const std::string& from) {
        const int n = checkedIndex(nodeIndex, model_.nodes.size(), from, "node");
        const std::string path = "/nodes/" + std::to_string(n);
        if (depth > limits::kMaxGltfNodeDepth)
            fail(path, "node hierarchy deeper than " + std::to_string(limits::kMaxGltfNodeDepth) + " (a cycle?)");
        // Nodes that share children are instanced once per path to them: bounded, as
        // such a graph may double its size at each level.
        if (++instances_ > limits::kMaxGltfNodeInstances)
            fail(path, "more than " + std::to_string(limits::kMaxGltfNodeInstances) +
                           " node instances (nodes shared by several parents count once per path) exceed the limit of " +
                           std::to_string(limits::kMaxGltfNodeInstances));
        const auto& node = model_.nodes[size_t(n)];
        Transform world = parent * nodeTransform(node);
        if (node.mesh >= 0) {
            const int m = checkedIndex(node.mesh, model_.meshes.size(), path + "/mesh", "mesh");
            const auto& prims = model_.meshes[size_t(m)].primitives;
            for (size_t k = 0; k < prims.size(); ++k)
                addPrimitive(prims[k], "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(k), world);
        }
        for (int child : node.children) addNode(child, world, depth + 1, path + "/children");
    }

    static std::string typeName(int type) {
        switch (type) {
            case TINYGLTF_TYPE_SCALAR: return "SCALAR";
            case TINYGLTF_TYPE_VEC2: return "VEC2";
            case TINYGLTF_TYPE_VEC3: return "VEC3";
            case TINYGLTF_TYPE_VEC4: return "VEC4";
            case TINYGLTF_TYPE_MAT2: return "MAT2";
            case TINYGLTF_TYPE_MAT3: return "MAT3";
            case TINYGLTF_TYPE_MAT4: return "MAT4";
            default: return std::to_string(type);
        }
    }

    const tinygltf::Model& model_;
    std::string file_;
    uint32_t material_;
    TriangleMesh mesh_;
    uint64_t instances_ = 0;
};

// File access for tinygltf: only regular files within the size limit (its defaults
// open a FIFO and block, read /dev/zero until memory runs out, and expand paths
// with wordexp).
bool gltfFileExists(const std::string& path, void*) {
    std::error_code ec;
    return fs::exists(path, ec);
}
std::string gltfExpandPath(const std::string& path, void*) { return path; }
bool gltfReadFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    std::string why = unreadable(path, limits::kMaxMeshFileBytes);
    if (!why.empty()) {
        if (err) *err += path + ": " + why + "\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (err) *err += path + ": cannot open the file\n";
        return false;
    }
    out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}
// Images are not used (materials come from the scene): never decoded.
bool gltfSkipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

TriangleMesh loadGltf(const fs::path& file, uint32_t material, bool binary) {
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({gltfFileExists, gltfExpandPath, gltfReadFile, tinygltf::WriteWholeFile, nullptr});
    loader.SetImageLoader(gltfSkipImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                     : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        std::replace(err.begin(), err.end(), '\n', ' ');
        throw FileError(file.string(), "", err.empty() ? "cannot parse glTF" : err);
    }
    return GltfReader(model, file.string(), material).read();
}

}  // namespace

TriangleMesh loadMeshFile(const fs::path& file, uint32_t material) {
    std::string why = unreadable(file, limits::kMaxMeshFileBytes);
    if (!why.empty()) throw IoError(why);
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    TriangleMesh mesh;
    try {
        if (ext == ".obj") mesh = loadObj(file, material);
        else if (ext == ".gltf") mesh = loadGltf(file, material, false);
        else if (ext == ".glb") mesh = loadGltf(file, material, true);
        else throw IoError("unsupported mesh format \"" + ext + "\" (use .obj, .gltf or .glb)");
    } catch (const std::out_of_range&) {
        throw FileError(file.string(), "", "malformed glTF: an index refers to nothing");
    }
    if (mesh.empty()) throw IoError("holds no triangles");
    return mesh;
}

}  // namespace luxplan::io
