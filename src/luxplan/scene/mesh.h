// Indexed triangle meshes: the one geometric representation behind the room
// shell, boxes, imported models and furniture presets.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

// A closed axis-aligned box among a mesh's triangles (addBox), of one material: a
// point inside it sees only the box's inner faces.
struct SolidBox {
    Bounds3 box;
    uint32_t material = 0;
};

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
    std::vector<uint32_t> materials;                  // per triangle, index into Scene::materials
    std::vector<Vec3> normals;                        // optional per-vertex shading normals
    std::vector<SolidBox> solidBoxes;                 // the boxes addBox made, still closed and axis-aligned

    size_t triangleCount() const { return triangles.size(); }
    bool empty() const { return triangles.empty(); }
    void addTriangle(uint32_t a, uint32_t b, uint32_t c, uint32_t material) {
        triangles.push_back({a, b, c});
        materials.push_back(material);
    }
    // Appends `other` transformed by `t` (normals too, if both meshes carry them; its
    // solid boxes where `t` keeps boxes axis-aligned).
    void append(const TriangleMesh& other, const Transform& t = Transform());
    Bounds3 bounds() const;
    double area() const;
    // Area of the triangles with the given material.
    double area(uint32_t material) const;
    Vec3 geometricNormal(size_t tri) const;  // unit, from the winding order
};

// Builds primitives into `mesh` (appending); winding faces outwards.
void addBox(TriangleMesh& mesh, const Bounds3& box, uint32_t material);
// Axis-aligned quad: four corners counter-clockwise seen from the side the normal points to.
void addQuad(TriangleMesh& mesh, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, uint32_t material);

}  // namespace luxplan
