// The closed opaque boxes of the current layout that hold no luminaire: no light
// reaches a point inside one, so a path from there is worth exactly 0 and is not
// traced (a desk's measurement point under a monitor's foot). Built from the boxes
// the meshes were made of (TriangleMesh::solidBoxes): a box is closed by
// construction, which a mesh file's triangles are not known to be.
#pragma once

#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/pathtracer/emitters.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

class SealedBoxes {
public:
    // A point must lie this far inside a box (m): a sensor's first ray starts 0.1 mm
    // along its direction (kRayEpsilon), and float error moves the box's faces far less.
    static constexpr double kInset = 1e-3;

    SealedBoxes() = default;
    // The boxes of static geometry and of every entity as `worldFromEntity` places it,
    // of a material nothing crosses (not glass, not translucent), each shrunk by
    // kInset, without those that any luminaire's sphere reaches into.
    SealedBoxes(const Scene& scene, const std::vector<Transform>& worldFromEntity, const EmitterSet& emitters);

    bool empty() const { return entities_.empty(); }
    // Whether p lies inside one of them; if so, `exit` is where the shortest way out
    // of that box (its unshrunk box) leaves it, on one of its faces.
    bool contain(const Vec3& p, Vec3& exit) const;
    // Whether p lies in one of them or within `tolerance` outside it (the box's own
    // faces, not the shrunk ones); if so, of the face nearest p (of the box p lies least
    // deep in), `outward` is its outward normal (world frame, unit) and `depth` how far p
    // lies inside it (negative outside). For the scene checks: a sampler just inside a
    // box, or on one looking into it, measures the dark inside.
    bool nearestFace(const Vec3& p, double tolerance, Vec3& outward, double& depth) const;

private:
    struct Placed {
        Transform localFromWorld;
        Bounds3 world;                // around all its boxes, world frame
        std::vector<Bounds3> inner;   // its boxes shrunk by kInset, local frame
        Transform worldFromLocal;
    };
    std::vector<Placed> entities_;    // the static geometry as one, with the identity
};

}  // namespace luxplan
