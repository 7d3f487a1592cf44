// Volume sampler: the mean spherical luminance (cd/m2) at Halton points in an
// oriented box, e.g. the space a presenter stands in; its value is their mean.
#include <cmath>
#include <stdexcept>

#include <luxplan/lightsamplers/sampler_type.h>
#include <nlohmann/json.hpp>

#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {
namespace {

// Halton radical inverse: well-spread, deterministic points.
double radicalInverse(int base, uint64_t i) {
    double inv = 1.0 / base, f = inv, r = 0;
    while (i > 0) {
        r += f * double(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

class PlacedVolume final : public PlacedSampler {
public:
    std::vector<Vec3> points, corners;

    int items() const override { return int(points.size()); }
    void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                PathContributions& out) const override {
        out.add(tracer.sample(SphereSensor(points[size_t(item)]), samples, stats, params));
    }
    std::unique_ptr<Sensor> sensorOf(int item) const override { return std::make_unique<SphereSensor>(points[size_t(item)]); }
    SamplerDrawing drawing() const override {
        SamplerDrawing d;
        d.outline = corners;
        d.fillOpacity = 0.15;
        return d;
    }
};

class Volume final : public SamplerType {
public:
    Vec3 center;
    std::array<Vec3, 3> axes{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};  // the box's sides
    int points = 200;

    const char* name() const override { return "volume"; }
    const char* unit() const override { return "cd/m2"; }
    std::string quantityHtml(bool) const override { return "mean luminance"; }

    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        auto p = std::make_unique<PlacedVolume>();
        Vec3 corner = center - (axes[0] + axes[1] + axes[2]) * 0.5;
        for (int i = 0; i < points; ++i) {
            // Halton points 1..N in the unit cube, mapped onto the box.
            Vec3 u(radicalInverse(2, i + 1), radicalInverse(3, i + 1), radicalInverse(5, i + 1));
            p->points.push_back(world.applyPoint(corner + axes[0] * u.x + axes[1] * u.y + axes[2] * u.z));
        }
        for (int i = 0; i < 8; ++i)
            p->corners.push_back(world.applyPoint(corner + axes[0] * double(i & 1) + axes[1] * double((i >> 1) & 1) +
                                                  axes[2] * double((i >> 2) & 1)));
        return p;
    }

    bool looksAllRound() const override { return true; }
    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Volume>(*this);
        s->center = t.applyPoint(center);
        for (Vec3& a : s->axes) a = t.applyVector(a);
        return s;
    }

    std::string describe() const override {
        return std::to_string(points) + " points in a " + json::formatNumber(length(axes[0])) + " x " +
               json::formatNumber(length(axes[1])) + " x " + json::formatNumber(length(axes[2])) + " m box";
    }

    bool hasPointStatistics() const override { return true; }
};

}  // namespace

std::shared_ptr<const SamplerType> volumeSampler(Vec3 center, std::array<Vec3, 3> axes, int points) {
    if (std::abs(dot(cross(axes[0], axes[1]), axes[2])) < 1e-12)
        throw std::invalid_argument("volume sampler: the box has zero volume (side vectors are degenerate)");
    if (points < 1 || points > limits::kMaxSamplerPoints)
        throw std::invalid_argument("volume sampler: points must lie in [1, " + std::to_string(limits::kMaxSamplerPoints) + "]");
    auto s = std::make_shared<Volume>();
    s->center = center;
    s->axes = axes;
    s->points = points;
    return s;
}

std::shared_ptr<const SamplerType> readVolumeSampler(const json::Fields& f) {
    auto s = std::make_shared<Volume>();
    s->center = f.vec3("center", true, json::coordinateRange()).value_or(Vec3());
    if (const json::Json* axes = f.array("axes", true)) {
        if (axes->size() != 3) {
            f.error("axes", "expected three side vectors, got " + std::to_string(axes->size()));
        } else {
            bool ok = true;
            for (size_t i = 0; i < 3; ++i) {
                auto n = json::readNumbers(f.sink(), (*axes)[i], json::pointer(f.at("axes"), i), 3,
                                           json::signedLengthRange());
                if (n) s->axes[i] = Vec3((*n)[0], (*n)[1], (*n)[2]);
                else ok = false;
            }
            if (ok && std::abs(dot(cross(s->axes[0], s->axes[1]), s->axes[2])) < 1e-12)
                f.error("axes", "the box has zero volume (side vectors are degenerate)");
        }
    }
    s->points = f.integer("points", json::Range::atLeast(1)).value_or(200);
    if (s->points > limits::kMaxSamplerPoints) {
        f.error("points", std::to_string(s->points) + " points exceeds the limit of " + std::to_string(limits::kMaxSamplerPoints));
        s->points = 200;
    }
    return s;
}

}  // namespace luxplan
