// Sphere emitter: a two-sided bulb that emits all round, sampled uniformly in the
// cone it subtends from the shading point.
#include <array>
#include <map>

#include <luxplan/core/warp.h>
#include <luxplan/emitters/emitter_shape.h>

namespace luxplan {
namespace {

constexpr int kMeshSubdivisions = 2;  // of the glTF icosphere: 320 triangles

// The unit icosahedron with every triangle split in four, `levels` times, wound
// counter-clockwise seen from outside.
TriangleMesh unitIcosphere(int levels) {
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                           {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (Vec3& v : p) v = normalize(v);
    std::vector<std::array<uint32_t, 3>> faces = {
        {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto [it, added] = midpoints.try_emplace({key.first, key.second}, uint32_t(p.size()));
            if (added) p.push_back(normalize(p[a] + p[b]));
            return it->second;
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& f : faces) {
            uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            next.push_back({f[0], ab, ca});
            next.push_back({f[1], bc, ab});
            next.push_back({f[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        faces = std::move(next);
    }
    TriangleMesh mesh;
    mesh.positions = p;
    mesh.normals = p;
    for (auto f : faces) {
        // Outward winding: the face normal along its centroid.
        Vec3 a = p[f[0]], b = p[f[1]], c = p[f[2]];
        if (dot(cross(b - a, c - a), a + b + c) < 0) std::swap(f[1], f[2]);
        mesh.addTriangle(f[0], f[1], f[2], 0);
    }
    return mesh;
}

class Sphere final : public EmitterShape {
public:
    Sphere(Vec3 center, double radius) : center_(center), radius_(radius) {}

    const char* name() const override { return "sphere"; }
    double area() const override { return 4 * kPi * radius_ * radius_; }
    Vec3 center() const override { return center_; }
    std::optional<Vec3> normal() const override { return std::nullopt; }
    double reach() const override { return radius_; }

    std::shared_ptr<const EmitterShape> transformed(const Transform& t) const override {
        return std::make_shared<Sphere>(t.applyPoint(center_), radius_);
    }

    std::optional<EmitterPoint> sample(const Vec3& p, Vec2 u) const override {
        Vec3 toCenter = center_ - p;
        double dist2 = lengthSquared(toCenter);
        if (dist2 <= radius_ * radius_) return std::nullopt;
        double dist = std::sqrt(dist2), cosMax = std::sqrt(std::max(0.0, 1 - radius_ * radius_ / dist2));
        Frame f = Frame::fromNormal(toCenter / dist);
        Vec3 w = f.toWorld(sampleUniformCone(u, cosMax));
        // Nearest intersection of p + t w with the sphere.
        double b = dot(w, toCenter), c = dist2 - radius_ * radius_, disc = std::max(0.0, b * b - c);
        Vec3 q = p + w * (b - std::sqrt(disc));
        return EmitterPoint{q, normalize(q - center_), uniformConePdf(cosMax)};
    }

    double pdf(const Vec3& p, const Vec3&) const override {
        double dist2 = lengthSquared(center_ - p);
        if (dist2 <= radius_ * radius_) return 0;
        return uniformConePdf(std::sqrt(std::max(0.0, 1 - radius_ * radius_ / dist2)));
    }

    EmitterPrimitive primitive() const override {
        EmitterPrimitive p;
        p.kind = EmitterPrimitive::Kind::Sphere;
        p.center = center_, p.radius = radius_;
        return p;
    }

    // Its horizontal great circle: what a plan shows.
    std::vector<Vec3> outline() const override {
        std::vector<Vec3> pts;
        for (int i = 0; i < kOutlinePoints; ++i) {
            double phi = 2 * kPi * i / kOutlinePoints;
            pts.push_back(center_ + Vec3(std::cos(phi), std::sin(phi), 0) * radius_);
        }
        return pts;
    }

    EmitterMesh mesh() const override {
        EmitterMesh m;
        m.mesh = unitIcosphere(kMeshSubdivisions);
        for (Vec3& v : m.mesh.positions) v = v * radius_;
        m.frame.t = center_;
        return m;
    }

    std::string describe() const override { return "sphere of radius " + json::formatNumber(radius_) + " m"; }

private:
    Vec3 center_;
    double radius_;
};

}  // namespace

std::shared_ptr<const EmitterShape> sphereEmitter(Vec3 center, double radius) {
    return std::make_shared<Sphere>(center, radius);
}

std::shared_ptr<const EmitterShape> readSphereEmitter(const json::Fields& f) {
    Vec3 center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    double radius = f.number("radius", json::luminaireSizeRange(), true).value_or(0.1);
    return sphereEmitter(center, radius);
}

}  // namespace luxplan
