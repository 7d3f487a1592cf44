#include <luxplan/pathtracer/sensor.h>

#include <luxplan/core/warp.h>

namespace luxplan {

double CosineSensor::response(const Vec3& wi) const { return std::max(0.0, dot(wi, n_)); }
double CosineSensor::pdf(const Vec3& wi) const { return cosineHemispherePdf(dot(wi, n_)); }
SensorSample CosineSensor::sample(Vec2 u) const {
    Vec3 local = sampleCosineHemisphere(u);
    return {Frame::fromNormal(n_).toWorld(local), kPi, cosineHemispherePdf(local.z), false};  // cos / pdf = pi
}

double SphereSensor::response(const Vec3&) const { return 1 / (4 * kPi); }
double SphereSensor::pdf(const Vec3&) const { return uniformSpherePdf(); }
SensorSample SphereSensor::sample(Vec2 u) const {
    return {sampleUniformSphere(u), 1, uniformSpherePdf(), false};  // (1 / 4 pi) / pdf
}

}  // namespace luxplan
