#include <luxplan/lightsamplers/glare_sources.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include <luxplan/core/format.h>
#include <luxplan/core/warp.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {

double guthIndex(double tau, double sigma) {
    const double e = (35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                     (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma;
    return std::min(16.0, std::exp(e));
}

Frame eyeFrame(const Vec3& forward) {
    const Vec3 f = normalize(forward);
    Vec3 up = Vec3(0, 0, 1) - f * f.z;
    if (length(up) < 1e-9) up = Vec3(0, 1, 0) - f * f.y;  // looking straight up or down
    up = normalize(up);
    return Frame(cross(f, up), up, f);
}

double guthIndexOf(const Vec3& forward, const Vec3& w) {
    const Frame eye = eyeFrame(forward);
    const double z = dot(w, eye.n), x = dot(w, eye.s), y = dot(w, eye.t);
    if (z <= 0) return 16;
    if (y >= 0) {
        const double sigma = degrees(std::acos(std::clamp(z / length(w), -1.0, 1.0)));
        const double tau = degrees(std::atan2(std::abs(x), y));
        return guthIndex(tau, sigma);
    }
    // Iwata, below the line of sight: r = sqrt(tan^2 phi + tan^2 teta), capped at 3.
    double r = std::min(3.0, std::sqrt((y * y + x * x) / (z * z)));
    const double fact = r > 0.6 ? 1.2 : 0.8;
    return std::min(16.0, 1 + fact * r);
}

namespace {
double glareSum(const std::vector<GlareSource>& sources) {
    double sum = 0;
    for (const GlareSource& s : sources)
        sum += s.luminance * s.luminance * s.solidAngle / (s.positionIndex * s.positionIndex);
    return sum;
}
}  // namespace

double unifiedGlareRating(double Lb, const std::vector<GlareSource>& sources) {
    const double sum = glareSum(sources);
    if (!(sum > 0)) return 0;
    return std::max(0.0, 8 * std::log10(0.25 / std::max(Lb, 1e-9) * sum));
}

double daylightGlareProbability(double Ev, const std::vector<GlareSource>& sources) {
    Ev = std::max(Ev, 0.0);
    const double sum = glareSum(sources);
    double dgp = 5.87e-5 * Ev + 0.159 + (sum > 0 && Ev > 0 ? 0.092 * std::log10(1 + sum / std::pow(Ev, 1.87)) : 0.0);
    if (Ev < 1000) {
        const double x = std::exp(0.024 * Ev - 4);
        dgp *= x / (1 + x);
    }
    return std::clamp(dgp, 0.0, 1.0);
}

DirectionGrid::DirectionGrid(int n) : n_(n), centroids_(size_t(n) * size_t(n)) {
    constexpr int kSub = 16;  // a cell's centroid by the midpoint rule on kSub x kSub
    for (int c = 0; c < cells(); ++c) {
        Vec3 sum;
        for (int j = 0; j < kSub; ++j)
            for (int i = 0; i < kSub; ++i) sum += direction(c, {(i + 0.5) / kSub, (j + 0.5) / kSub});
        centroids_[size_t(c)] = sum / double(kSub * kSub);
    }
}

Vec3 DirectionGrid::direction(int cell, Vec2 u) const {
    return equalAreaHemisphere({((cell % n_) + u.x) / n_, ((cell / n_) + u.y) / n_});
}

void PlacedGlare::sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                         PathContributions& out) const {
    if (item == 0) {
        out.add(tracer.sample(CosineSensor(eye_, forward_), samples, stats, params));
    } else if (item >= firstCell()) {
        // The sky, the ground outside and surfaces through a cell; the luminaires and
        // sun disks a ray meets first are their slots' sources.
        const Vec3 w = frame_.toWorld(grid_->direction(item - firstCell(), samples.get2D(PathSamples::Direction)));
        out.add(tracer.sample(RaySensor(Ray{eye_, w}, true), samples, stats, params));
    } else {
        sampleSlot(tracer, item, samples, stats, params, out);
    }
}

void PlacedGlare::sampleSlot(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats,
                             const PathParams& params, PathContributions& out) const {
    const int slot = (item - 1) / kQuantities, q = (item - 1) % kQuantities;
    const EmitterSet& emitters = tracer.emitters();
    Vec3 w;
    double pdf = 0, Le = 0, T = 0;
    if (slot < int(emitters.size())) {
        if (params.footprint) params.footprint->usedEmitterChoice = true;  // where the luminaires are
        const WorldEmitter& e = emitters[size_t(slot)];
        auto p = e.shape->sample(eye_, samples.get2D(PathSamples::EmitterPoint));
        if (!p || !(p->pdf > 0)) return;
        Vec3 d = p->position - eye_;
        const double dist = length(d);
        if (!(dist > 2e-4)) return;
        w = d / dist, pdf = p->pdf;
        if (dot(w, forward_) <= 0 || (metric_ == Metric::Ugr && w.z <= 0)) return;
        Le = emitters.emitted(size_t(slot), w);
        if (!(Le > 0)) return;
        T = tracer.transmittance(eye_ + w * 1e-4, w, dist - 1e-4, slot, stats, params.footprint);
    } else {
        const DaylightEnvironment* daylight = tracer.daylight();
        const int sun = slot - int(emitters.size());
        if (metric_ == Metric::Ugr || !daylight || sun >= int(daylight->sunDisks().size())) return;
        const SunDisk& disk = daylight->sunDisks()[size_t(sun)];
        const double cosMax = std::cos(kSunHalfAngle);
        w = Frame::fromNormal(disk.direction).toWorld(sampleUniformCone(samples.get2D(PathSamples::SunPoint), cosMax));
        pdf = uniformConePdf(cosMax), Le = disk.luminance;
        if (dot(w, forward_) <= 0 || !(Le > 0)) return;
        T = tracer.transmittance(eye_, w, kInf, -1, stats, params.footprint);
    }
    if (!(T > 0)) return;
    const double omega = T / pdf;  // a pane in the way dims the source, as if smaller
    switch (q) {
        case 0: out.add(omega); break;
        case 1: out.add(omega * Le); break;
        case 2: out.add(omega * Le * dot(w, forward_)); break;
        default: out.add(omega * (q == 3 ? w.x : q == 4 ? w.y : w.z)); break;
    }
}

GlareSurvey PlacedGlare::surveyOf(const std::vector<double>& m) const {
    GlareSurvey s;
    s.verticalIlluminance = m.empty() ? 0 : m[0];
    double direct = 0;
    for (int slot = 0; slot < slots_; ++slot) {
        const size_t b = 1 + size_t(slot) * kQuantities;
        if (b + kQuantities > m.size()) break;
        const double omega = m[b];
        if (!(omega > 1e-12)) continue;
        GlareSource g;
        g.solidAngle = omega;
        g.luminance = m[b + 1] / omega;
        Vec3 c(m[b + 3], m[b + 4], m[b + 5]);
        g.direction = length(c) > 0 ? normalize(c) : forward_;
        g.positionIndex = guthIndexOf(forward_, g.direction);
        g.index = slot;
        g.kind = slot < luminaires_ ? GlareSource::Kind::Luminaire : GlareSource::Kind::Sun;
        if (metric_ == Metric::Dgp && g.luminance <= threshold_) continue;
        direct += m[b + 2];
        s.sources.push_back(g);
    }
    if (grid_) addRegions(m, s.sources, direct);
    s.directIlluminance = direct;
    s.backgroundLuminance = std::max(0.0, s.verticalIlluminance - direct) / kPi;
    s.value = metric_ == Metric::Ugr ? unifiedGlareRating(s.backgroundLuminance, s.sources)
                                     : daylightGlareProbability(s.verticalIlluminance, s.sources);
    return s;
}

void PlacedGlare::addRegions(const std::vector<double>& m, std::vector<GlareSource>& sources, double& direct) const {
    const int n = grid_->cellsPerSide();
    const int first = firstCell();
    if (m.size() < size_t(first + grid_->cells())) return;
    auto bright = [&](int i, int j) { return m[size_t(first + j * n + i)] > threshold_; };
    std::vector<int> region(size_t(grid_->cells()), -1);
    std::vector<int> stack;
    int regions = 0;
    for (int start = 0; start < grid_->cells(); ++start) {
        if (region[size_t(start)] >= 0 || !bright(start % n, start / n)) continue;
        // One region: a flood fill over the eight neighbours.
        double sumL = 0, sumE = 0;
        Vec3 sumDir;
        int count = 0;
        region[size_t(start)] = regions;
        stack.assign(1, start);
        while (!stack.empty()) {
            const int c = stack.back();
            stack.pop_back();
            const double L = m[size_t(first + c)];
            sumL += L, sumE += L * grid_->centroid(c).z, sumDir += grid_->centroid(c), ++count;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int i = c % n + di, j = c / n + dj;
                    if (i < 0 || j < 0 || i >= n || j >= n) continue;
                    const int k = j * n + i;
                    if (region[size_t(k)] >= 0 || !bright(i, j)) continue;
                    region[size_t(k)] = regions;
                    stack.push_back(k);
                }
        }
        GlareSource g;
        g.kind = GlareSource::Kind::Region;
        g.index = regions++;
        g.solidAngle = count * grid_->cellSolidAngle();
        g.luminance = sumL / count;  // the cells have equal solid angles
        g.direction = normalize(frame_.toWorld(sumDir));
        g.positionIndex = guthIndexOf(forward_, g.direction);
        direct += sumE * grid_->cellSolidAngle();
        sources.push_back(g);
    }
}

