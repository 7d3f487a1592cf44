#include <luxplan/emitters/photometric_emitter.h>

#include <stdexcept>

namespace luxplan {

PhotometricEmitter::PhotometricEmitter(std::shared_ptr<const EmitterShape> opening,
                                       std::shared_ptr<const IntensityDistribution> distribution, Vec3 axis, Vec3 c0,
                                       std::string source)
    : opening_(std::move(opening)), distribution_(std::move(distribution)), source_(std::move(source)) {
    axis_ = normalize(axis);
    Vec3 c = c0 - axis_ * dot(c0, axis_);
    if (length(c) < 1e-9) throw std::invalid_argument("photometric emitter: c0 is parallel to the axis");
    c0_ = normalize(c);
    c90_ = cross(c0_, axis_);  // the contract's C = 90: counter-clockwise seen along -axis
}

std::optional<Vec3> PhotometricEmitter::normal() const {
    if (distribution_->emitsBeyond90()) return std::nullopt;
    return opening_->normal();
}

std::shared_ptr<const EmitterShape> PhotometricEmitter::transformed(const Transform& t) const {
    return std::make_shared<PhotometricEmitter>(opening_->transformed(t), distribution_, t.applyVector(axis_),
                                                t.applyVector(c0_), source_);
}

double PhotometricEmitter::projectedArea(const Vec3& w) const {
    auto n = opening_->normal();
    return n ? opening_->area() * std::abs(dot(w, *n)) : opening_->area() / 4;
}

std::string PhotometricEmitter::describe() const {
    return opening_->describe() + ", photometric" + (source_.empty() ? "" : " (" + source_ + ")");
}

Vec3 defaultC0(const EmitterShape& opening, const Vec3& axis) {
    if (auto side = opening.firstSide()) return *side;
    Vec3 n = normalize(axis);
    Vec3 x(1, 0, 0);
    if (length(cross(x, n)) < 1e-6) x = Vec3(0, 1, 0);
    return normalize(x - n * dot(x, n));
}

std::shared_ptr<const PhotometricEmitter> photometricEmitter(std::shared_ptr<const EmitterShape> opening,
                                                             std::shared_ptr<const IntensityDistribution> distribution,
                                                             Vec3 axis, std::optional<Vec3> c0, std::string source) {
    Vec3 c = c0 ? *c0 : defaultC0(*opening, axis);
    return std::make_shared<PhotometricEmitter>(std::move(opening), std::move(distribution), axis, c, std::move(source));
}

}  // namespace luxplan
