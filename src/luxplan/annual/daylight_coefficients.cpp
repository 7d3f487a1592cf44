#include <luxplan/annual/daylight_coefficients.h>

#include <atomic>
#include <cmath>
#include <memory>

#include <luxplan/core/parallel.h>
#include <luxplan/core/rng.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/pathtracer/path_samples.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/pathtracer/sensor.h>
#include <luxplan/rt/embree_scene.h>

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
              const std::vector<Vec3>& sunBins)
        : sky_(sky), sunPatches_(sunPatches), binOfPatch_(binOfPatch), sunBins_(sunBins) {}
    void add(int source, const Vec3& towards, int depth, double value) override {
        if (value == 0) return;
        if (source == LightBudget::kSky) {
            entries_.push_back({sky_.patchOf(towards), value});
        } else if (depth > 0) {
            entries_.push_back({sky_.count() + nearestBin(towards), value});
        }
    }
    void clear() { entries_.clear(); }
    struct Entry {
        int basis;
        double value;
    };
    const std::vector<Entry>& entries() const { return entries_; }

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
    std::vector<Entry> entries_;
};

}  // namespace

DaylightCoefficients::DaylightCoefficients(const Scene& scene, const Layout& layout,
                                           const std::vector<DaylightInstant>& hours,
                                           const DaylightCoefficientOptions& options)
    : scene_(&scene), hours_(hours), options_(options), sky_(options.skySubdivision), sunPatches_(options.sunSubdivision) {
    // The sun bins: the patches of the finer subdivision that the hours' suns visit,
    // each disk at the mean direction of its hours' suns.
    std::vector<int> binOfPatch(size_t(sunPatches_.count()), -1);
    std::vector<Vec3> sums;
    hourBins_.assign(hours_.size(), -1);
    for (size_t h = 0; h < hours_.size(); ++h) {
        if (!hours_[h].sunUp()) continue;
        const int patch = sunPatches_.patchOf(hours_[h].sunDirection);
        int& bin = binOfPatch[size_t(patch)];
        if (bin < 0) bin = int(sums.size()), sums.push_back(Vec3());
        sums[size_t(bin)] += hours_[h].sunDirection;
        hourBins_[h] = bin;
    }
    for (const Vec3& s : sums) sunBinDirections_.push_back(normalize(s));

    const DaylightEnvironment basis = basisSky(sunBinDirections_);
    EmbreeScene rt(scene, layout);
    PathTracerOptions tracing;
    tracing.exteriorSun = false;  // its samples mix the sun and the sky
    const PathTracer tracer(rt, &basis, tracing);

    struct Work {
        size_t sampler;
        int item;
    };
    std::vector<Work> work;
    std::vector<std::unique_ptr<PlacedSampler>> placed(scene.samplers.size());
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        placed[k] = placeSampler(scene.samplers[k], tracer);
        if (!placed[k]->sensorOf(0)) {
            unsupported_.push_back(scene.samplers[k].name);
            continue;
        }
        Sampler s{k, std::vector<Point>(size_t(placed[k]->items()))};
        for (int i = 0; i < placed[k]->items(); ++i) {
            s.points[size_t(i)].covered = placed[k]->covered(i);
            if (!placed[k]->covered(i)) work.push_back({samplers_.size(), i});
        }
        samplers_.push_back(std::move(s));
    }

    const int bases = sky_.count() + int(sunBinDirections_.size());
    const int paths = std::max(1, options_.pathsPerPoint);
    std::atomic<size_t> done{0};
    parallelFor(work.size(), [&](size_t w) {
        const Work& job = work[w];
        Sampler& sampler = samplers_[job.sampler];
        const PlacedSampler& place = *placed[sampler.index];
        Point& point = sampler.points[size_t(job.item)];
        std::vector<double> sums(size_t(bases), 0.0);
        PathTally tally(sky_, sunPatches_, binOfPatch, sunBinDirections_);
        PathParams params;
        params.daylight = &tally;
        RayStats stats;
        const PathSamples::Sequence sequence(
            hashValues({options_.seed, kCoefficientTag, uint64_t(sampler.index), uint64_t(job.item)}));
        for (int p = 0; p < paths; ++p) {
            tally.clear();
            Rng rng(hashValues({options_.seed, kCoefficientTag, uint64_t(sampler.index), uint64_t(job.item), uint64_t(p)}));
            PathSamples samples(rng, sequence, uint32_t(p));
            PathContributions out(job.item);
            place.sample(tracer, job.item, samples, stats, params, out);
            if (!out.finite()) continue;  // dropped, as the estimator drops it
            for (const PathTally::Entry& e : tally.entries()) sums[size_t(e.basis)] += e.value;
        }
        point.sky.assign(sums.begin(), sums.begin() + sky_.count());
        point.sun.assign(sums.begin() + sky_.count(), sums.end());
        for (double& v : point.sky) v /= paths;
        for (double& v : point.sun) v /= paths;
        // The sun straight at the point, for each hour's own position.
        const std::unique_ptr<Sensor> sensor = place.sensorOf(job.item);
        point.direct.assign(hours_.size(), 0.0);
        for (size_t h = 0; h < hours_.size(); ++h)
            if (hours_[h].sunUp()) point.direct[h] = tracer.directSun(*sensor, hours_[h].sunDirection, stats);
        const size_t finished = ++done;
        if (options_.progress) options_.progress(finished, work.size());
    });
}