std::vector<char> PlacedGlare::stillNeeded(const ItemEstimates& e, double z, double, double) const {
    std::vector<char> keep(size_t(e.items()), 1);
    for (int k = firstCell(); k < e.items(); ++k) {
        const Estimate x = e.of(k);
        keep[size_t(k)] = x.value + z * x.standardError >= threshold_;
    }
    return keep;
}

Estimate PlacedGlare::combine(const ItemEstimates& e) const {
    auto meansOf = [&](int heldOut) {
        std::vector<double> m(size_t(e.items()));
        for (int i = 0; i < e.items(); ++i) m[size_t(i)] = (heldOut < 0 ? e.of(i) : e.ofAllBut(i, heldOut)).value;
        return m;
    };
    Estimate r;
    r.value = surveyOf(meansOf(-1)).value;
    std::vector<double> folds;
    for (int g = 0; g < ItemEstimates::kFolds; ++g)
        if (e.pathsInFold(0, g) > 0) folds.push_back(surveyOf(meansOf(g)).value);
    if (folds.size() >= 2) {
        double mean = 0, var = 0;
        for (double v : folds) mean += v / double(folds.size());
        for (double v : folds) var += (v - mean) * (v - mean);
        r.standardError = std::sqrt(var * double(folds.size() - 1) / double(folds.size()));
        r.degreesOfFreedom = int(folds.size()) - 1;
    }
    return r;
}

