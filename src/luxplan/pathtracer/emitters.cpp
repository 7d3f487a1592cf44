#include <luxplan/pathtracer/emitters.h>

#include <atomic>

namespace luxplan {

EmitterSet::EmitterSet(const Scene& scene, const std::vector<Transform>& world, EmitterSelection selection)
    : selection_(selection) {
    static std::atomic<uint64_t> nextId{1};
    id_ = nextId++;
    for (const Emitter& e : scene.emitters) {
        Transform t = e.entity >= 0 ? world[e.entity] : Transform();
        auto shape = e.shape->transformed(t);
        emitters_.push_back({shape, emitterLuminance(e), e.fluxLm, shape->center(), shape->reach(), shape->normal()});
        if (auto* luminaire = dynamic_cast<const PhotometricEmitter*>(shape.get())) {
            double fileFlux = luminaire->distribution().flux();
            emitters_.back().photometric = luminaire;
            emitters_.back().intensityScale = fileFlux > 0 ? e.fluxLm / fileFlux : 0;
        }
    }
}

double EmitterSet::importance(size_t i, const Vec3& p) const {
    const WorldEmitter& e = emitters_[i];
    if (e.flux <= 0) return 0;
    if (selection_ == EmitterSelection::Uniform) return 1;
    Vec3 d = e.center - p;
    // A one-sided emitter lights nothing behind its plane.
    if (e.normal && dot(-d, *e.normal) <= 0) return 0;
    if (e.photometric) {
        // 4 pi I is the flux of a uniform source as bright towards p: a point the
        // luminaire sends nothing to never chooses it (BSDF paths still see it, at
        // full MIS weight). Within its reach, where the centre's direction says
        // little, at least the mean intensity.
        double d2 = lengthSquared(d);
        double I = d2 > 0 ? e.intensityScale * e.photometric->intensity(-d / std::sqrt(d2)) : 0;
        if (d2 < e.reach * e.reach) I = std::max(I, e.flux / (4 * kPi));
        return 4 * kPi * I / std::max(d2, e.reach * e.reach);
    }
    return e.flux / std::max(lengthSquared(d), e.reach * e.reach);
}

double EmitterSet::selectionProbability(size_t i, const Vec3& p) const {
    double total = 0;
    for (size_t k = 0; k < emitters_.size(); ++k) total += importance(k, p);
    return total > 0 ? importance(i, p) / total : 0;
}

double EmitterSet::pdf(size_t i, const Vec3& p, const Vec3& onEmitter) const {
    double select = selectionProbability(i, p);
    return select > 0 ? select * emitters_[i].shape->pdf(p, onEmitter) : 0;
}

double EmitterSet::emitted(size_t i, const Vec3& w) const {
    const WorldEmitter& e = emitters_[i];
    if (e.photometric) {
        if (e.normal && dot(w, *e.normal) >= 0) return 0;
        // The opening seen edge-on shows no area (and sends nothing).
        double area = e.photometric->projectedArea(-w);
        if (!(area > 1e-9 * e.photometric->area())) return 0;
        return e.intensityScale * e.photometric->intensity(-w) / area;
    }
    return !e.normal || dot(w, *e.normal) < 0 ? e.luminance : 0.0;
}

size_t EmitterSet::choose(const double* weights, double total, double uSelect) const {
    double target = uSelect * total, acc = 0;
    size_t chosen = emitters_.size();
    for (size_t k = 0; k < emitters_.size(); ++k) {
        if (weights[k] <= 0) continue;
        chosen = k;  // the last emitter with weight, should rounding leave target >= total
        acc += weights[k];
        if (target < acc) break;
    }
    return chosen;
}

EmitterSample EmitterSet::finish(size_t chosen, double select, const std::optional<EmitterPoint>& q, const Vec3& p) const {
    EmitterSample s;
    if (!q || !(q->pdf > 0) || !std::isfinite(q->pdf)) return s;
    Vec3 d = q->position - p;
    s.distance = length(d);
    if (s.distance <= 0) return s;
    s.wi = d / s.distance;
    s.Lv = emitted(chosen, s.wi);
    s.pdf = select * q->pdf;
    s.emitter = int(chosen);
    return s;
}

EmitterSample EmitterSet::sample(const Vec3& p, double uSelect, Vec2 u) const {
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
    if (total <= 0) return {};
    const size_t chosen = choose(weights, total, uSelect);
    return finish(chosen, weights[chosen] / total, emitters_[chosen].shape->sample(p, u), p);
}

const EmitterShape::FromPoint& EmitterSet::PointView::shape(const EmitterSet& set, size_t i) const {
    if (!shapes_[i]) shapes_[i] = set.emitters_[i].shape->from(point_);
    return *shapes_[i];
}

const EmitterSet::PointView& EmitterSet::viewFrom(const Vec3& p) const {
    thread_local uint64_t cachedSet = 0;
    thread_local PointView view;
    if (cachedSet != id_ || !(view.point_ == p)) {
        view.point_ = p;
        view.weights_.resize(emitters_.size());
        view.total_ = 0;
        for (size_t k = 0; k < emitters_.size(); ++k) view.total_ += view.weights_[k] = importance(k, p);
        view.shapes_.clear();
        view.shapes_.resize(emitters_.size());
        cachedSet = id_;
    }
    return view;
}

EmitterSample EmitterSet::sample(const PointView& view, double uSelect, Vec2 u) const {
    if (view.total_ <= 0) return {};
    const size_t chosen = choose(view.weights_.data(), view.total_, uSelect);
    return finish(chosen, view.weights_[chosen] / view.total_, view.shape(*this, chosen).sample(u), view.point_);
}

double EmitterSet::pdf(size_t i, const PointView& view, const Vec3& onEmitter) const {
    const double select = view.total_ > 0 ? view.weights_[i] / view.total_ : 0;
    return select > 0 ? select * view.shape(*this, i).pdf(onEmitter) : 0;
}

}  // namespace luxplan
