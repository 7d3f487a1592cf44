#include <luxplan/optimizer/light_surrogate.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include <luxplan/constraints/penalty.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/scene/region.h>

namespace luxplan {
namespace {

// Whether the sampler moves with furniture: its entity or one above it is movable.
bool movesWithFurniture(const Scene& scene, int entity) {
    for (int e = entity; e >= 0; e = scene.entities[size_t(e)].parent)
        if (scene.entities[size_t(e)].movable()) return true;
    return false;
}

// The topmost movable entity at or above `entity`: the one whose placement carries it
// farthest (a workstation, not the monitor on it); -1 if none moves.
int topmostMovable(const Scene& scene, int entity) {
    int top = -1;
    for (int e = entity; e >= 0; e = scene.entities[size_t(e)].parent)
        if (scene.entities[size_t(e)].movable()) top = e;
    return top;
}

// Pose tables' nodes are at most this far apart (m), and a turn that may take any
// heading in an interval is traced at this many of them (kHeadingsOfInterval) or every
// kHeadingStepDeg round a full turn.
constexpr double kPoseCell = 0.5;
constexpr int kHeadingsOfInterval = 5;
constexpr double kHeadingStepDeg = 45;

// The headings a table traces: its regions' distinct rotations, and for a rotation
// interval, kHeadingsOfInterval across it (every kHeadingStepDeg round a full turn).
std::vector<double> tableHeadings(const Entity& e) {
    std::vector<double> out;
    auto add = [&](double deg) {
        for (double h : out)
            if (sameRotation(h, deg)) return;
        out.push_back(deg);
    };
    for (const Region& r : e.regions) {
        if (!r.continuousRotation) {
            for (double deg : distinctRotations(r)) add(deg);
        } else if (r.rotationMaxDeg - r.rotationMinDeg >= 360 - kRotationToleranceDeg) {
            for (double deg = 0; deg < 360 - 1e-9; deg += kHeadingStepDeg) add(r.rotationMinDeg + deg);
        } else {
            for (int k = 0; k < kHeadingsOfInterval; ++k)
                add(r.rotationMinDeg + (r.rotationMaxDeg - r.rotationMinDeg) * k / (kHeadingsOfInterval - 1));
        }
    }
    return out;
}

// Signed difference b - a of two headings (degrees), in (-180, 180].
double headingDifference(double a, double b) {
    double d = std::fmod(b - a, 360.0);
    if (d > 180) d -= 360;
    if (d <= -180) d += 360;
    return d;
}

// What decides a table's values, written out: the entity's regions, its subtree (each
// piece's triangles, bounds, materials and, below the entity, place in its parent) and
// the samplers (where they sit and what they are). Two pieces with the same text are
// built alike.
std::string tableSignature(const Scene& scene, int entity, const std::vector<int>& samplers) {
    std::ostringstream out;
    out << std::setprecision(9);
    for (const Region& r : scene.entities[size_t(entity)].regions) {
        out << "R" << r.lo.x << ',' << r.lo.y << ',' << r.hi.x << ',' << r.hi.y << ',' << r.continuousRotation << ','
            << r.rotationMinDeg << ',' << r.rotationMaxDeg;
        for (double d : r.rotationsDeg) out << ',' << d;
    }
    std::vector<int> order{entity};
    for (size_t i = 0; i < order.size(); ++i) {
        const Entity& e = scene.entities[size_t(order[i])];
        out << "|E";
        if (i > 0) out << e.position.x << ',' << e.position.y << ',' << e.position.z << ',' << e.rotationDeg << ',';
        out << e.mesh.triangleCount();
        if (!e.mesh.empty()) {
            const Bounds3 b = e.mesh.bounds();
            out << ',' << b.lo.x << ',' << b.lo.y << ',' << b.lo.z << ',' << b.hi.x << ',' << b.hi.y << ',' << b.hi.z;
        }
        for (const PartInfo& part : e.parts) out << ",m" << part.material;
        out << ",e" << e.emitters.size();
        for (int c : e.children) order.push_back(c);
    }
    for (int k : samplers) {
        const LightSamplerSpec& s = scene.samplers[size_t(k)];
        const auto at = std::find(order.begin(), order.end(), s.entity);
        out << "|S" << (at - order.begin()) << ':' << s.type->name() << ':' << s.type->describe();
    }
    return out.str();
}

// correction() scales a sampler by at most this factor either way: a layout's look at the
// light corrects the surrogate, it does not replace it.
constexpr double kMaxCorrection = 2;

// Fields closer than this in height are one field.
constexpr double kSameHeight = 0.01;
// A plan aims this share of its band's width inside each finite end (of the bound
// itself where the band is open): what the surrogate cannot see (the furniture's own
// shadows and reflections, the cells' interpolation and noise) moves the traced light a
// few percent, and a plan on the band's edge is outside as often as in.
constexpr double kPlanMargin = 0.1;

// A term's penalty against its band narrowed by kPlanMargin (Eq. 3 with the term's
// tolerance). A lower bound at or below 0 stays: the quantities are never negative, so
// such a bound holds whatever the surrogate misses.
double plannedPenalty(const LightingTerm& t) {
    const bool lo = std::isfinite(t.targetMin), hi = std::isfinite(t.targetMax);
    const double width = lo && hi ? t.targetMax - t.targetMin : lo ? std::abs(t.targetMin) : hi ? std::abs(t.targetMax) : 0;
    const double m = kPlanMargin * width;
    return penalty(t.value, lo && t.targetMin > 0 ? t.targetMin + m : t.targetMin, hi ? t.targetMax - m : t.targetMax,
                   t.tolerance, kLightingStiffness);
}

// Bilinear interpolation on an nx x ny grid of nodes at the grid position (u, v) (in
// nodes from the first), clamped at the edges; value(i, j) reads node (i, j).
template <typename Value>
double bilinear(double u, double v, int nx, int ny, const Value& value) {
    u = std::clamp(u, 0.0, double(nx - 1)), v = std::clamp(v, 0.0, double(ny - 1));
    const int i = std::min(int(u), std::max(0, nx - 2)), j = std::min(int(v), std::max(0, ny - 2));
    const int i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, ny - 1);
    const double fu = u - i, fv = v - j;
    return (1 - fv) * ((1 - fu) * value(i, j) + fu * value(i1, j)) + fv * ((1 - fu) * value(i, j1) + fu * value(i1, j1));
}

}  // namespace

