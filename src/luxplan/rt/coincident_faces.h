// Faces of two materials that lie in one plane and overlap there: a ray that meets the
// plane hits one or the other as the order of the BVH decides, and a move anywhere
// rebuilds the BVH of the flat geometry. EmbreeScene breaks ties at such faces by a
// fixed order, so that a path traced after a move is the one the path cache kept
// (incremental/path_cache.h). A partition's glass running into its wooden base,
// flush at the ends, is one; a glass top resting on a leg is another, which only a ray
// inside the glass reaches (the path tracer asks for the fixed order there itself).
#pragma once

#include <vector>

#include <luxplan/scene/mesh.h>

namespace luxplan {

// Per triangle of `mesh`: whether a triangle of another material lies in its plane
// (within 0.1 mm and 1e-4 in the normal, either way round) and their boxes overlap in
// it with some area. Conservative: triangles whose boxes overlap but whose interiors do
// not are flagged too, which costs only the ties' second query.
std::vector<char> coincidentFacesOfOtherMaterials(const TriangleMesh& mesh);

}  // namespace luxplan
