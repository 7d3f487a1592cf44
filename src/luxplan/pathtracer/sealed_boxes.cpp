#include <luxplan/pathtracer/sealed_boxes.h>

#include <algorithm>
#include <cmath>

namespace luxplan {
namespace {

// The distance from p to the box (0 inside).
double distanceTo(const Bounds3& b, const Vec3& p) {
    double d2 = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double below = b.lo[axis] - p[axis], above = p[axis] - b.hi[axis];
        const double out = std::max({below, above, 0.0});
        d2 += out * out;
    }
    return std::sqrt(d2);
}

}  // namespace

SealedBoxes::SealedBoxes(const Scene& scene, const std::vector<Transform>& worldFromEntity, const EmitterSet& emitters) {
    auto place = [&](const std::vector<SolidBox>& boxes, const Transform& worldFromLocal) {
        Placed placed;
        placed.localFromWorld = worldFromLocal.inverse();
        placed.worldFromLocal = worldFromLocal;
        for (const SolidBox& b : boxes) {
            if (!isOpaque(scene.materials[b.material])) continue;
            const Vec3 inset(kInset, kInset, kInset);
            const Bounds3 inner(b.box.lo + inset, b.box.hi - inset);
            if (!(inner.lo.x < inner.hi.x && inner.lo.y < inner.hi.y && inner.lo.z < inner.hi.z)) continue;
            // A luminaire whose sphere reaches into the box may light its inside. The
            // distance is taken in the local frame: the transforms are rigid.
            bool lit = false;
            for (size_t i = 0; i < emitters.size() && !lit; ++i)
                lit = distanceTo(b.box, placed.localFromWorld.applyPoint(emitters[i].center)) <= emitters[i].reach;
            if (lit) continue;
            placed.inner.push_back(inner);
            placed.world.extend(worldFromLocal.apply(inner));
        }
        if (!placed.inner.empty()) entities_.push_back(std::move(placed));
    };
    std::vector<SolidBox> statics;  // blockers take no part in light transport
    for (const StaticItem& item : scene.geometry)
        if (!item.invisible) statics.insert(statics.end(), item.mesh.solidBoxes.begin(), item.mesh.solidBoxes.end());
    place(statics, Transform());
    for (size_t i = 0; i < scene.entities.size() && i < worldFromEntity.size(); ++i)
        place(scene.entities[i].mesh.solidBoxes, worldFromEntity[i]);
}

bool SealedBoxes::contain(const Vec3& p, Vec3& exit) const {
    for (const Placed& e : entities_) {
        if (!e.world.contains(p)) continue;
        const Vec3 local = e.localFromWorld.applyPoint(p);
        for (const Bounds3& b : e.inner) {
            if (!b.contains(local)) continue;
            // The nearest face of the box (the inner one widened back by kInset).
            Vec3 out = local;
            double nearest = kInf;
            for (int axis = 0; axis < 3; ++axis)
                for (double face : {b.lo[axis] - kInset, b.hi[axis] + kInset})
                    if (std::abs(face - local[axis]) < nearest) {
                        nearest = std::abs(face - local[axis]);
                        out = local;
                        out[axis] = face;
                    }
            exit = e.worldFromLocal.applyPoint(out);
            return true;
        }
    }
    return false;
}

bool SealedBoxes::nearestFace(const Vec3& p, double tolerance, Vec3& outward, double& depth) const {
    const double reach = kInset + tolerance;
    bool found = false;
    for (const Placed& e : entities_) {
        if (!Bounds3(e.world.lo - Vec3(reach, reach, reach), e.world.hi + Vec3(reach, reach, reach)).contains(p)) continue;
        const Vec3 local = e.localFromWorld.applyPoint(p);
        for (const Bounds3& inner : e.inner) {
            const Bounds3 b(inner.lo - Vec3(kInset, kInset, kInset), inner.hi + Vec3(kInset, kInset, kInset));
            // How far p lies inside each face (negative outside); within the tolerance
            // of the box on every axis, the face p lies least far inside is its nearest.
            double least = kInf;
            int nearest = -1;
            for (int face = 0; face < 6; ++face) {
                const int axis = face / 2;
                const double inside = face % 2 ? b.hi[axis] - local[axis] : local[axis] - b.lo[axis];
                if (inside < -tolerance) {
                    nearest = -1;
                    break;
                }
                if (inside < least) least = inside, nearest = face;
            }
            if (nearest < 0 || (found && least >= depth)) continue;
            Vec3 n;
            n[nearest / 2] = nearest % 2 ? 1 : -1;
            outward = normalize(e.worldFromLocal.applyVector(n));
            depth = least;
            found = true;
        }
    }
    return found;
}

}  // namespace luxplan