double LightSurrogate::Field::at(Vec2 p, double cell) const {
    // Cell centres at origin + (i + 1/2) cell: the position in cells from the first centre.
    return bilinear((p.x - origin.x) / cell - 0.5, (p.y - origin.y) / cell - 0.5, nx, ny,
                    [&](int a, int b) { return lux[size_t(b) * size_t(nx) + size_t(a)]; });
}

LightSurrogate::LightSurrogate(const Scene& scene, double cellMetres)
    : scene_(&scene), cell_(cellMetres), fieldOf_(scene.samplers.size(), -1),
      tableOf_(scene.samplers.size(), {-1, -1}) {
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
        Vec3 normal;
        const std::vector<Vec3> probes = s.type->place(world[size_t(s.entity)])->coverageProbes(normal);
        // Upward planes only (furniture turns about z); the others go to the tables.
        if (!facing || facing->z < 0.999 || probes.empty()) continue;
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
    addPoseTables();
}

void LightSurrogate::addPoseTables() {
    const Scene& scene = *scene_;
    // The samplers with furniture that the fields do not stand in for, by the entity whose
    // placement keys their table. A glare survey (ugr, dgp) traces every source at every
    // pose, which costs more than a plan saves; a goal on point statistics needs points.
    std::vector<std::vector<int>> byEntity(scene.entities.size());
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        if (fieldOf_[k] >= 0 || s.entity < 0 || s.annual || !s.statistics.empty() || s.type->surveysSources()) continue;
        const int top = topmostMovable(scene, s.entity);
        if (top < 0) continue;
        byEntity[size_t(top)].push_back(int(k));
        for (int e = s.entity; e != top; e = scene.entities[size_t(e)].parent)
            if (scene.entities[size_t(e)].movable() && std::find(held_.begin(), held_.end(), e) == held_.end()) held_.push_back(e);
    }
    std::vector<std::string> signatures;
    for (size_t e = 0; e < byEntity.size(); ++e) {
        if (byEntity[e].empty()) continue;
        const Entity& entity = scene.entities[e];
        PoseTable t;
        t.entity = int(e);
        t.samplers = byEntity[e];
        Vec2 lo(kInf, kInf), hi(-kInf, -kInf);
        for (const Region& r : entity.regions) {
            lo = {std::min(lo.x, r.lo.x), std::min(lo.y, r.lo.y)};
            hi = {std::max(hi.x, r.hi.x), std::max(hi.y, r.hi.y)};
        }
        const Vec2 extent = hi - lo;
        t.nx = extent.x > 0 ? int(std::ceil(extent.x / kPoseCell - 1e-9)) + 1 : 1;
        t.ny = extent.y > 0 ? int(std::ceil(extent.y / kPoseCell - 1e-9)) + 1 : 1;
        t.lo = lo;
        t.step = {t.nx > 1 ? extent.x / (t.nx - 1) : 0.0, t.ny > 1 ? extent.y / (t.ny - 1) : 0.0};
        t.headingsDeg = tableHeadings(entity);
        std::string signature = tableSignature(scene, int(e), t.samplers);
        const auto same = std::find(signatures.begin(), signatures.end(), signature);
        if (same != signatures.end()) t.sharesWith = int(same - signatures.begin());
        signatures.push_back(std::move(signature));
        for (size_t slot = 0; slot < t.samplers.size(); ++slot)
            tableOf_[size_t(t.samplers[slot])] = {int(tables_.size()), int(slot)};
        tables_.push_back(std::move(t));
    }
}