SamplerDrawing PlacedGlare::drawing() const {
    SamplerDrawing d;
    d.outline = {eye_, eye_ + forward_ * 0.8};
    d.lineWidth = 1.5;
    d.dots = {eye_};
    d.dotRadius = 4;
    d.labelAt = eye_;
    return d;
}

void GlareSamplerType::addDetails(const SamplerResult& result, nlohmann::ordered_json& out) const {
    if (!result.glare) return;
    const GlareSurvey& g = *result.glare;
    nlohmann::ordered_json sources = nlohmann::ordered_json::array();
    for (const GlareSource& s : g.sources)
        sources.push_back({{"kind", glareSourceKindName(s.kind)},
                           {s.kind == GlareSource::Kind::Region ? "region" : "slot", s.index},
                           {"direction", {s.direction.x, s.direction.y, s.direction.z}},
                           {"luminance", s.luminance},
                           {"solid_angle", s.solidAngle},
                           {"position_index", s.positionIndex}});
    out["glare"] = {{"vertical_illuminance", g.verticalIlluminance},
                    {"direct_illuminance", g.directIlluminance},
                    {"background_luminance", g.backgroundLuminance},
                    {"sources", sources}};
}

std::string GlareSamplerType::detailsText(const SamplerResult& result) const {
    if (!result.glare) return "";
    const GlareSurvey& g = *result.glare;
    std::string d = surveyHead(result.value, g) + ", " + std::to_string(g.sources.size()) +
                    (g.sources.size() == 1 ? " source" : " sources");
    for (const GlareSource& s : g.sources)
        d += std::string("; ") + glareSourceKindName(s.kind) + " [" + fixedDigits(s.direction.x, 2) + " " +
             fixedDigits(s.direction.y, 2) + " " + fixedDigits(s.direction.z, 2) + "] L " + fixedDigits(s.luminance, 0) +
             " cd/m2, omega " + fixedDigits(s.solidAngle * 1e3, 3) + " msr, P " + fixedDigits(s.positionIndex, 2);
    return d;
}

}  // namespace luxplan
