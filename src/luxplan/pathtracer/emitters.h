// Area emitters in world space (fixed luminaires and the ones entities carry, placed
// by the current layout), their sampling from a shading point with pdfs per unit
// solid angle, and the choice of which emitter to sample (EmitterSelector).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/emitters/photometric_emitter.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// One emitter placed by the current layout.
struct WorldEmitter {
    std::shared_ptr<const EmitterShape> shape;  // world frame
    // cd/m^2 (maintenance factor x flux / (pi A)); a photometric luminaire's varies with direction
    double luminance = 0;
    double flux = 0;       // lm, as rated (the emitter choice's weight; the maintenance factor not applied)
    // What the emitter choice reads for every emitter at every vertex, copied out of
    // the shape once per layout so the hot loop makes no virtual calls.
    Vec3 center;
    double reach = 0;
    std::optional<Vec3> normal;  // one-sided emitters
    // A photometric luminaire (the shape itself, world frame) and the factor taking
    // its file's candela to `flux`; null for a Lambertian emitter.
    const PhotometricEmitter* photometric = nullptr;
    double intensityScale = 0;
    double maintenance = 1;  // Scene::maintenanceFactor: what it emits is this share of intensityScale's

};

// A sampled point on an emitter as seen from a shading point.
struct EmitterSample {
    Vec3 wi;          // unit, from the shading point to the emitter
    double distance = 0;
    double Lv = 0;    // emitted luminance towards the point (0 if it sees the back)
    double pdf = 0;   // per unit solid angle, including the emitter's selection probability
    int emitter = -1; // which emitter (shadow rays end when they reach it)
};

enum class EmitterSelection {
    Uniform,        // every emitter equally likely
    // flux / distance^2, zero for points behind a one-sided emitter; a photometric
    // luminaire's weight is 4 pi I(towards the point) / distance^2, so that the
    // choice follows its intensity distribution.
    PowerDistance,
};

class EmitterSet {
public:
    EmitterSet() = default;
    // World-space emitters from the scene and the entities' world transforms.
    EmitterSet(const Scene& scene, const std::vector<Transform>& worldFromEntity, EmitterSelection selection);

    bool empty() const { return emitters_.empty(); }
    size_t size() const { return emitters_.size(); }
    const WorldEmitter& operator[](size_t i) const { return emitters_[i]; }

    // Probability of choosing emitter i when sampling from point p (normal n; zero
    // normal for points that see all round).
    double selectionProbability(size_t i, const Vec3& p) const;
    // Chooses an emitter (uSelect) and a point on it (u).
    EmitterSample sample(const Vec3& p, double uSelect, Vec2 u) const;
    // Density (per solid angle, selection included) that sample() gives the point
    // `onEmitter` of emitter i seen from p.
    double pdf(size_t i, const Vec3& p, const Vec3& onEmitter) const;
    // Choosing and sampling from one point many times (every path of a sampler point
    // starts there): the choice's weights, and each chosen shape's set-up (a rect's
    // spherical rectangle), once. The numbers are those of sample(p, ...) and pdf(i, p, q).
    class PointView {
    public:
        const Vec3& point() const { return point_; }

    private:
        friend class EmitterSet;
        Vec3 point_;
        std::vector<double> weights_;  // importance from point_
        std::vector<double> sums_;     // their running sums
        double total_ = 0;
        mutable std::vector<std::unique_ptr<const EmitterShape::FromPoint>> shapes_;  // on first use
        const EmitterShape::FromPoint& shape(const EmitterSet& set, size_t i) const;
    };
    // This thread's view from p, valid until its next call (measureSamplers runs a
    // point's paths on one thread in a row, as SkyLight::viewFromSensor).
    const PointView& viewFrom(const Vec3& p) const;
    EmitterSample sample(const PointView& view, double uSelect, Vec2 u) const;
    double pdf(size_t i, const PointView& view, const Vec3& onEmitter) const;
    // Luminance emitter i sends along -w (w: direction from the viewer towards it):
    // flux / (pi A), or a photometric luminaire's I(-w) / (its area projected across w).
    double emitted(size_t i, const Vec3& w) const;

private:
    // The choice's weight of every emitter from p, into weights[0, size()): the
    // Lambertian emitters' in one branch-free loop over arrays (it vectorizes: a large
    // office's dozens of luminaires are weighed at every vertex), the photometric ones
    // after it (photometricImportance).
    void weigh(const Vec3& p, double* weights) const;
    // A photometric luminaire's weight: 4 pi I(towards p) / max(d^2, reach^2).
    double photometricImportance(size_t i, const Vec3& p) const;
    // The emitter uSelect picks in proportion to `weights`, whose running sums are
    // `sums` (the total, the last, > 0).
    size_t choose(const double* weights, const double* sums, double uSelect) const;
    EmitterSample finish(size_t chosen, double select, const std::optional<EmitterPoint>& q, const Vec3& p) const;

    uint64_t id_ = 0;  // which set a thread's cached view is from
    // weigh()'s inputs, one array per field; a two-sided emitter has a zero normal and
    // oneSided 0; a photometric one is weighed by photometricImportance() (its index in
    // `photometric_`).
    struct Arrays {
        std::vector<double> cx, cy, cz, nx, ny, nz, flux, reach2, oneSided;
    } arrays_;
    std::vector<size_t> photometric_;

    std::vector<WorldEmitter> emitters_;
    EmitterSelection selection_ = EmitterSelection::PowerDistance;
};

}  // namespace luxplan