std::vector<Placement> LightSurrogate::PoseTable::placements(const Scene& scene) const {
    const Entity& e = scene.entities[size_t(entity)];
    std::vector<Placement> out;
    for (double heading : headingsDeg)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                Placement p;
                p.position = {lo.x + i * step.x, lo.y + j * step.y, e.position.z};
                p.rotationDeg = heading;
                p.region = std::max(0, findRegion(e.regions, {p.position.x, p.position.y}, heading));
                out.push_back(p);
            }
    return out;
}

double LightSurrogate::PoseTable::at(int slot, const Placement& p) const {
    size_t h = 0;
    for (size_t k = 1; k < headingsDeg.size(); ++k)
        if (std::abs(headingDifference(headingsDeg[k], p.rotationDeg)) < std::abs(headingDifference(headingsDeg[h], p.rotationDeg)))
            h = k;
    const size_t n = samplers.size();
    return bilinear(step.x > 0 ? (p.position.x - lo.x) / step.x : 0.0, step.y > 0 ? (p.position.y - lo.y) / step.y : 0.0, nx,
                    ny, [&](int a, int b) { return values[((h * size_t(ny) + size_t(b)) * size_t(nx) + size_t(a)) * n + size_t(slot)]; });
}

std::vector<LightSurrogate::PoseQuery> LightSurrogate::poseQueries() const {
    std::vector<PoseQuery> out;
    for (const PoseTable& t : tables_)
        if (t.sharesWith < 0) out.push_back({t.entity, t.placements(*scene_), t.samplers});
    return out;
}

void LightSurrogate::setPoseValues(const std::vector<std::vector<std::vector<double>>>& values) {
    if (values.empty()) {  // the evaluator cannot tell: the tables' samplers count as met
        tables_.clear();
        held_.clear();
        for (auto& slot : tableOf_) slot = {-1, -1};
        return;
    }
    size_t q = 0;
    for (PoseTable& t : tables_) {
        if (t.sharesWith >= 0) {
            t.values = tables_[size_t(t.sharesWith)].values;
        } else {
            if (q >= values.size() || values[q].size() != size_t(t.nx) * size_t(t.ny) * t.headingsDeg.size())
                throw std::invalid_argument("LightSurrogate::setPoseValues: one list per query, one entry per placement");
            t.values.clear();
            for (const std::vector<double>& pose : values[q]) {
                if (pose.size() != t.samplers.size())
                    throw std::invalid_argument("LightSurrogate::setPoseValues: one value per sampler of the query");
                t.values.insert(t.values.end(), pose.begin(), pose.end());
            }
            ++q;
        }
        t.traced = true;
    }
    if (q != values.size()) throw std::invalid_argument("LightSurrogate::setPoseValues: one list per query");
}

