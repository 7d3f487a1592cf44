#include <luxplan/pathtracer/emitters.h>

#include <luxplan/core/warp.h>

namespace luxplan {

EmitterSet::EmitterSet(const Scene& scene, const std::vector<Transform>& world, EmitterSelection selection)
    : selection_(selection) {
    for (const Emitter& e : scene.emitters) {
        Transform t = e.entity >= 0 ? world[e.entity] : Transform();
        WorldEmitter w;
        w.shape = e.shape;
        w.center = t.applyPoint(e.center);
        w.normal = normalize(t.applyVector(e.normal));
        w.up = normalize(t.applyVector(e.up));
        w.radius = e.radius;
        w.area = e.area();
        w.flux = e.fluxLm;
        w.luminance = e.luminance();
        if (e.shape == EmitterShape::Rect) {
            Vec3 u = cross(w.up, w.normal);  // first side, so that cross(u, up) = normal
            w.rect = {w.center - u * (e.size.x / 2) - w.up * (e.size.y / 2), u * e.size.x, w.up * e.size.y};
        }
        emitters_.push_back(w);
    }
}

double EmitterSet::importance(size_t i, const Vec3& p) const {
    const WorldEmitter& e = emitters_[i];
    if (e.flux <= 0) return 0;
    if (selection_ == EmitterSelection::Uniform) return 1;
    Vec3 d = e.center - p;
    double reach = e.shape == EmitterShape::Rect ? 0.5 * length(e.rect.edgeU + e.rect.edgeV) : e.radius;
    // A one-sided emitter lights nothing behind its plane.
    if (e.shape != EmitterShape::Sphere && dot(-d, e.normal) <= 0) return 0;
    return e.flux / std::max(lengthSquared(d), reach * reach);
}

double EmitterSet::selectionProbability(size_t i, const Vec3& p) const {
    double total = 0;
    for (size_t k = 0; k < emitters_.size(); ++k) total += importance(k, p);
    return total > 0 ? importance(i, p) / total : 0;
}

double EmitterSet::solidAnglePdf(size_t i, const Vec3& p, const Vec3& q) const {
    const WorldEmitter& e = emitters_[i];
    switch (e.shape) {
        case EmitterShape::Rect: {
            double omega = SphericalRect(e.rect, p).solidAngle();
            return omega > 0 ? 1 / omega : 0;
        }
        case EmitterShape::Disk: {
            Vec3 d = q - p;
            double dist2 = lengthSquared(d), cosE = std::abs(dot(normalize(d), e.normal));
            return cosE > 0 ? dist2 / (e.area * cosE) : 0;
        }
        case EmitterShape::Sphere: {
            double dist2 = lengthSquared(e.center - p);
            if (dist2 <= e.radius * e.radius) return 0;
            double cosMax = std::sqrt(std::max(0.0, 1 - e.radius * e.radius / dist2));
            return uniformConePdf(cosMax);
        }
    }
    return 0;
}

double EmitterSet::pdf(size_t i, const Vec3& p, const Vec3& onEmitter) const {
    double select = selectionProbability(i, p);
    return select > 0 ? select * solidAnglePdf(i, p, onEmitter) : 0;
}

double EmitterSet::emitted(size_t i, const Vec3& w, const Vec3& hitNormal) const {
    const WorldEmitter& e = emitters_[i];
    if (e.shape == EmitterShape::Sphere) return e.luminance;
    return dot(w, e.normal) < 0 ? e.luminance : 0.0;
}

EmitterSample EmitterSet::sample(const Vec3& p, double uSelect, Vec2 u) const {
    EmitterSample s;
    // Choose by importance: one pass for the weights (on the stack for the usual few
    // dozen emitters), one for the choice.
    constexpr size_t kStack = 64;
    double stackWeights[kStack];
    std::vector<double> heapWeights;
    double* weights = stackWeights;
    if (emitters_.size() > kStack) {
        heapWeights.resize(emitters_.size());
        weights = heapWeights.data();
    }
    double total = 0;
    for (size_t k = 0; k < emitters_.size(); ++k) total += weights[k] = importance(k, p);
    if (total <= 0) return s;
    double target = uSelect * total, acc = 0;
    size_t chosen = emitters_.size();
    for (size_t k = 0; k < emitters_.size(); ++k) {
        if (weights[k] <= 0) continue;
        chosen = k;  // the last emitter with weight, should rounding leave target >= total
        acc += weights[k];
        if (target < acc) break;
    }
    const WorldEmitter& e = emitters_[chosen];
    double select = weights[chosen] / total;

    Vec3 q;
    double pdfSolid = 0;
    switch (e.shape) {
        case EmitterShape::Rect: {
            SphericalRect sr(e.rect, p);
            if (sr.solidAngle() <= 0) return s;
            q = sr.sample(u);
            pdfSolid = 1 / sr.solidAngle();
            break;
        }
        case EmitterShape::Disk: {
            Vec2 d = sampleUniformDiskConcentric(u);
            Frame f = Frame::fromNormal(e.normal);
            q = e.center + (f.s * d.x + f.t * d.y) * e.radius;
            pdfSolid = solidAnglePdf(chosen, p, q);
            break;
        }
        case EmitterShape::Sphere: {
            Vec3 toCenter = e.center - p;
            double dist2 = lengthSquared(toCenter);
            if (dist2 <= e.radius * e.radius) return s;
            double dist = std::sqrt(dist2), cosMax = std::sqrt(std::max(0.0, 1 - e.radius * e.radius / dist2));
            Frame f = Frame::fromNormal(toCenter / dist);
            Vec3 w = f.toWorld(sampleUniformCone(u, cosMax));
            // Nearest intersection of p + t w with the sphere.
            double b = dot(w, toCenter), c = dist2 - e.radius * e.radius, disc = std::max(0.0, b * b - c);
            q = p + w * (b - std::sqrt(disc));
            pdfSolid = uniformConePdf(cosMax);
            break;
        }
    }
    if (!(pdfSolid > 0) || !std::isfinite(pdfSolid)) return s;
    Vec3 d = q - p;
    s.distance = length(d);
    if (s.distance <= 0) return s;
    s.wi = d / s.distance;
    Vec3 n = e.shape == EmitterShape::Sphere ? normalize(q - e.center) : e.normal;
    s.Lv = emitted(chosen, s.wi, n);
    s.pdf = select * pdfSolid;
    s.emitter = int(chosen);
    return s;
}

}  // namespace luxplan
