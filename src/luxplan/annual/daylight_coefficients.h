// Daylight coefficients: a year of hourly light at every sampler point from one trace.
// Each point's paths are traced once under a basis sky: every sky patch (sky_patches.h)
// and the ground at 1 cd/m2, and one sun disk of 1 lx per sun bin (the sun positions
// of the hours, binned by the patches of a finer subdivision). The light each path
// brings is credited to the patch or the bin it came from (PathParams::daylight), so a
// point's value at any hour is a dot product: each patch's mean luminance that hour
// times its coefficient, plus the ground's, plus that hour's sun (its normal
// illuminance) times its bin's coefficient. The sun straight at the point is no
// coefficient: it is computed for each hour's own sun position (PathTracer::directSun),
// so a sun patch on a desk lands where it does. docs/daylight.md, "Daylight coefficients".
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <luxplan/annual/annual_series.h>
#include <luxplan/annual/sky_patches.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_samples.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

struct DaylightCoefficientOptions {
    int skySubdivision = 1;    // Reinhart MF of the sky patches (1: 145 patches)
    int sunSubdivision = 2;    // ... of the bins of the interreflected sun (2: about 6 deg)
    double groundReflectance = 0.2;  // of the ground outside, lit by each hour's sky and sun
};

// One hour's sky: its luminance (cd/m2) in a scene direction above the horizon.
using SkyLuminance = std::function<double(const Vec3&)>;

// One hour's sky for the coefficients: its luminance, or a relative distribution and the
// diffuse horizontal illuminance (lx) to scale it to, on the patches' own quadrature (a
// Perez sky: its normalisation on a fine grid costs more than the rest of a year).
struct HourSky {
    HourSky(SkyLuminance sky) : luminance(std::move(sky)) {}  // NOLINT: a luminance is an hour's sky
    HourSky(SkyLuminance relative, double diffuseHorizontalLx)
        : luminance(std::move(relative)), diffuseHorizontalLx(diffuseHorizontalLx) {}
    SkyLuminance luminance;
    std::optional<double> diffuseHorizontalLx;  // set: `luminance` is relative, scaled to give this
};

// The hours an annual measurement counts: the instants of the scene's daylight period
// (every hour of its weather file's period) that are occupied (DaylightParams::occupied)
// with the sun above the horizon.
std::vector<DaylightInstant> annualHours(const DaylightParams& params, const Site& site);

// What one point receives per unit of each basis: [patch] per cd/m2 of the patch
// (patch 0 the ground), [bin] per lx of a sun in that bin, scattered at least once;
// [hour]: straight from that hour's sun, per lx.
struct PointCoefficients {
    std::vector<double> sky, sun, direct;
};

// What one path brought from one basis: index < patches a sky patch's, else sun bin
// (index - patches)'s.
struct BasisEntry {
    int basis;
    double value;
};

class DaylightCoefficients {
public:
    // The basis for these hours (their suns set the sun bins) and each hour's patch
    // luminances, `sky(k)` being hour k's sky (layout-free: computed once).
    DaylightCoefficients(std::vector<DaylightInstant> hours, const std::function<HourSky(size_t hour)>& sky,
                         const DaylightCoefficientOptions& options);

    // The basis sky the coefficients are traced under, and how (no exterior sun: its
    // samples mix the sun and the sky). A tracer of both on the scene's EmbreeScene
    // measures any layout it is updated to.
    const DaylightEnvironment& basis() const { return *basis_; }
    static PathTracerOptions tracing();

    // Every hour's light at the samplers `which` (indices into Scene::samplers; those
    // that are no single sensors per point, as directional, ugr and dgp, are left out:
    // supports()), where the tracer's layout puts them, `paths` paths per point.
    // `progress(done, total)` is told as points finish.
    // `points`, if given, is told how many points were measured.
    AnnualSeries measure(const PathTracer& tracer, const std::vector<size_t>& which, int paths, uint64_t seed,
                         const std::function<void(size_t, size_t)>& progress = {}, size_t* points = nullptr) const;
    // Whether a sampler type gets coefficients (each item one sensor).
    static bool supports(const PlacedSampler& placed);

    // One point's coefficients: `paths` paths (tracePath), summed in order and divided
    // by their count, and the direct sun per hour.
    PointCoefficients coefficients(const PathTracer& tracer, const PlacedSampler& placed, size_t sampler, int item,
                                   int paths, uint64_t seed) const;

    // The parts of coefficients() and measure(), for an incremental measurement
    // (coefficient_cache.h) that gives the same numbers bit for bit.
    // A point to measure: sampler index `sampler` (in Scene::samplers), placed as
    // placed[placed], its item `item`.
    struct Point {
        size_t sampler, placed;
        int item;
    };
    // The uncovered points of the samplers `which` that supports() takes, sampler after
    // sampler, as the tracer's layout places them (`placed`: one per `which`).
    static std::vector<Point> points(const Scene& scene, const PathTracer& tracer, const std::vector<size_t>& which,
                                     std::vector<std::unique_ptr<PlacedSampler>>& placed);
    static PathSamples::Sequence sequenceOf(size_t sampler, int item, uint64_t seed);
    // Path `path` of the point: its light by basis in `entries` (in the order the path
    // brought it), its rays in `footprint` if given. False, with no entries, for a path
    // the estimator drops (not finite).
    bool tracePath(const PathTracer& tracer, const PlacedSampler& placed, const PathSamples::Sequence& sequence,
                   size_t sampler, int item, int path, uint64_t seed, std::vector<BasisEntry>& entries, RayStats& stats,
                   PathFootprint* footprint) const;
    PointCoefficients emptyCoefficients() const;  // sized, zero
    void add(std::span<const BasisEntry> entries, PointCoefficients& c) const;
    static void scale(PointCoefficients& c, int paths);  // the sums of `paths` paths to means
    // The point's value and its direct-sun part at each hour.
    void hourly(const PointCoefficients& c, std::vector<double>& values, std::vector<double>& direct) const;
    // The series of the points' hourly values (moved from), as measure() assembles it.
    AnnualSeries series(const Scene& scene, const std::vector<size_t>& which,
                        const std::vector<std::unique_ptr<PlacedSampler>>& placed, const std::vector<Point>& points,
                        std::vector<std::vector<double>>& values, std::vector<std::vector<double>>& direct) const;

    const std::vector<DaylightInstant>& hours() const { return hours_; }
    const SkyPatches& skyPatches() const { return sky_; }
    int sunBins() const { return int(sunBinDirections_.size()); }
    int sunBinOf(size_t hour) const { return hourBins_[hour]; }  // -1: its sun is down

private:
    std::vector<DaylightInstant> hours_;
    DaylightCoefficientOptions options_;
    SkyPatches sky_, sunPatches_;
    std::vector<int> binOfPatch_;         // sun patch -> bin (-1: none)
    std::vector<Vec3> sunBinDirections_;  // the basis disks' centres
    std::vector<int> hourBins_;
    std::vector<double> luminance_;  // [patch * hours + hour], cd/m2 (patch 0: the ground)
    std::unique_ptr<DaylightEnvironment> basis_;
};

}  // namespace luxplan