double LightSurrogate::tableValue(int sampler, const Layout& layout, double scale) const {
    const auto [t, slot] = tableOf_[size_t(sampler)];
    const PoseTable& table = tables_[size_t(t)];
    return scale * table.at(slot, layout.placements[size_t(table.entity)]);
}

LightSurrogate::Correction LightSurrogate::correction(const Layout& layout, const std::vector<Transform>& world,
                                                      const std::vector<SamplerResult>& traced) const {
    if (traced.size() != scene_->samplers.size())
        throw std::invalid_argument("LightSurrogate::correction: one result per sampler");
    Correction scale(traced.size(), 1.0);
    for (size_t k = 0; k < traced.size(); ++k) {
        const bool table = tableOf_[k][0] >= 0 && tables_[size_t(tableOf_[k][0])].traced;
        if (fieldOf_[k] < 0 && !table) continue;
        const double v = value(int(k), layout, world), t = traced[k].value;
        if (v > 0 && std::isfinite(t) && t >= 0) scale[k] = std::clamp(t / v, 1 / kMaxCorrection, kMaxCorrection);
    }
    return scale;
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

std::vector<double> LightSurrogate::pointValues(int sampler, const std::vector<Transform>& world, double scale) const {
    const LightSamplerSpec& s = scene_->samplers[size_t(sampler)];
    const Field& f = fields_[size_t(fieldOf_[size_t(sampler)])];
    Vec3 normal;
    std::vector<Vec3> probes = s.type->place(world[size_t(s.entity)])->coverageProbes(normal);
    std::vector<double> values(probes.size());
    for (size_t i = 0; i < probes.size(); ++i) values[i] = scale * f.at({probes[i].x, probes[i].y}, cell_);
    return values;
}

namespace {
double scaleOf(const LightSurrogate::Correction& correction, int sampler) {
    return correction.empty() ? 1.0 : correction.at(size_t(sampler));
}
}  // namespace

double LightSurrogate::value(int sampler, const Layout& layout, const std::vector<Transform>& world,
                             const Correction& correction) const {
    if (!ready_) throw std::logic_error("LightSurrogate::value: no illuminance yet");
    const auto [t, slot] = tableOf_.at(size_t(sampler));
    if (t >= 0 && tables_[size_t(t)].traced) return tableValue(sampler, layout, scaleOf(correction, sampler));
    if (fieldOf_.at(size_t(sampler)) < 0) throw std::logic_error("LightSurrogate::value: not a stood-in sampler");
    const std::vector<double> v = pointValues(sampler, world, scaleOf(correction, sampler));
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
}

double LightSurrogate::lighting(const Layout& layout, const std::vector<Transform>& world,
                                const Correction& correction) const {
    if (!ready_) throw std::logic_error("LightSurrogate::lighting: no illuminance yet");
    if (!(termWeights_ > 0)) return 0.0;
    double sum = 0;
    for (int k : standIns_) {
        SamplerResult r;
        r.points = pointValues(k, world, scaleOf(correction, k));
        r.pointErrors.assign(r.points.size(), 0.0);
        for (double x : r.points) r.value += x;
        r.value /= double(std::max<size_t>(1, r.points.size()));
        for (const LightingTerm& t : lightingTerms(scene_->samplers[size_t(k)], r)) sum += t.weight * plannedPenalty(t);
    }
    for (const PoseTable& table : tables_) {
        if (!table.traced) continue;
        for (size_t slot = 0; slot < table.samplers.size(); ++slot) {
            const LightSamplerSpec& s = scene_->samplers[size_t(table.samplers[slot])];
            LightingTerm t;
            t.value = tableValue(table.samplers[slot], layout, scaleOf(correction, table.samplers[slot]));
            t.targetMin = s.targetMin, t.targetMax = s.targetMax, t.tolerance = s.tolerance;
            sum += s.weight * plannedPenalty(t);  // its mean term only: a table holds no points
        }
    }
    return sum / termWeights_;
}

}  // namespace luxplan
