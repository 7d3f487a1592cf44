// Cylindrical sampler: the cylindrical illuminance E_z (lx) at a point, the mean
// illuminance on the curved surface of a small vertical cylinder there (EN 12464-1's
// measure of how well faces are lit): E_z = (1/pi) * integral of L sin(theta) d omega
// over the sphere, theta from the vertical. Its own sensor gives that response.
#include <cmath>

#include <luxplan/core/warp.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {
namespace {

// Response sin(theta) / pi; directions uniform on the sphere, so each path's weight
// response / pdf = 4 sin(theta) stays below 4.
class CylindricalSensor final : public Sensor {
public:
    explicit CylindricalSensor(const Vec3& p) : p_(p) {}
    Vec3 position() const override { return p_; }
    bool isDelta() const override { return false; }
    double response(const Vec3& wi) const override { return std::sqrt(std::max(0.0, 1 - wi.z * wi.z)) * kInvPi; }
    double pdf(const Vec3&) const override { return uniformSpherePdf(); }
    SensorSample sample(Vec2 u) const override {
        Vec3 wi = sampleUniformSphere(u);
        return {wi, response(wi) / uniformSpherePdf(), uniformSpherePdf(), false};
    }

private:
    Vec3 p_;
};

class PlacedCylindrical final : public PlacedSampler {
public:
    explicit PlacedCylindrical(const Vec3& p) : p_(p) {}
    int items() const override { return 1; }
    void sample(const PathTracer& tracer, int, PathSamples& samples, RayStats& stats, const PathParams& params,
                PathContributions& out) const override {
        out.add(tracer.sample(CylindricalSensor(p_), samples, stats, params));
    }
    std::unique_ptr<Sensor> sensorOf(int /*item*/) const override { return std::make_unique<CylindricalSensor>(p_); }
    // A 15 cm circle around the point, as plans mark a cylindrical measurement.
    SamplerDrawing drawing() const override {
        SamplerDrawing d;
        for (int i = 0; i < 16; ++i) {
            double phi = 2 * kPi * i / 16;
            d.outline.push_back(p_ + Vec3(std::cos(phi), std::sin(phi), 0) * 0.15);
        }
        d.lineWidth = 1.5;
        d.dots = {p_};
        d.dotRadius = 3;
        return d;
    }

private:
    Vec3 p_;
};

class Cylindrical final : public SamplerType {
public:
    Vec3 center;

    const char* name() const override { return "cylindrical"; }
    const char* unit() const override { return "lx"; }
    std::string quantityHtml(bool) const override { return "E<sub>z</sub> (cylindrical illuminance)"; }
    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        return std::make_unique<PlacedCylindrical>(world.applyPoint(center));
    }
    bool looksAllRound() const override { return true; }
    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Cylindrical>(*this);
        s->center = t.applyPoint(center);
        return s;
    }
    std::string describe() const override { return "cylindrical illuminance at a point"; }
};

}  // namespace

std::shared_ptr<const SamplerType> cylindricalSampler(Vec3 center) {
    auto s = std::make_shared<Cylindrical>();
    s->center = center;
    return s;
}

std::shared_ptr<const SamplerType> readCylindricalSampler(const json::Fields& f) {
    auto s = std::make_shared<Cylindrical>();
    s->center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    return s;
}

}  // namespace luxplan
