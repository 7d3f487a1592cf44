#include <luxplan/scene/mesh.h>

#include <cmath>

namespace luxplan {

void TriangleMesh::append(const TriangleMesh& other, const Transform& t) {
    auto base = uint32_t(positions.size());
    bool withNormals = normals.size() == positions.size() && other.normals.size() == other.positions.size();
    for (const Vec3& p : other.positions) positions.push_back(t.applyPoint(p));
    if (withNormals)
        for (const Vec3& n : other.normals) normals.push_back(t.applyNormal(n));
    else
        normals.clear();
    // A mirroring transform flips the winding; restore outward-facing order.
    bool flip = t.determinant() < 0;
    for (size_t i = 0; i < other.triangles.size(); ++i) {
        auto tri = other.triangles[i];
        if (flip) std::swap(tri[1], tri[2]);
        addTriangle(base + tri[0], base + tri[1], base + tri[2], other.materials[i]);
    }
    // A box stays a box under a map that sends each axis to an axis (a rotation by a
    // quarter turn, whose cosine is 6e-17 in double, a scale, a mirror); under any
    // other it is no longer axis-aligned.
    bool axisAligned = true;
    for (int row = 0; row < 3; ++row) {
        int nonzero = 0;
        for (int col = 0; col < 3; ++col) nonzero += std::abs(t.m[size_t(3 * row + col)]) > 1e-12;
        axisAligned = axisAligned && nonzero == 1;
    }
    if (!axisAligned) return;
    for (const SolidBox& b : other.solidBoxes) {
        Bounds3 placed;
        placed.extend(t.applyPoint(b.box.lo));
        placed.extend(t.applyPoint(b.box.hi));
        solidBoxes.push_back({placed, b.material});
    }
}

Bounds3 TriangleMesh::bounds() const {
    Bounds3 b;
    for (const auto& tri : triangles)
        for (uint32_t v : tri) b.extend(positions[v]);
    return b;
}

double TriangleMesh::area() const {
    double a = 0;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const auto& t = triangles[i];
        a += 0.5 * length(cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]));
    }
    return a;
}

double TriangleMesh::area(uint32_t material) const {
    double a = 0;
    for (size_t i = 0; i < triangles.size(); ++i) {
        if (materials[i] != material) continue;
        const auto& t = triangles[i];
        a += 0.5 * length(cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]));
    }
    return a;
}

Vec3 TriangleMesh::geometricNormal(size_t tri) const {
    const auto& t = triangles[tri];
    return normalize(cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]));
}

void addQuad(TriangleMesh& mesh, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, uint32_t material) {
    auto base = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
    mesh.normals.clear();
    mesh.addTriangle(base, base + 1, base + 2, material);
    mesh.addTriangle(base, base + 2, base + 3, material);
}

void addBox(TriangleMesh& mesh, const Bounds3& box, uint32_t material) {
    const Vec3 &l = box.lo, &h = box.hi;
    addQuad(mesh, {l.x, l.y, l.z}, {l.x, h.y, l.z}, {h.x, h.y, l.z}, {h.x, l.y, l.z}, material);  // bottom (-z)
    addQuad(mesh, {l.x, l.y, h.z}, {h.x, l.y, h.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z}, material);  // top (+z)
    addQuad(mesh, {l.x, l.y, l.z}, {h.x, l.y, l.z}, {h.x, l.y, h.z}, {l.x, l.y, h.z}, material);  // -y
    addQuad(mesh, {l.x, h.y, l.z}, {l.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, l.z}, material);  // +y
    addQuad(mesh, {l.x, l.y, l.z}, {l.x, l.y, h.z}, {l.x, h.y, h.z}, {l.x, h.y, l.z}, material);  // -x
    addQuad(mesh, {h.x, l.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z}, {h.x, l.y, h.z}, material);  // +x
    mesh.solidBoxes.push_back({box, material});
}

}  // namespace luxplan
