// Reads triangle meshes from OBJ (tinyobjloader) and glTF 2.0 (.gltf/.glb, tinygltf).
#pragma once

#include <filesystem>

#include <luxplan/scene/mesh.h>

namespace luxplan::io {

// Loads every triangle of the file, all with `material`, in metres and luxplan's
// z-up frame. OBJ coordinates are taken as they are (z up); glTF is y-up by its
// specification and is turned to z up ((x, y, z) -> (x, -z, y)), node transforms
// applied. Throws IoError with the reason when the file cannot be read or holds
// no triangles.
TriangleMesh loadMeshFile(const std::filesystem::path& file, uint32_t material);

}  // namespace luxplan::io
