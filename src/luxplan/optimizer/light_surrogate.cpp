#include <luxplan/optimizer/light_surrogate.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <luxplan/constraints/penalty.h>
#include <luxplan/lightsamplers/sampler_type.h>

namespace luxplan {
namespace {

// Whether the sampler moves with furniture: its entity or one above it is movable.
bool movesWithFurniture(const Scene& scene, int entity) {
    for (int e = entity; e >= 0; e = scene.entities[size_t(e)].parent)
        if (scene.entities[size_t(e)].movable()) return true;
    return false;
}

// Fields closer than this in height are one field.
constexpr double kSameHeight = 0.01;
// A plan aims this share of its band's width inside each finite end (of the bound
// itself where the band is open): what the surrogate cannot see (the furniture's own
// shadows and reflections, the cells' interpolation and noise) moves the traced light a
// few percent, and a plan on the band's edge is outside as often as in.
constexpr double kPlanMargin = 0.1;

// A term's penalty against its band narrowed by kPlanMargin (Eq. 3 with the term's tolerance).
double plannedPenalty(const LightingTerm& t) {
    const bool lo = std::isfinite(t.targetMin), hi = std::isfinite(t.targetMax);
    const double width = lo && hi ? t.targetMax - t.targetMin : lo ? std::abs(t.targetMin) : hi ? std::abs(t.targetMax) : 0;
    const double m = kPlanMargin * width;
    return penalty(t.value, lo ? t.targetMin + m : t.targetMin, hi ? t.targetMax - m : t.targetMax, t.tolerance, kLightingStiffness);
}

}  // namespace

double LightSurrogate::Field::at(Vec2 p, double cell) const {
    // Cell centres at origin + (i + 1/2) cell: the position in cells from the first centre.
    const double u = std::clamp((p.x - origin.x) / cell - 0.5, 0.0, double(nx - 1));
    const double v = std::clamp((p.y - origin.y) / cell - 0.5, 0.0, double(ny - 1));
    const int i = std::min(int(u), std::max(0, nx - 2)), j = std::min(int(v), std::max(0, ny - 2));
    const int i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, ny - 1);
    const double fu = u - i, fv = v - j;
    auto value = [&](int a, int b) { return lux[size_t(b) * size_t(nx) + size_t(a)]; };
    return (1 - fv) * ((1 - fu) * value(i, j) + fu * value(i1, j)) + fv * ((1 - fu) * value(i, j1) + fu * value(i1, j1));
}

LightSurrogate::LightSurrogate(const Scene& scene, double cellMetres)
    : scene_(&scene), cell_(cellMetres), fieldOf_(scene.samplers.size(), -1) {
    if (!(cellMetres > 0)) throw std::invalid_argument("LightSurrogate: the cells' size must be above 0");
    for (const LightSamplerSpec& s : scene.samplers) termWeights_ += s.weight * double(1 + s.statistics.size() + (s.annual ? 1 : 0));
    const RoomShell* room = scene.room();
    if (!room) return;
    const Vec3 size = room->box.size();
    const std::vector<Transform> world = worldTransforms(scene, initialLayout(scene));
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        if (s.entity < 0 || s.annual || !s.type->hasPointStatistics() || !movesWithFurniture(scene, s.entity)) continue;
        const std::optional<Vec3> facing = s.type->facing(world[size_t(s.entity)]);
        if (!facing || facing->z < 0.999) continue;  // upward planes only: furniture turns about z
        Vec3 normal;
        const std::vector<Vec3> probes = s.type->place(world[size_t(s.entity)])->coverageProbes(normal);
        if (probes.empty()) continue;
        const double height = probes.front().z;
        int f = 0;
        while (f < int(fields_.size()) && std::abs(fields_[size_t(f)].height - height) > kSameHeight) ++f;
        if (f == int(fields_.size())) {
            Field field;
            field.height = height;
            field.nx = std::max(1, int(std::ceil(size.x / cell_ - 1e-9)));
            field.ny = std::max(1, int(std::ceil(size.y / cell_ - 1e-9)));
            field.origin = {room->box.lo.x - (field.nx * cell_ - size.x) / 2, room->box.lo.y - (field.ny * cell_ - size.y) / 2};
            fields_.push_back(field);
        }
        fieldOf_[k] = f;
        standIns_.push_back(int(k));
    }
}

std::vector<Vec3> LightSurrogate::points() const {
    std::vector<Vec3> out;
    for (const Field& f : fields_)
        for (int j = 0; j < f.ny; ++j)
            for (int i = 0; i < f.nx; ++i) out.push_back({f.origin.x + (i + 0.5) * cell_, f.origin.y + (j + 0.5) * cell_, f.height});
    return out;
}

void LightSurrogate::setIlluminance(const std::vector<double>& values) {
    size_t n = 0;
    for (const Field& f : fields_) n += size_t(f.nx) * size_t(f.ny);
    if (values.size() != n) throw std::invalid_argument("LightSurrogate::setIlluminance: one value per point");
    auto v = values.begin();
    for (Field& f : fields_) {
        f.lux.assign(v, v + ptrdiff_t(f.nx) * f.ny);
        v += ptrdiff_t(f.nx) * f.ny;
    }
    ready_ = true;
}

std::vector<double> LightSurrogate::pointValues(int sampler, const std::vector<Transform>& world) const {
    const LightSamplerSpec& s = scene_->samplers[size_t(sampler)];
    const Field& f = fields_[size_t(fieldOf_[size_t(sampler)])];
    Vec3 normal;
    std::vector<Vec3> probes = s.type->place(world[size_t(s.entity)])->coverageProbes(normal);
    std::vector<double> values(probes.size());
    for (size_t i = 0; i < probes.size(); ++i) values[i] = f.at({probes[i].x, probes[i].y}, cell_);
    return values;
}

double LightSurrogate::value(int sampler, const std::vector<Transform>& world) const {
    if (!ready_ || fieldOf_.at(size_t(sampler)) < 0) throw std::logic_error("LightSurrogate::value: not a stood-in sampler, or no illuminance yet");
    const std::vector<double> v = pointValues(sampler, world);
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
}

double LightSurrogate::lighting(const std::vector<Transform>& world) const {
    if (!ready_) throw std::logic_error("LightSurrogate::lighting: no illuminance yet");
    if (!(termWeights_ > 0)) return 0.0;
    double sum = 0;
    for (int k : standIns_) {
        SamplerResult r;
        r.points = pointValues(k, world);
        r.pointErrors.assign(r.points.size(), 0.0);
        for (double x : r.points) r.value += x;
        r.value /= double(std::max<size_t>(1, r.points.size()));
        for (const LightingTerm& t : lightingTerms(scene_->samplers[size_t(k)], r)) sum += t.weight * plannedPenalty(t);
    }
    return sum / termWeights_;
}

}  // namespace luxplan
