// Directional sampler: the mean luminance (cd/m2) seen from an eye through each
// cell of a strata x strata grid over a pyramidal frustum; its value is the
// brightest cell's (glare on a screen, a presenter seen by the audience).
//
// A cell's mean is over its area on the image plane at unit distance, as a pinhole
// camera's pixel averages: response 1 / (A_cell cos^3) in every cell. A stratum's
// primary rays are uniform in its cell, with that density, so light sampling at the
// eye works: a sun, a window's sky or a lamp in view is sampled directly and
// combined with the primary ray by MIS, and each light sample counts in the cell its
// direction falls in. Every stratum's estimate is then the mean over all the
// sampler's paths (sharesPaths): a path adds its primary ray's value, times the
// number of strata, to its own stratum (so that those paths keep their weight) and
// each light sample's to the stratum it falls in. The MIS weights compare a light's
// density with one stratum's (not the whole frustum's), which keeps primary rays in
// charge of what they see well (a window's sky) and light sampling of what they
// miss (the sun, a small lamp); any such split is unbiased.
//
// The max over noisy strata would read high, the more so the fewer the paths. So
// the value is cross-fitted: for each fold of paths (ItemEstimates), the brightest
// stratum is chosen with the other folds and measured with that fold alone, and the
// value is the mean over the folds. Each fold's value is then that of a real stratum,
// unbiased for it: the estimate can only fall short of the true max, by what a wrong
// choice among near-equal strata costs (measured in docs/light-transport.md), and
// does not grow as paths shrink. Its standard error is the spread of the fold
// values. That misses part of how the choice varies: the folds choose from data they
// mostly share, so where strata are near-equal they tend to choose alike, and the fold
// values move together from run to run. The error reported (reportedError) is
// therefore a parametric bootstrap of the whole cross-fitted estimate.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

#include <luxplan/core/rng.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {
namespace {

struct Frustum {
    Vec3 eye, forward, right, up;
    double tanHalfFov = 0;
    int strata = 0;

