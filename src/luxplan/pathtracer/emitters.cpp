#include <luxplan/pathtracer/emitters.h>

#include <algorithm>
#include <atomic>

namespace luxplan {
namespace {

// A vertex's weights and their running sums, on the stack for the usual few dozen
// emitters.
class WeightBuffers {
public:
    explicit WeightBuffers(size_t n) {
        if (n > kStack) heap_.resize(2 * n);
        weights = n > kStack ? heap_.data() : stack_;
        sums = weights + (n > kStack ? n : kStack);
    }
    double* weights;
    double* sums;

private:
    static constexpr size_t kStack = 64;
    double stack_[2 * kStack];
    std::vector<double> heap_;
};

// sums[k] = w[0] + ... + w[k], added in order (the last is the total).
void runningSums(const double* w, size_t n, double* sums) {
    double acc = 0;
    for (size_t k = 0; k < n; ++k) sums[k] = acc += w[k];
}

}  // namespace

EmitterSet::EmitterSet(const Scene& scene, const std::vector<Transform>& world, EmitterSelection selection)
    : selection_(selection) {
    static std::atomic<uint64_t> nextId{1};
    id_ = nextId++;
    // The maintenance factor scales what every emitter sends, not the choice among them
    // (`flux`, the importance): the same paths, each carrying that share of the light.
    const double maintenance = scene.maintenanceFactor;
    for (const Emitter& e : scene.emitters) {
        Transform t = e.entity >= 0 ? world[e.entity] : Transform();
        auto shape = e.shape->transformed(t);
        emitters_.push_back({shape, maintenance * emitterLuminance(e), e.fluxLm, shape->center(), shape->reach(), shape->normal()});
        if (auto* luminaire = dynamic_cast<const PhotometricEmitter*>(shape.get())) {
            double fileFlux = luminaire->distribution().flux();
            emitters_.back().photometric = luminaire;
            emitters_.back().intensityScale = fileFlux > 0 ? e.fluxLm / fileFlux : 0;
            emitters_.back().maintenance = maintenance;
        }
    }
    for (size_t k = 0; k < emitters_.size(); ++k) {
        const WorldEmitter& e = emitters_[k];
        if (e.photometric) photometric_.push_back(k);
        const Vec3 n = e.normal.value_or(Vec3());
        arrays_.cx.push_back(e.center.x), arrays_.cy.push_back(e.center.y), arrays_.cz.push_back(e.center.z);
        arrays_.nx.push_back(n.x), arrays_.ny.push_back(n.y), arrays_.nz.push_back(n.z);
        arrays_.flux.push_back(e.flux), arrays_.reach2.push_back(e.reach * e.reach);
        arrays_.oneSided.push_back(e.normal ? 1 : 0);
    }
}

void EmitterSet::weigh(const Vec3& p, double* weights) const {
    const size_t n = emitters_.size();
    if (selection_ == EmitterSelection::Uniform) {
        for (size_t k = 0; k < n; ++k) weights[k] = emitters_[k].flux > 0 ? 1 : 0;
        return;
    }
    // flux / max(d^2, reach^2), 0 behind a one-sided emitter's plane or without flux.
    const Arrays& a = arrays_;
    for (size_t k = 0; k < n; ++k) {
        const double dx = a.cx[k] - p.x, dy = a.cy[k] - p.y, dz = a.cz[k] - p.z;
        const double facing = (-dx) * a.nx[k] + (-dy) * a.ny[k] + (-dz) * a.nz[k];
        const double d2 = dx * dx + dy * dy + dz * dz, r2 = a.reach2[k];
        const double w = a.flux[k] / (d2 < r2 ? r2 : d2);
        const bool lit = (a.flux[k] > 0) & ((a.oneSided[k] == 0) | (facing > 0));  // & and |: no branch
        weights[k] = lit ? w : 0.0;
    }
    for (size_t k : photometric_) weights[k] = photometricImportance(k, p);
}

double EmitterSet::photometricImportance(size_t i, const Vec3& p) const {
    const WorldEmitter& e = emitters_[i];
    if (e.flux <= 0) return 0;
    Vec3 d = e.center - p;
    // A one-sided emitter lights nothing behind its plane.
    if (e.normal && dot(-d, *e.normal) <= 0) return 0;
    // 4 pi I is the flux of a uniform source as bright towards p: a point the
    // luminaire sends nothing to never chooses it (BSDF paths still see it, at full
    // MIS weight). Within its reach, where the centre's direction says little, at
    // least the mean intensity.
    double d2 = lengthSquared(d);
    double I = d2 > 0 ? e.intensityScale * e.photometric->intensity(-d / std::sqrt(d2)) : 0;
    if (d2 < e.reach * e.reach) I = std::max(I, e.flux / (4 * kPi));
    return 4 * kPi * I / std::max(d2, e.reach * e.reach);
}

double EmitterSet::selectionProbability(size_t i, const Vec3& p) const {
    WeightBuffers b(emitters_.size());
    weigh(p, b.weights);
    double total = 0;
    for (size_t k = 0; k < emitters_.size(); ++k) total += b.weights[k];
    return total > 0 ? b.weights[i] / total : 0;
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
        return e.maintenance * e.intensityScale * e.photometric->intensity(-w) / area;
    }
    return !e.normal || dot(w, *e.normal) < 0 ? e.luminance : 0.0;
}

size_t EmitterSet::choose(const double* weights, const double* sums, double uSelect) const {
    // The first emitter whose running sum passes the target; it has weight, since its
    // sum grew there. A scan adding the weights in the same order picks the same one.
    const size_t n = emitters_.size();
    const double target = uSelect * sums[n - 1];
    const size_t chosen = size_t(std::upper_bound(sums, sums + n, target) - sums);
    if (chosen < n) return chosen;
    for (size_t k = n; k-- > 0;)  // rounding left the target at the total: the last with weight
        if (weights[k] > 0) return k;
    return n;
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
    // Choose by importance: the weights, their running sums, a binary search.
    if (emitters_.empty()) return {};
    WeightBuffers b(emitters_.size());
    weigh(p, b.weights);
    runningSums(b.weights, emitters_.size(), b.sums);
    const double total = b.sums[emitters_.size() - 1];
    if (total <= 0) return {};
    const size_t chosen = choose(b.weights, b.sums, uSelect);
    return finish(chosen, b.weights[chosen] / total, emitters_[chosen].shape->sample(p, u), p);
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
        view.sums_.resize(emitters_.size());
        weigh(p, view.weights_.data());
        runningSums(view.weights_.data(), emitters_.size(), view.sums_.data());
        view.total_ = emitters_.empty() ? 0 : view.sums_.back();
        view.shapes_.clear();
        view.shapes_.resize(emitters_.size());
        cachedSet = id_;
    }
    return view;
}

EmitterSample EmitterSet::sample(const PointView& view, double uSelect, Vec2 u) const {
    if (view.total_ <= 0) return {};
    const size_t chosen = choose(view.weights_.data(), view.sums_.data(), uSelect);
    return finish(chosen, view.weights_[chosen] / view.total_, view.shape(*this, chosen).sample(u), view.point_);
}

double EmitterSet::pdf(size_t i, const PointView& view, const Vec3& onEmitter) const {
    const double select = view.total_ > 0 ? view.weights_[i] / view.total_ : 0;
    return select > 0 ? select * view.shape(*this, i).pdf(onEmitter) : 0;
}

}  // namespace luxplan
