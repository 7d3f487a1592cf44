// A photometric luminaire: an emitter shape taken as the luminous opening of a
// measured intensity distribution (intensity_distribution.h). Its luminance towards
// omega is I(omega) / (the opening's area projected across omega), so that far from
// it E = I cos(incidence) / d^2. Everything geometric (point sampling, Embree, plans,
// glTF) is the opening's own; only what it emits changes.
#pragma once

#include <memory>
#include <string>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/emitters/intensity_distribution.h>

namespace luxplan {

class PhotometricEmitter final : public EmitterShape {
public:
    // `axis`: where gamma = 0 points; `c0`: where C = 0 points (its part normal to
    // the axis; it must not be parallel to it). `source` names the file for people.
    PhotometricEmitter(std::shared_ptr<const EmitterShape> opening, std::shared_ptr<const IntensityDistribution> distribution,
                       Vec3 axis, Vec3 c0, std::string source);

    const char* name() const override { return opening_->name(); }
    double area() const override { return opening_->area(); }
    Vec3 center() const override { return opening_->center(); }
    // One-sided like its opening unless the file sends light past gamma = 90: a flat
    // opening then emits from both faces.
    std::optional<Vec3> normal() const override;
    double reach() const override { return opening_->reach(); }
    std::optional<Vec3> firstSide() const override { return opening_->firstSide(); }
    std::shared_ptr<const EmitterShape> transformed(const Transform& newFromOld) const override;
    std::optional<EmitterPoint> sample(const Vec3& p, Vec2 u) const override { return opening_->sample(p, u); }
    double pdf(const Vec3& p, const Vec3& q) const override { return opening_->pdf(p, q); }
    std::unique_ptr<const FromPoint> from(const Vec3& p) const override { return opening_->from(p); }
    EmitterPrimitive primitive() const override { return opening_->primitive(); }
    std::vector<Vec3> outline() const override { return opening_->outline(); }
    EmitterMesh mesh() const override { return opening_->mesh(); }
    std::string describe() const override;

    const EmitterShape& opening() const { return *opening_; }
    const IntensityDistribution& distribution() const { return *distribution_; }
    const std::string& source() const { return source_; }
    // The luminaire's unit axes in this shape's frame: gamma = 0, C = 0, C = 90 (c0 x axis).
    Vec3 axis() const { return axis_; }
    Vec3 c0() const { return c0_; }
    Vec3 c90() const { return c90_; }
    // A direction of this frame in the luminaire's (x: C = 0, y: C = 90, z: gamma = 0).
    Vec3 toLuminaire(const Vec3& w) const { return {dot(w, c0_), dot(w, c90_), dot(w, axis_)}; }
    // The file's candela along the unit direction w (light leaving the luminaire).
    double intensity(const Vec3& w) const { return distribution_->intensity(toLuminaire(w)); }
    // The area the opening shows across w: A |cos| to a flat opening's normal, A / 4
    // for a sphere (pi r^2).
    double projectedArea(const Vec3& w) const;

private:
    std::shared_ptr<const EmitterShape> opening_;
    std::shared_ptr<const IntensityDistribution> distribution_;
    Vec3 axis_, c0_, c90_;
    std::string source_;
};

// Where C = 0 points when the scene does not say: a rect's first side, else world +x
// (+y for an axis along x) projected onto the plane normal to `axis`.
Vec3 defaultC0(const EmitterShape& opening, const Vec3& axis);

// The luminaire of `opening` and `distribution`, gamma = 0 along `axis` (a flat
// opening's normal), C = 0 along `c0` (none: defaultC0).
std::shared_ptr<const PhotometricEmitter> photometricEmitter(std::shared_ptr<const EmitterShape> opening,
                                                             std::shared_ptr<const IntensityDistribution> distribution,
                                                             Vec3 axis, std::optional<Vec3> c0 = std::nullopt,
                                                             std::string source = "");

}  // namespace luxplan
