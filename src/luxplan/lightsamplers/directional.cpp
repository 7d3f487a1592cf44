// Directional sampler: the mean luminance (cd/m2) seen from an eye through each
// cell of a strata x strata grid over a pyramidal frustum; its value is the
// brightest cell's (glare on a screen, a presenter seen by the audience).
#include <cmath>
#include <stdexcept>

#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {
namespace {

class PlacedDirectional final : public PlacedSampler {
public:
    Vec3 eye, forward, right, up;
    double tanHalfFov = 0;
    int strata = 0;

    int items() const override { return strata * strata; }

    // A direction spread uniformly over the stratum's cell of the image plane; the
    // strata are row-major, right fastest, bottom row first.
    double sample(const PathTracer& tracer, int item, Rng& rng, RayStats& stats) const override {
        int i = item % strata, j = item / strata;
        double a = (-1 + 2 * (i + rng.uniform()) / strata) * tanHalfFov;
        double b = (-1 + 2 * (j + rng.uniform()) / strata) * tanHalfFov;
        Vec3 d = normalize(forward + right * a + up * b);
        return tracer.sample(RaySensor({eye, d}), rng, stats);
    }

    // The brightest stratum, with that stratum's own error (the selection among
    // noisy strata is not part of it).
    Estimate combine(const std::vector<double>& means, const std::vector<double>& errors) const override {
        Estimate e;
        if (means.empty()) return e;
        size_t best = 0;
        for (size_t i = 1; i < means.size(); ++i)
            if (means[i] > means[best]) best = i;
        e.value = means[best];
        e.standardError = errors[best];
        return e;
    }

    // The apex and the frustum's four edge rays, 1 m long.
    SamplerDrawing drawing() const override {
        const double reach = 1.0;
        SamplerDrawing d;
        d.outline.push_back(eye);
        for (int i = 0; i < 4; ++i) {
            double a = (i & 1) ? 1 : -1, b = (i & 2) ? 1 : -1;
            d.outline.push_back(eye + normalize(forward + right * (a * tanHalfFov) + up * (b * tanHalfFov)) * reach);
        }
        d.fillOpacity = 0.12;
        d.lineWidth = 1.5;
        d.dots = {eye};
        d.dotRadius = 4;
        d.labelAt = eye;
        return d;
    }
};

class Directional final : public SamplerType {
public:
    Vec3 origin, direction{0, -1, 0}, up{0, 0, 1};
    double fovDeg = 60;
    int strata = 8;

    const char* name() const override { return "directional"; }
    const char* unit() const override { return "cd/m2"; }

    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        auto p = std::make_unique<PlacedDirectional>();
        p->eye = world.applyPoint(origin);
        p->forward = normalize(world.applyVector(direction));
        p->right = normalize(cross(p->forward, world.applyVector(up)));
        p->up = cross(p->right, p->forward);
        p->tanHalfFov = std::tan(radians(fovDeg) / 2);
        p->strata = strata;
        return p;
    }

    std::shared_ptr<const SamplerType> transformed(const Transform& t) const override {
        auto s = std::make_shared<Directional>(*this);
        s->origin = t.applyPoint(origin);
        s->direction = t.applyVector(direction);
        s->up = t.applyVector(up);
        return s;
    }

    std::string describe() const override {
        return std::to_string(strata) + " x " + std::to_string(strata) + " strata over " + json::formatNumber(fovDeg) + " deg";
    }
};

}  // namespace

std::shared_ptr<const SamplerType> directionalSampler(Vec3 origin, Vec3 direction, Vec3 up, double fovDeg, int strata) {
    if (length(direction) < 1e-12 || length(up) < 1e-12) throw std::invalid_argument("directional sampler: zero direction");
    if (!(fovDeg > 0 && fovDeg < 180)) throw std::invalid_argument("directional sampler: fov_deg must lie in (0, 180)");
    if (strata < 1 || strata > 256) throw std::invalid_argument("directional sampler: strata must lie in [1, 256]");
    auto s = std::make_shared<Directional>();
    s->origin = origin;
    s->direction = normalize(direction);
    s->up = normalize(up);
    if (length(cross(s->up, s->direction)) < 1e-6)
        throw std::invalid_argument("directional sampler: \"up\" is parallel to \"direction\"");
    s->fovDeg = fovDeg;
    s->strata = strata;
    return s;
}

std::shared_ptr<const SamplerType> readDirectionalSampler(const json::Fields& f) {
    auto s = std::make_shared<Directional>();
    s->origin = f.vec3("origin", true).value_or(Vec3());
    s->direction = f.direction("direction", true).value_or(Vec3(0, -1, 0));
    s->fovDeg = f.number("fov_deg", 60.0, json::Range{0, 180, true, true, "deg"});
    s->strata = f.integer("strata", json::Range::closed(1, 256)).value_or(8);
    Vec3 fallbackUp = std::abs(s->direction.z) > 0.999 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    s->up = f.direction("up").value_or(fallbackUp);
    if (length(cross(s->up, s->direction)) < 1e-6) f.error("up", "\"up\" is parallel to \"direction\"");
    return s;
}

}  // namespace luxplan
