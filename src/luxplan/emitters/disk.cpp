// Disk emitter: a one-sided disk (a downlight's opening), sampled uniformly by
// area (concentric map) and converted to solid angle.
#include <luxplan/core/warp.h>
#include <luxplan/emitters/emitter_shape.h>

namespace luxplan {
namespace {

constexpr int kMeshSegments = 48;  // of the glTF mesh

class Disk final : public EmitterShape {
public:
    Disk(Vec3 center, Vec3 normal, double radius)
        : center_(center), normal_(normal), radius_(radius), n_(normalize(normal)), frame_(Frame::fromNormal(n_)) {}

    const char* name() const override { return "disk"; }
    double area() const override { return kPi * radius_ * radius_; }
    Vec3 center() const override { return center_; }
    std::optional<Vec3> normal() const override { return n_; }
    double reach() const override { return radius_; }

    std::shared_ptr<const EmitterShape> transformed(const Transform& t) const override {
        return std::make_shared<Disk>(t.applyPoint(center_), t.applyVector(normal_), radius_);
    }

    std::optional<EmitterPoint> sample(const Vec3& p, Vec2 u) const override {
        Vec2 d = sampleUniformDiskConcentric(u);
        Vec3 q = center_ + (frame_.s * d.x + frame_.t * d.y) * radius_;
        return EmitterPoint{q, n_, pdf(p, q)};
    }

    double pdf(const Vec3& p, const Vec3& q) const override {
        Vec3 d = q - p;
        double dist2 = lengthSquared(d), cosE = std::abs(dot(normalize(d), n_));
        return cosE > 0 ? dist2 / (area() * cosE) : 0;
    }

    EmitterPrimitive primitive() const override {
        EmitterPrimitive p;
        p.kind = EmitterPrimitive::Kind::Disc;
        p.center = center_, p.normal = normal_, p.radius = radius_;
        return p;
    }

    std::vector<Vec3> outline() const override {
        Frame f = Frame::fromNormal(n_);
        std::vector<Vec3> pts;
        for (int i = 0; i < kOutlinePoints; ++i) {
            double phi = 2 * kPi * i / kOutlinePoints;
            pts.push_back(center_ + (f.s * std::cos(phi) + f.t * std::sin(phi)) * radius_);
        }
        return pts;
    }

    EmitterMesh mesh() const override {
        EmitterMesh m;
        m.mesh.positions.push_back({0, 0, 0});
        for (int k = 0; k < kMeshSegments; ++k) {
            double phi = 2 * kPi * k / kMeshSegments;
            m.mesh.positions.push_back({radius_ * std::cos(phi), radius_ * std::sin(phi), 0});
        }
        // A fan whose triangles face -z.
        for (uint32_t k = 0; k < uint32_t(kMeshSegments); ++k) m.mesh.addTriangle(0, 1 + (k + 1) % kMeshSegments, 1 + k, 0);
        m.mesh.normals.assign(m.mesh.positions.size(), Vec3(0, 0, -1));
        Frame f = Frame::fromNormal(-n_);
        Vec3 x = f.s, y = f.t, z = -n_;
        m.frame.t = center_;
        m.frame.m = {x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z};
        return m;
    }

    std::string describe() const override { return "disk of radius " + json::formatNumber(radius_) + " m"; }

private:
    Vec3 center_, normal_;
    double radius_;
    Vec3 n_;
    Frame frame_;  // of n_, for sample()
};

}  // namespace

std::shared_ptr<const EmitterShape> diskEmitter(Vec3 center, Vec3 normal, double radius) {
    return std::make_shared<Disk>(center, normal, radius);
}

std::shared_ptr<const EmitterShape> readDiskEmitter(const json::Fields& f) {
    Vec3 center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    Vec3 normal = f.direction("normal").value_or(Vec3(0, 0, -1));
    double radius = f.number("radius", json::luminaireSizeRange(), true).value_or(0.1);
    return diskEmitter(center, normal, radius);
}

}  // namespace luxplan
