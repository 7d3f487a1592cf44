// Rect emitter: a one-sided rectangle (a panel, a troffer's diffuser), sampled
// uniformly in the solid angle it subtends (core/spherical_rect.h).
#include <luxplan/core/spherical_rect.h>
#include <luxplan/emitters/emitter_shape.h>

namespace luxplan {
namespace {

class Rect final : public EmitterShape {
public:
    // `normal` and `up` as given (unit and orthogonal in the scene's own frame); the
    // unit frame and the rectangle are derived once.
    Rect(Vec3 center, Vec3 normal, Vec3 up, Vec2 size) : center_(center), normal_(normal), up_(up), size_(size) {
        n_ = normalize(normal_);
        Vec3 v = normalize(up_);
        Vec3 u = cross(v, n_);  // first side, so that cross(u, up) = normal
        rect_ = {center_ - u * (size_.x / 2) - v * (size_.y / 2), u * size_.x, v * size_.y};
    }

    const char* name() const override { return "rect"; }
    double area() const override { return size_.x * size_.y; }
    Vec3 center() const override { return center_; }
    std::optional<Vec3> normal() const override { return n_; }
    double reach() const override { return 0.5 * length(rect_.edgeU + rect_.edgeV); }
    std::optional<Vec3> firstSide() const override { return normalize(rect_.edgeU); }

    std::shared_ptr<const EmitterShape> transformed(const Transform& t) const override {
        return std::make_shared<Rect>(t.applyPoint(center_), t.applyVector(normal_), t.applyVector(up_), size_);
    }

    std::optional<EmitterPoint> sample(const Vec3& p, Vec2 u) const override { return sampleFrom(SphericalRect(rect_, p), u); }
    double pdf(const Vec3& p, const Vec3&) const override { return pdfFrom(SphericalRect(rect_, p)); }

    // The spherical rectangle (four acos and a sqrt to set up) once per point.
    std::unique_ptr<const FromPoint> from(const Vec3& p) const override {
        class Prepared final : public FromPoint {
        public:
            Prepared(const Rect& rect, const Vec3& p) : rect_(rect), sr_(rect.rect_, p) {}
            std::optional<EmitterPoint> sample(Vec2 u) const override { return rect_.sampleFrom(sr_, u); }
            double pdf(const Vec3&) const override { return rect_.pdfFrom(sr_); }

        private:
            const Rect& rect_;
            SphericalRect sr_;
        };
        return std::make_unique<Prepared>(*this, p);
    }

    EmitterPrimitive primitive() const override {
        // Two triangles, wound so that their normal is the emitter's.
        Vec3 v = up_, u = cross(v, normal_);
        Vec3 hu = u * (size_.x / 2), hv = v * (size_.y / 2);
        EmitterPrimitive p;
        addQuad(p.triangles, center_ - hu - hv, center_ + hu - hv, center_ + hu + hv, center_ - hu + hv, 0);
        return p;
    }

    std::vector<Vec3> outline() const override {
        return {rect_.corner, rect_.corner + rect_.edgeU, rect_.corner + rect_.edgeU + rect_.edgeV, rect_.corner + rect_.edgeV};
    }

    EmitterMesh mesh() const override {
        EmitterMesh m;
        double a = size_.x / 2, b = size_.y / 2;
        m.mesh.positions = {{-a, -b, 0}, {a, -b, 0}, {a, b, 0}, {-a, b, 0}};
        m.mesh.addTriangle(0, 3, 2, 0);
        m.mesh.addTriangle(0, 2, 1, 0);
        m.mesh.normals.assign(4, Vec3(0, 0, -1));
        // Local -z along the normal, x along the first side, y along the second (up).
        Vec3 n = normalize(normal_), up = up_ - n * dot(up_, n);
        Vec3 y = length(up) > 1e-9 ? normalize(up) : Frame::fromNormal(-n).t;
        Vec3 x = length(up) > 1e-9 ? -cross(y, n) : Frame::fromNormal(-n).s;
        Vec3 z = -n;
        m.frame.t = center_;
        m.frame.m = {x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z};
        return m;
    }

    std::string describe() const override {
        return json::formatNumber(size_.x) + " x " + json::formatNumber(size_.y) + " m rect";
    }

private:
    std::optional<EmitterPoint> sampleFrom(const SphericalRect& sr, Vec2 u) const {
        if (sr.solidAngle() <= 0) return std::nullopt;
        return EmitterPoint{sr.sample(u), n_, 1 / sr.solidAngle()};
    }
    static double pdfFrom(const SphericalRect& sr) { return sr.solidAngle() > 0 ? 1 / sr.solidAngle() : 0; }

    Vec3 center_, normal_, up_;
    Vec2 size_;
    Vec3 n_;
    Rect3 rect_;
};

}  // namespace

std::shared_ptr<const EmitterShape> rectEmitter(Vec3 center, Vec3 normal, Vec3 up, Vec2 size) {
    return std::make_shared<Rect>(center, normal, up, size);
}

std::shared_ptr<const EmitterShape> readRectEmitter(const json::Fields& f) {
    Vec3 center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    Vec3 normal = f.direction("normal").value_or(Vec3(0, 0, -1));
    Vec2 size = f.vec2("size", true, json::luminaireSizeRange()).value_or(Vec2(1, 1));
    Vec3 up = f.direction("up").value_or(std::abs(normal.y) > 0.999 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    if (length(cross(up, normal)) < 1e-6) {
        f.error(f.has("up") ? "up" : "normal", "\"up\" is parallel to \"normal\"");
        up = Vec3(0, 1, 0);
    } else {
        up = normalize(up - normal * dot(up, normal));  // orthogonalize
    }
    return rectEmitter(center, normal, up, size);
}

}  // namespace luxplan