    double planeArea() const { return 4 * tanHalfFov * tanHalfFov; }
    // The stratum whose cell the unit direction w passes through, or -1 outside.
    int cellOf(const Vec3& w) const {
        double z = dot(w, forward);
        if (z <= 0) return -1;
        double a = dot(w, right) / z / tanHalfFov, b = dot(w, up) / z / tanHalfFov;
        if (!(std::abs(a) <= 1 && std::abs(b) <= 1)) return -1;
        int i = std::clamp(int((a + 1) / 2 * strata), 0, strata - 1);
        int j = std::clamp(int((b + 1) / 2 * strata), 0, strata - 1);
        return j * strata + i;
    }
    // A stratum's density per unit solid angle at the unit direction w, 1 / (A_cell
    // cos^3 theta): its primary rays' pdf and the cells' response; 0 outside.
    double density(const Vec3& w) const {
        if (cellOf(w) < 0) return 0;
        double c = dot(w, forward);
        return double(strata) * strata / (planeArea() * c * c * c);
    }
};

// The frustum as a sensor whose primary rays fall in one stratum's cell.
class FrustumSensor final : public Sensor {
public:
    FrustumSensor(const Frustum& f, int stratum) : f_(f), i_(stratum % f.strata), j_(stratum / f.strata) {}
    Vec3 position() const override { return f_.eye; }
    bool isDelta() const override { return false; }
    double response(const Vec3& wi) const override { return f_.density(wi); }
    double pdf(const Vec3& wi) const override { return f_.density(wi); }
    bool maySee(const Vec3& axis, double cosHalfAngle) const override {
        return pyramidMaySee(f_.forward, f_.right, f_.up, f_.tanHalfFov, axis, cosHalfAngle);
    }
    SensorSample sample(Vec2 u) const override {
        double a = (-1 + 2 * (i_ + u.x) / f_.strata) * f_.tanHalfFov;
        double b = (-1 + 2 * (j_ + u.y) / f_.strata) * f_.tanHalfFov;
        Vec3 d = normalize(f_.forward + f_.right * a + f_.up * b);
        return {d, 1, f_.density(d), false};  // response / pdf = 1
    }

private:
    const Frustum& f_;
    int i_, j_;
};

// A path adds to its own stratum and to the strata of its eye's light samples.
static_assert(PathContributions::kCapacity >= 1 + SensorLight::kCapacity);

// Standard normal numbers for the bootstrap from one 32-bit draw each: the quantiles
// at the midpoints of 4096 equal steps of probability (their variance 0.999; the
// bootstrap's error of 5% is far larger), found by bisection on erfc once.
constexpr int kNormalBits = 12, kNormals = 1 << kNormalBits;
const std::array<double, kNormals>& normalQuantiles() {
    static const std::array<double, kNormals> table = [] {
        std::array<double, kNormals> t{};
        for (int k = 0; k < kNormals; ++k) {
            const double p = (k + 0.5) / kNormals;  // Phi(x) = erfc(-x / sqrt 2) / 2
            double lo = -10, hi = 10;
            for (int step = 0; step < 60; ++step) {
                const double mid = 0.5 * (lo + hi);
                (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
            }
            t[size_t(k)] = 0.5 * (lo + hi);
        }
        return t;
    }();
    return table;
}

class PlacedDirectional final : public PlacedSampler {
    static constexpr int kBootstrapDraws = 200;  // the error's own error about 5%
    static constexpr uint64_t kBootstrapTag = 0x626f6f74ULL;  // "boot"
    std::vector<std::pair<size_t, double>> neighbours_;  // (stratum, weight), by stratum
    std::vector<size_t> neighbourStart_;                 // stratum k's: [start[k], start[k + 1])
    std::vector<double> neighbourWeight_;

public:
    Frustum frustum;

    int items() const override { return frustum.strata * frustum.strata; }
    bool sharesPaths() const override { return true; }
    bool independentFolds() const override { return true; }  // the cross-fitted choice

    // The strata are row-major, right fastest, bottom row first.
    void sample(const PathTracer& tracer, int item, PathSamples& samples, RayStats& stats, const PathParams& params,
                PathContributions& out) const override {
        SensorLight light;
        out.add(item, items() * tracer.sample(FrustumSensor(frustum, item), samples, stats, params, nullptr, &light));
        for (int k = 0; k < light.count; ++k) {
            int cell = frustum.cellOf(light.wi[k]);
            if (cell >= 0) out.add(cell, light.value[k]);
        }
    }

    // The stratum to measure, chosen from other paths' means and their standard
    // errors: the best of the means shrunk towards their neighbours' (empirical
    // Bayes). Each mean m_i, of variance s_i^2, is blended with the mean of its
    // eight neighbours, n_i (sides weigh 2, corners 1), as (t^2 m_i + s_i^2 n_i) /
    // (t^2 + s_i^2), where t^2 is how much strata truly differ from their
    // neighbours, estimated over the frustum. Near-equal noisy strata of a smooth
    // field (a lit wall) are judged by their neighbourhood, a precise one (a window's
    // sky, the sun) by itself, and with many paths the choice is the plain max.
    // Whatever the rule, the chosen stratum is measured with paths it did not see.
    size_t brightest(const std::vector<double>& mean, const std::vector<double>& error) const {
        thread_local std::vector<double> score;
        shrunk(mean, error, score);
        size_t best = 0;
        double bestScore = -kInf;
        for (size_t k = 0; k < score.size(); ++k)
            if (score[k] > bestScore) bestScore = score[k], best = k;
        return best;
    }
    // The means shrunk towards their neighbours', as brightest() weighs them, into `score`.
    void shrunk(const std::vector<double>& mean, const std::vector<double>& error, std::vector<double>& score) const {
        const size_t n = mean.size();
        thread_local std::vector<double> nbr, nbrVar;
        nbr.resize(n), nbrVar.resize(n), score.resize(n);
        double spread = 0;
        for (size_t k = 0; k < n; ++k) {
            double sum = 0, var = 0;
            for (size_t q = neighbourStart_[k]; q < neighbourStart_[k + 1]; ++q) {
                const auto [index, w] = neighbours_[q];
                sum += w * mean[index], var += w * w * error[index] * error[index];
            }
            const double weight = neighbourWeight_[k];
            nbr[k] = sum / weight, nbrVar[k] = var / (weight * weight);
            double d = mean[k] - nbr[k];
            spread += d * d - error[k] * error[k] - nbrVar[k];
        }
        const double t2 = std::max(0.0, spread / double(n));
        for (size_t k = 0; k < n; ++k) {
            double s2 = error[k] * error[k];
            score[k] = (t2 + s2) > 0 ? (t2 * mean[k] + s2 * nbr[k]) / (t2 + s2) : mean[k];
        }
    }
    // Each stratum's eight neighbours (fewer at the edges): sides weigh 2, corners 1.
    void findNeighbours() {
        const int s = frustum.strata;
        neighbours_.clear(), neighbourStart_.assign(1, 0), neighbourWeight_.clear();
        for (int j = 0; j < s; ++j)
            for (int i = 0; i < s; ++i) {
                double weight = 0;
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di) {
                        int x = i + di, y = j + dj;
                        if ((di == 0 && dj == 0) || x < 0 || y < 0 || x >= s || y >= s) continue;
                        double w = (di == 0 || dj == 0) ? 2 : 1;
                        neighbours_.push_back({size_t(y * s + x), w});
                        weight += w;
                    }
                neighbourStart_.push_back(neighbours_.size());
                neighbourWeight_.push_back(weight);
            }
    }

    // Successive elimination: a stratum whose upper bound (mean + z sigma) lies below
    // another's lower bound cannot hold the max; its paths stop (its estimate keeps
    // the paths it had, and the light samples other strata's paths send it). Where
    // the band starts at 0 or below, a stratum whose upper bound lies below the band's
    // top while another's does not pauses: the max is above the top only through the
    // others, and below it only once every upper bound is (upperEnd), but its own is
    // from fewer paths, which may not have met the rare bright ones yet, so it catches
    // up before the value settles below the top (kPaused).
    std::vector<char> stillNeeded(const ItemEstimates& e, double z, double targetMin, double targetMax) const override {
        const int n = e.items();
        std::vector<double> upper(static_cast<size_t>(n));
        double bestLower = -kInf, mostUpper = -kInf;
        for (int i = 0; i < n; ++i) {
            const Estimate x = e.of(i);
            upper[size_t(i)] = x.value + z * x.standardError;
            bestLower = std::max(bestLower, x.value - z * x.standardError);
            mostUpper = std::max(mostUpper, upper[size_t(i)]);
        }
        const bool pauseBelowTop = targetMin <= 0 && mostUpper >= targetMax;
        std::vector<char> keep(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i)
            keep[size_t(i)] = upper[size_t(i)] < bestLower                          ? kNoMorePaths
                              : pauseBelowTop && upper[size_t(i)] < targetMax ? kPaused
                                                                              : kMorePaths;
        if (!pauseBelowTop) return keep;
        // Focus: while the best stratum's mean is above the band's top, only it is
        // traced on, the best by the shrunk means that choose the value (brightest()).
        // One stratum's lower end above the top settles the value there (lowerEnd),
        // and paths shared among near-equal strata clear it later than the same paths
        // given to one. The others pause, though they may still hold the max: they
        // catch up before a stop at or below the top, and one of them is traced on
        // once its mean overtakes the best's.
        std::vector<double> mean(static_cast<size_t>(n)), error(static_cast<size_t>(n)), score;
        for (int i = 0; i < n; ++i) mean[size_t(i)] = e.of(i).value, error[size_t(i)] = e.of(i).standardError;
        shrunk(mean, error, score);
        int best = -1;
        for (int i = 0; i < n; ++i)
            if (keep[size_t(i)] == kMorePaths && (best < 0 || score[size_t(i)] > score[size_t(best)])) best = i;
        if (best < 0 || !(mean[size_t(best)] > targetMax)) return keep;
        for (int i = 0; i < n; ++i)
            if (i != best && keep[size_t(i)] == kMorePaths) keep[size_t(i)] = kPaused;
        return keep;
    }

    // The cross-fitted max can read far low while few paths have found the bright
    // ones: a stratum is chosen where other folds' paths found them, and the held-out
    // fold's seldom did (in the office, near a glare bound, 16 +- 2 cd/m2 where the
    // truth is 131). No stratum's own interval has that choice in it, so the value is
    // below a bound only when every stratum's upper end is.
    double upperEnd(const ItemEstimates& e, double z) const override {
        double most = -kInf;
        for (int i = 0; i < e.items(); ++i) {
            const Estimate x = e.of(i);
            most = std::max(most, x.value + z * x.standardError);
        }
        return most;
    }

    // The other way round, a stratum's own interval bounds the max from below without
    // any choice in it: once one stratum's lower end is above a bound, so is the max,
    // where the cross-fitted value's interval (a few fold values, Student's) is wider.
    double lowerEnd(const ItemEstimates& e, double z) const override {
        double most = -kInf;
        for (int i = 0; i < e.items(); ++i) {
            const Estimate x = e.of(i);
            most = std::max(most, x.value - z * x.standardError);
        }
        return most;
    }

    Estimate combine(const ItemEstimates& e) const override {
        const int n = e.items();
        std::vector<double> value, weight;  // per fold with paths
        std::vector<double> mean(static_cast<size_t>(n)), error(static_cast<size_t>(n));
        for (int g = 0; g < ItemEstimates::kFolds && n > 1; ++g) {
            const double paths = double(e.pathsInFold(0, g));  // the same for every stratum
            if (paths == 0) continue;
            for (int i = 0; i < n; ++i) {
                Estimate x = e.ofAllBut(i, g);
                mean[size_t(i)] = x.value, error[size_t(i)] = x.standardError;
            }
            value.push_back(e.ofFold(int(brightest(mean, error)), g).value);
            weight.push_back(paths);
        }
        Estimate r;
        if (value.size() < 2) {
            // One stratum, or too few paths to hold one fold out: the best stratum.
            for (int i = 0; i < n; ++i) {
                Estimate x = e.of(i);
                mean[size_t(i)] = x.value, error[size_t(i)] = x.standardError;
            }
            if (n > 0) r = e.of(int(brightest(mean, error)));
            return r;
        }
        double total = 0;
        for (double w : weight) total += w;
        for (size_t g = 0; g < value.size(); ++g) r.value += weight[g] / total * value[g];
        double var = 0;
        for (size_t g = 0; g < value.size(); ++g) var += std::pow(weight[g] / total * (value[g] - r.value), 2);
        r.standardError = std::sqrt(var * double(value.size()) / double(value.size() - 1));
        r.degreesOfFreedom = int(value.size()) - 1;
        return r;
    }

    // A parametric bootstrap of combine(), its choices included: every fold's stratum
    // means are drawn afresh around the strata's shrunk means (what brightest() judges
    // by), each with the spread the stratum's own fold means show, and the value is
    // cross-fitted again from them; the error is the spread of those values. The folds
    // choose from data they mostly share, so they choose alike and their values move
    // together from run to run, which their own spread cannot show (on a lit wall of
    // near-equal strata it was 0.65 of the spread over seeds; docs/light-transport.md).
    // The fold means' spread, not the paths', since the latter overstates the error of
    // low-discrepancy paths. The draws' numbers are seeded by the estimates: the same
    // paths give the same error.
    double reportedError(const ItemEstimates& e, const Estimate& value) const override {
        const size_t n = size_t(e.items());
        if (n < 2 || value.degreesOfFreedom < 1) return value.standardError;  // no choice cross-fitted
        std::vector<int> folds;
        std::vector<double> weight;
        double total = 0;
        for (int g = 0; g < ItemEstimates::kFolds; ++g)
            if (const double paths = double(e.pathsInFold(0, g)); paths > 0)
                folds.push_back(g), weight.push_back(paths), total += paths;
        const size_t k = folds.size();
        if (k < 2) return value.standardError;
        std::vector<double> mean(n), error(n), foldMean(k);
        uint64_t seed = kBootstrapTag;
        for (size_t i = 0; i < n; ++i) {
            double m = 0, spread = 0;
            for (size_t g = 0; g < k; ++g) foldMean[g] = e.ofFold(int(i), folds[g]).value, m += weight[g] / total * foldMean[g];
            for (size_t g = 0; g < k; ++g) spread += weight[g] / total * (foldMean[g] - m) * (foldMean[g] - m);
            mean[i] = m, error[i] = std::sqrt(spread / double(k - 1));
            seed = hashValues({seed, std::bit_cast<uint64_t>(m)});
        }
        std::vector<double> centre;
        shrunk(mean, error, centre);
        const std::array<double, kNormals>& normal = normalQuantiles();
        Rng rng(seed);
        // What each fold's choice reads the other folds' means with: the same in every draw.
        std::vector<double> othersError(k * n);
        for (size_t g = 0; g < k; ++g)
            for (size_t i = 0; i < n; ++i) othersError[g * n + i] = error[i] * std::sqrt(total / (total - weight[g]));
        std::vector<double> drawn(k * n), sums(n), others(n), foldErrors(n);
        double sum = 0, sumSquares = 0;
        for (int b = 0; b < kBootstrapDraws; ++b) {
            std::fill(sums.begin(), sums.end(), 0.0);
            for (size_t g = 0; g < k; ++g) {
                const double spread = std::sqrt(total / weight[g]);
                for (size_t i = 0; i < n; ++i)
                    drawn[g * n + i] = centre[i] + error[i] * spread * normal[rng.nextU32() >> (32 - kNormalBits)];
            }
            for (size_t g = 0; g < k; ++g)
                for (size_t i = 0; i < n; ++i) sums[i] += weight[g] * drawn[g * n + i];
            double v = 0;
            for (size_t g = 0; g < k; ++g) {
                const double rest = total - weight[g];
                for (size_t i = 0; i < n; ++i) others[i] = (sums[i] - weight[g] * drawn[g * n + i]) / rest;
                std::copy_n(othersError.begin() + long(g * n), n, foldErrors.begin());
                v += weight[g] / total * drawn[g * n + brightest(others, foldErrors)];
            }
            v -= value.value;  // about the value: no cancellation where the spread is a tiny part of it
            sum += v, sumSquares += v * v;
        }
        const double m = sum / kBootstrapDraws;
        return std::sqrt(std::max(0.0, (sumSquares / kBootstrapDraws - m * m) * kBootstrapDraws / (kBootstrapDraws - 1)));
    }

    // The apex and the frustum's four edge rays, 1 m long.
    SamplerDrawing drawing() const override {
        const Vec3 &eye = frustum.eye, &forward = frustum.forward, &right = frustum.right, &up = frustum.up;
        const double tanHalfFov = frustum.tanHalfFov;
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
    ResultGroup resultGroup() const override { return ResultGroup::Glare; }  // glare on a screen
    std::string quantityHtml(bool) const override { return "luminance in view (brightest part)"; }

    std::unique_ptr<PlacedSampler> place(const Transform& world) const override {
        auto p = std::make_unique<PlacedDirectional>();
        Frustum& f = p->frustum;
        f.eye = world.applyPoint(origin);
        f.forward = normalize(world.applyVector(direction));
        f.right = normalize(cross(f.forward, world.applyVector(up)));
        f.up = cross(f.right, f.forward);
        f.tanHalfFov = std::tan(radians(fovDeg) / 2);
        f.strata = strata;
        p->findNeighbours();
        return p;
    }

    std::optional<Vec3> facing(const Transform& world) const override { return normalize(world.applyVector(direction)); }

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
    if (strata < 1 || strata > limits::kMaxDirectionalStrata)
        throw std::invalid_argument("directional sampler: strata must lie in [1, " +
                                    std::to_string(limits::kMaxDirectionalStrata) + "]");
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
    s->origin = f.vec3("origin", true, json::coordinateRange()).value_or(Vec3());
    s->direction = f.direction("direction", true).value_or(Vec3(0, -1, 0));
    s->fovDeg = f.number("fov_deg", 60.0, json::Range{0, 180, true, true, "deg"});
    s->strata = f.integer("strata", json::Range::atLeast(1)).value_or(8);
    if (s->strata > limits::kMaxDirectionalStrata) {
        f.error("strata", "strata " + std::to_string(s->strata) + " (" + std::to_string(int64_t(s->strata) * s->strata) +
                              " strata) exceeds the limit of " + std::to_string(limits::kMaxDirectionalStrata));
        s->strata = 8;
    }
    Vec3 fallbackUp = std::abs(s->direction.z) > 0.999 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    s->up = f.direction("up").value_or(fallbackUp);
    if (length(cross(s->up, s->direction)) < 1e-6) f.error("up", "\"up\" is parallel to \"direction\"");
    return s;
}

}  // namespace luxplan