AnnualSeries DaylightCoefficients::series(const std::function<SkyLuminance(size_t hour)>& skyOf) const {
    AnnualSeries out;
    const size_t hours = hours_.size();
    for (const DaylightInstant& h : hours_) out.hours.push_back(h.time.value_or(DateTime{}));

    // Each hour's patch luminances (the ground's from the light on the open horizontal
    // plane, as the baked sky's), then every point's dot product.
    const int patches = sky_.count(), n = std::max(2, 8 / sky_.subdivision());
    std::vector<std::vector<double>> luminance(hours, std::vector<double>(size_t(patches), 0.0));
    parallelFor(hours, [&](size_t h) {
        const SkyLuminance sky = skyOf(h);
        std::vector<double>& L = luminance[h];
        double horizontal = 0;
        for (int p = 1; p < patches; ++p) {
            double sum = 0;
            const std::vector<Vec3> dirs = sky_.directions(p, n);
            for (const Vec3& d : dirs) sum += sky(d);
            L[size_t(p)] = sum / double(dirs.size());
            horizontal += L[size_t(p)] * sky_.projectedSolidAngle(p);
        }
        const DaylightInstant& i = hours_[h];
        if (i.sunUp()) horizontal += i.sunNormalIlluminanceLx * std::max(0.0, i.sunDirection.z);
        L[0] = options_.groundReflectance * horizontal / kPi;
    });

    for (const Sampler& s : samplers_) {
        const LightSamplerSpec& spec = scene_->samplers[s.index];
        AnnualSampler a;
        a.name = spec.name;
        a.type = spec.type->name();
        a.targetMin = spec.targetMin, a.targetMax = spec.targetMax;
        a.planar = spec.type->hasPointStatistics() && std::string(a.type) == "planar";
        a.values.assign(hours, 0.0);
        std::vector<std::vector<double>> points(s.points.size()), direct(s.points.size());
        int counted = 0;
        for (size_t k = 0; k < s.points.size(); ++k) {
            const Point& pt = s.points[k];
            if (pt.covered) continue;
            ++counted;
            points[k].assign(hours, 0.0);
            direct[k].assign(hours, 0.0);
            for (size_t h = 0; h < hours; ++h) {
                double v = 0;
                for (int p = 0; p < patches; ++p) v += pt.sky[size_t(p)] * luminance[h][size_t(p)];
                const DaylightInstant& i = hours_[h];
                if (hourBins_[h] >= 0) {
                    const double En = i.sunNormalIlluminanceLx;
                    direct[k][h] = En * pt.direct[h];
                    v += En * pt.sun[size_t(hourBins_[h])] + direct[k][h];
                }
                points[k][h] = v;
                a.values[h] += v;
            }
        }
        for (double& v : a.values) v = counted > 0 ? v / counted : 0;
        if (a.planar) a.points = std::move(points), a.directSun = std::move(direct);
        out.samplers.push_back(std::move(a));
    }
    return out;
}

}  // namespace luxplan
