// The first vertex of a path: what a measurement responds to, as pbrt's camera or
// sensor does. A sensor evaluates its response to light arriving from a direction
// (next-event estimation at the sensor uses it), gives the density with which it
// samples directions (for multiple importance sampling), and samples one. Light
// samplers choose their sensor; the path tracer traces from any of them.
#pragma once

#include <optional>

#include <luxplan/core/math.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

struct SensorSample {
    Vec3 wi;             // unit, away from the sensor
    double weight = 0;   // response * |cos| / pdf
    double pdf = 0;      // per unit solid angle; 0 for a delta direction
    bool delta = false;  // a single direction: no light sampling at the sensor
};

class Sensor {
public:
    virtual ~Sensor() = default;
    virtual Vec3 position() const = 0;
    // Whether it sees along one direction only (a camera ray): light sampling at the
    // sensor cannot find that direction, so the tracer skips it there.
    virtual bool isDelta() const = 0;
    // The response to unit luminance arriving from `wi` (unit, away from the sensor).
    virtual double response(const Vec3& wi) const = 0;
    virtual double pdf(const Vec3& wi) const = 0;
    virtual SensorSample sample(Vec2 u) const = 0;
    // False only when the response is zero for every direction within the cone of
    // half-angle acos(cosHalfAngle) around unit `axis`: the tracer then draws no light
    // sample there (a glare frustum that faces away from every window). True when unsure.
    virtual bool maySee(const Vec3& /*axis*/, double /*cosHalfAngle*/) const { return true; }
    // Whether the light a luminaire or a sun disk sends straight to the sensor is left
    // out (the sky, the ground outside and everything scattered still count): the DGP
    // sampler's direction cells, whose sources are surveyed apart.
    virtual bool hidesSources() const { return false; }
};

// Sensor::maySee for a sensor that responds inside the pyramid of directions w with
// |dot(w, right)| and |dot(w, up)| at most tanHalfFov dot(w, forward) (an orthonormal
// frame): false only when the cone lies wholly outside one of its four side planes.
bool pyramidMaySee(const Vec3& forward, const Vec3& right, const Vec3& up, double tanHalfFov, const Vec3& axis,
                   double cosHalfAngle);

// Illuminance (lx) at a point over the hemisphere around unit `normal`: response cos,
// directions cosine-weighted.
class CosineSensor final : public Sensor {
public:
    CosineSensor(const Vec3& p, const Vec3& normal) : p_(p), n_(normal) {}
    Vec3 position() const override { return p_; }
    bool isDelta() const override { return false; }
    double response(const Vec3& wi) const override;
    double pdf(const Vec3& wi) const override;
    SensorSample sample(Vec2 u) const override;

private:
    Vec3 p_, n_;
};

// Mean luminance (cd/m2) over the whole sphere at a point: response 1 / (4 pi),
// directions uniform.
class SphereSensor final : public Sensor {
public:
    explicit SphereSensor(const Vec3& p) : p_(p) {}
    Vec3 position() const override { return p_; }
    bool isDelta() const override { return false; }
    double response(const Vec3& wi) const override;
    double pdf(const Vec3& wi) const override;
    SensorSample sample(Vec2 u) const override;

private:
    Vec3 p_;
};

// Luminance (cd/m2) arriving along one ray: a pinhole camera's pixel sample; with
// `hideSources`, less what a luminaire or sun disk met by the ray itself emits.
class RaySensor final : public Sensor {
public:
    explicit RaySensor(const Ray& ray, bool hideSources = false) : ray_(ray), hideSources_(hideSources) {}
    Vec3 position() const override { return ray_.origin; }
    bool isDelta() const override { return true; }
    double response(const Vec3&) const override { return 0; }
    double pdf(const Vec3&) const override { return 0; }
    SensorSample sample(Vec2) const override { return {normalize(ray_.direction), 1, 0, true}; }
    bool hidesSources() const override { return hideSources_; }

private:
    Ray ray_;
    bool hideSources_;
};

}  // namespace luxplan
