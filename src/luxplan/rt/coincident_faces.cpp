#include <luxplan/rt/coincident_faces.h>

#include <array>
#include <cmath>
#include <map>

namespace luxplan {
namespace {

// A plane as integers: the unit normal turned so that its first clear component is
// positive, and the offset along it, each rounded (1e-4, 0.1 mm).
using PlaneKey = std::array<long long, 4>;

PlaneKey planeOf(const TriangleMesh& mesh, size_t t) {
    Vec3 n = mesh.geometricNormal(t);
    const double first = std::abs(n.x) > 1e-3 ? n.x : std::abs(n.y) > 1e-3 ? n.y : n.z;
    if (first < 0) n = -n;
    const double d = dot(n, mesh.positions[mesh.triangles[t][0]]);
    auto q = [](double v) { return (long long)std::llround(v * 1e4); };
    return {q(n.x), q(n.y), q(n.z), q(d)};
}

Bounds3 boxOf(const TriangleMesh& mesh, size_t t) {
    Bounds3 b;
    for (uint32_t v : mesh.triangles[t]) b.extend(mesh.positions[v]);
    return b;
}

// Whether two boxes of coplanar triangles share some area: they overlap by more than a
// sliver along at least two axes (along the third, a plane along an axis has none).
bool shareArea(const Bounds3& a, const Bounds3& b) {
    constexpr double kSliver = 1e-7;
    int wide = 0;
    for (int k = 0; k < 3; ++k) {
        const double overlap = std::min(a.hi[k], b.hi[k]) - std::max(a.lo[k], b.lo[k]);
        if (overlap < -kSliver) return false;
        wide += overlap > kSliver;
    }
    return wide >= 2;
}

}  // namespace

std::vector<char> coincidentFacesOfOtherMaterials(const TriangleMesh& mesh) {
    std::vector<char> flagged(mesh.triangles.size(), 0);
    std::map<PlaneKey, std::vector<size_t>> planes;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) planes[planeOf(mesh, t)].push_back(t);
    for (const auto& [key, members] : planes) {
        bool mixed = false;
        for (size_t t : members) mixed = mixed || mesh.materials[t] != mesh.materials[members.front()];
        if (!mixed) continue;
        std::vector<Bounds3> boxes;
        for (size_t t : members) boxes.push_back(boxOf(mesh, t));
        for (size_t i = 0; i < members.size(); ++i)
            for (size_t j = i + 1; j < members.size(); ++j)
                if (mesh.materials[members[i]] != mesh.materials[members[j]] && shareArea(boxes[i], boxes[j]))
                    flagged[members[i]] = flagged[members[j]] = 1;
    }
    return flagged;
}

}  // namespace luxplan
