#include <luxplan/pathtracer/sensor.h>

#include <algorithm>
#include <cmath>

#include <luxplan/core/warp.h>

namespace luxplan {

bool pyramidMaySee(const Vec3& forward, const Vec3& right, const Vec3& up, double tanHalfFov, const Vec3& axis,
                   double cosHalfAngle) {
    // The side planes' inward normals are tanHalfFov forward -+ right and tanHalfFov
    // forward -+ up, of length sqrt(tanHalfFov^2 + 1); a cone lies wholly outside one
    // when its axis is more than 90 degrees plus its half-angle from that normal.
    if (!(cosHalfAngle > 0)) return true;
    const double sinHalf = std::sqrt(std::max(0.0, 1 - cosHalfAngle * cosHalfAngle));
    // A hair of slack for rounding: a cone that touches a side plane counts as seen.
    const double below = -(sinHalf + 1e-9) * std::sqrt(tanHalfFov * tanHalfFov + 1);
    const double ahead = tanHalfFov * dot(axis, forward), across = dot(axis, right), along = dot(axis, up);
    return ahead - across >= below && ahead + across >= below && ahead - along >= below && ahead + along >= below;
}

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
