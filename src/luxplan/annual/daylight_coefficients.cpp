#include <luxplan/annual/daylight_coefficients.h>

#include <atomic>
#include <cmath>

#include <luxplan/core/parallel.h>
#include <luxplan/core/rng.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/pathtracer/path_samples.h>
#include <luxplan/pathtracer/sensor.h>

namespace luxplan {
namespace {

constexpr uint64_t kCoefficientTag = 0x6461'796c'6967'6874ULL;  // "daylight"

// The basis sky: every direction at 1 cd/m2, the ground too (a patch of its own), and
// one white disk of 1 lx normal illuminance per sun bin.
DaylightEnvironment basisSky(const std::vector<Vec3>& sunBins) {
    SkyMap map(64, 32);
    for (int iy = 0; iy < map.height(); ++iy)
        for (int ix = 0; ix < map.width(); ++ix) map.at(ix, iy) = Vec3(1, 1, 1);
    std::vector<SunDisk> disks;
    for (const Vec3& d : sunBins) {
        SunDisk s;
        s.direction = d;
        s.altitudeDeg = degrees(std::asin(std::clamp(d.z, -1.0, 1.0)));
        s.normalIlluminanceLx = 1;
        s.luminance = 1 / kSunDiskProjectedSolidAngle;
        disks.push_back(s);
    }
    return DaylightEnvironment(std::move(map), std::move(disks), Vec3(1, 1, 1));
}

// One path's daylight by basis: sky patches first, then sun bins (the sun straight at
// the sensor left out: directSun gives it per hour).
class PathTally final : public DaylightTally {
public:
    PathTally(const SkyPatches& sky, const SkyPatches& sunPatches, const std::vector<int>& binOfPatch,
              const std::vector<Vec3>& sunBins, std::vector<BasisEntry>& entries)
        : sky_(sky), sunPatches_(sunPatches), binOfPatch_(binOfPatch), sunBins_(sunBins), entries_(entries) {}
    void add(int source, const Vec3& towards, int depth, double value) override {
        if (value == 0) return;
        if (source == LightBudget::kSky) {
            entries_.push_back({sky_.patchOf(towards), value});
        } else if (depth > 0) {
            entries_.push_back({sky_.count() + nearestBin(towards), value});
        }
    }

private:
    // The disk the direction lies in: its patch's, unless the disk reaches over the
    // patch's edge (then the nearest centre).
    int nearestBin(const Vec3& w) const {
        const int own = binOfPatch_[size_t(sunPatches_.patchOf(w))];
        if (own >= 0 && dot(w, sunBins_[size_t(own)]) >= kWithinDisk) return own;
        int best = 0;
        double most = -2;
        for (size_t b = 0; b < sunBins_.size(); ++b)
            if (const double c = dot(w, sunBins_[b]); c > most) most = c, best = int(b);
        return best;
    }
    static inline const double kWithinDisk = std::cos(kSunHalfAngle * 1.01);
    const SkyPatches& sky_;
    const SkyPatches& sunPatches_;
    const std::vector<int>& binOfPatch_;
    const std::vector<Vec3>& sunBins_;
    std::vector<BasisEntry>& entries_;
};

}  // namespace

std::vector<DaylightInstant> annualHours(const DaylightParams& params, const Site& site) {
    std::vector<DaylightInstant> out;
    for (const DaylightInstant& i : daylightInstants(params, site))
        if (i.time && i.hasSunPosition && i.sunAltitudeDeg > 0 && occupiedAt(params.occupied, *i.time)) out.push_back(i);
    return out;
}

DaylightCoefficients::DaylightCoefficients(std::vector<DaylightInstant> hours,
                                           const std::function<HourSky(size_t hour)>& skyOf,
                                           const DaylightCoefficientOptions& options)
    : hours_(std::move(hours)), options_(options), sky_(options.skySubdivision), sunPatches_(options.sunSubdivision) {
    // The sun bins: the patches of the finer subdivision that the hours' suns visit,
    // each disk at the mean direction of its hours' suns.
    binOfPatch_.assign(size_t(sunPatches_.count()), -1);
    std::vector<Vec3> sums;
    hourBins_.assign(hours_.size(), -1);
    for (size_t h = 0; h < hours_.size(); ++h) {
        if (!hours_[h].sunUp()) continue;
        int& bin = binOfPatch_[size_t(sunPatches_.patchOf(hours_[h].sunDirection))];
        if (bin < 0) bin = int(sums.size()), sums.push_back(Vec3());
        sums[size_t(bin)] += hours_[h].sunDirection;
        hourBins_[h] = bin;
    }
    for (const Vec3& s : sums) sunBinDirections_.push_back(normalize(s));
    basis_ = std::make_unique<DaylightEnvironment>(basisSky(sunBinDirections_));

    // Each hour's patch luminances: the mean over n x n directions equal in solid angle,
    // and the ground's from the light on the open horizontal plane, as the baked sky's.
    const int patches = sky_.count(), n = std::max(2, 4 / sky_.subdivision());
    luminance_.assign(size_t(patches) * hours_.size(), 0.0);
    parallelFor(hours_.size(), [&](size_t h) {
        const HourSky hour = skyOf(h);
        std::vector<double> L(size_t(patches), 0.0);
        double horizontal = 0;
        for (int p = 1; p < patches; ++p) {
            double sum = 0;
            const std::vector<Vec3> dirs = sky_.directions(p, n);
            for (const Vec3& d : dirs) sum += hour.luminance(d);
            L[size_t(p)] = sum / double(dirs.size());
            horizontal += L[size_t(p)] * sky_.projectedSolidAngle(p);
        }
        if (hour.diffuseHorizontalLx) {
            // A relative sky: scaled so that its patches give the hour's diffuse
            // horizontal illuminance on the open plane.
            const double scale = horizontal > 0 ? *hour.diffuseHorizontalLx / horizontal : 0;
            for (int p = 1; p < patches; ++p) L[size_t(p)] *= scale;
            horizontal *= scale;
        }
        const DaylightInstant& i = hours_[h];
        if (i.sunUp()) horizontal += i.sunNormalIlluminanceLx * std::max(0.0, i.sunDirection.z);
        L[0] = options_.groundReflectance * horizontal / kPi;
        for (int p = 0; p < patches; ++p) luminance_[size_t(p) * hours_.size() + h] = L[size_t(p)];
    });
}

PathTracerOptions DaylightCoefficients::tracing() {
    PathTracerOptions o;
    o.exteriorSun = false;  // its samples mix the sun and the sky
    return o;
}

bool DaylightCoefficients::supports(const PlacedSampler& placed) { return placed.items() > 0 && placed.sensorOf(0) != nullptr; }

PathSamples::Sequence DaylightCoefficients::sequenceOf(size_t sampler, int item, uint64_t seed) {
    return PathSamples::Sequence(hashValues({seed, kCoefficientTag, uint64_t(sampler), uint64_t(item)}));
}

bool DaylightCoefficients::tracePath(const PathTracer& tracer, const PlacedSampler& placed, const PathSamples::Sequence& sequence,
                                     size_t sampler, int item, int path, uint64_t seed, std::vector<BasisEntry>& entries,
                                     RayStats& stats, PathFootprint* footprint) const {
    entries.clear();
    PathTally tally(sky_, sunPatches_, binOfPatch_, sunBinDirections_, entries);
    PathParams params;
    params.daylight = &tally;
    params.footprint = footprint;
    Rng rng(hashValues({seed, kCoefficientTag, uint64_t(sampler), uint64_t(item), uint64_t(path)}));
    PathSamples samples(rng, sequence, uint32_t(path));
    PathContributions out(item);
    placed.sample(tracer, item, samples, stats, params, out);
    if (out.finite()) return true;
    entries.clear();  // dropped, as the estimator drops it
    return false;
}

PointCoefficients DaylightCoefficients::coefficients(const PathTracer& tracer, const PlacedSampler& placed, size_t sampler,
                                                     int item, int paths, uint64_t seed) const {
    paths = std::max(1, paths);
    PointCoefficients c = emptyCoefficients();
    std::vector<BasisEntry> entries;
    RayStats stats;
    const PathSamples::Sequence sequence = sequenceOf(sampler, item, seed);
    for (int p = 0; p < paths; ++p) {
        tracePath(tracer, placed, sequence, sampler, item, p, seed, entries, stats, nullptr);
        add(entries, c);
    }
    scale(c, paths);
    // The sun straight at the point, for each hour's own position.
    const std::unique_ptr<Sensor> sensor = placed.sensorOf(item);
    for (size_t h = 0; h < hours_.size(); ++h)
        if (hours_[h].sunUp()) c.direct[h] = tracer.directSun(*sensor, hours_[h].sunDirection, stats);
    return c;
}

PointCoefficients DaylightCoefficients::emptyCoefficients() const {
    PointCoefficients c;
    c.sky.assign(size_t(sky_.count()), 0.0);
    c.sun.assign(sunBinDirections_.size(), 0.0);
    c.direct.assign(hours_.size(), 0.0);
    return c;
}

void DaylightCoefficients::add(std::span<const BasisEntry> entries, PointCoefficients& c) const {
    const int patches = sky_.count();
    for (const BasisEntry& e : entries)
        if (e.basis < patches) c.sky[size_t(e.basis)] += e.value;
        else c.sun[size_t(e.basis - patches)] += e.value;
}

void DaylightCoefficients::scale(PointCoefficients& c, int paths) {
    for (double& v : c.sky) v /= paths;
    for (double& v : c.sun) v /= paths;
}

void DaylightCoefficients::hourly(const PointCoefficients& c, std::vector<double>& values, std::vector<double>& direct) const {
    const size_t hours = hours_.size();
    const int patches = sky_.count();
    values.assign(hours, 0.0);
    direct.assign(hours, 0.0);
    // Patch after patch over every hour (the hours' sums vectorize; each hour still
    // adds its patches in order, so the sums are those of a loop over the patches).
    double* v = values.data();
    for (int p = 0; p < patches; ++p) {
        const double cp = c.sky[size_t(p)];
        const double* L = luminance_.data() + size_t(p) * hours;
        for (size_t h = 0; h < hours; ++h) v[h] += cp * L[h];
    }
    for (size_t h = 0; h < hours; ++h)
        if (hourBins_[h] >= 0) {
            const double En = hours_[h].sunNormalIlluminanceLx;
            direct[h] = En * c.direct[h];
            v[h] += En * c.sun[size_t(hourBins_[h])] + direct[h];
        }
}

std::vector<DaylightCoefficients::Point> DaylightCoefficients::points(const Scene& scene, const PathTracer& tracer,
                                                                      const std::vector<size_t>& which,
                                                                      std::vector<std::unique_ptr<PlacedSampler>>& placed) {
    std::vector<Point> out;
    placed.clear();
    for (size_t k : which) {
        std::unique_ptr<PlacedSampler> p = placeSampler(scene.samplers[k], tracer);
        if (supports(*p))
            for (int i = 0; i < p->items(); ++i)
                if (!p->covered(i)) out.push_back({k, placed.size(), i});
        placed.push_back(std::move(p));
    }
    return out;
}

AnnualSeries DaylightCoefficients::series(const Scene& scene, const std::vector<size_t>& which,
                                          const std::vector<std::unique_ptr<PlacedSampler>>& placed,
                                          const std::vector<Point>& points, std::vector<std::vector<double>>& values,
                                          std::vector<std::vector<double>>& direct) const {
    const size_t hours = hours_.size();
    AnnualSeries out;
    for (const DaylightInstant& h : hours_) out.hours.push_back(h.time.value_or(DateTime{}));
    // Each sampler: its points' mean per hour (the covered ones left out).
    size_t w = 0;
    for (size_t s = 0; s < placed.size(); ++s) {
        if (!supports(*placed[s])) continue;
        const LightSamplerSpec& spec = scene.samplers[which[s]];
        AnnualSampler a;
        a.name = spec.name;
        a.type = spec.type->name();
        a.targetMin = spec.targetMin, a.targetMax = spec.targetMax;
        a.planar = a.type == "planar";
        a.values.assign(hours, 0.0);
        const int items = placed[s]->items();
        std::vector<std::vector<double>> pointValues(static_cast<size_t>(items)), sun(static_cast<size_t>(items));
        int counted = 0;
        for (; w < points.size() && points[w].placed == s; ++w) {
            ++counted;
            for (size_t h = 0; h < hours; ++h) a.values[h] += values[w][h];
            pointValues[size_t(points[w].item)] = std::move(values[w]);
            sun[size_t(points[w].item)] = std::move(direct[w]);
        }
        for (double& v : a.values) v = counted > 0 ? v / counted : 0;
        if (a.planar) a.points = std::move(pointValues), a.directSun = std::move(sun);
        out.samplers.push_back(std::move(a));
    }
    return out;
}

AnnualSeries DaylightCoefficients::measure(const PathTracer& tracer, const std::vector<size_t>& which, int paths,
                                           uint64_t seed, const std::function<void(size_t, size_t)>& progress,
                                           size_t* measured) const {
    const Scene& scene = tracer.rayTracer().scene();
    std::vector<std::unique_ptr<PlacedSampler>> placed;
    const std::vector<Point> work = points(scene, tracer, which, placed);
    if (measured) *measured = work.size();
    // Each point's hours, from its coefficients.
    std::vector<std::vector<double>> values(work.size()), direct(work.size());
    std::atomic<size_t> done{0};
    parallelFor(work.size(), [&](size_t w) {
        const Point& job = work[w];
        hourly(coefficients(tracer, *placed[job.placed], job.sampler, job.item, paths, seed), values[w], direct[w]);
        const size_t finished = ++done;
        if (progress) progress(finished, work.size());
    });
    return series(scene, which, placed, work, values, direct);
}

}  // namespace luxplan
