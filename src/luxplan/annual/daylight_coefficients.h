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
#include <string>
#include <vector>

#include <luxplan/annual/annual_series.h>
#include <luxplan/annual/sky_patches.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

struct DaylightCoefficientOptions {
    int skySubdivision = 1;    // Reinhart MF of the sky patches (1: 145 patches)
    int sunSubdivision = 2;    // ... of the bins of the interreflected sun (2: about 6 deg)
    int pathsPerPoint = 1000;  // per sampler point, traced once
    uint64_t seed = 1;
    double groundReflectance = 0.2;  // of the ground outside, lit by each hour's sky and sun
    // Called as points finish, with how many of how many (progress on long runs).
    std::function<void(size_t done, size_t total)> progress;
};

// One hour's sky: its luminance (cd/m2) in a scene direction above the horizon.
using SkyLuminance = std::function<double(const Vec3&)>;

class DaylightCoefficients {
public:
    // Traces the scene's samplers where `layout` places them. `hours`: the instants
    // whose suns set the sun bins and whose direct sun is computed (each with the sun up
    // or not). Samplers whose points are no single sensors (directional, ugr, dgp) get
    // no coefficients: unsupported() names them.
    DaylightCoefficients(const Scene& scene, const Layout& layout, const std::vector<DaylightInstant>& hours,
                         const DaylightCoefficientOptions& options);

    // The light of every hour given at construction, `sky(k)` being hour k's sky.
    AnnualSeries series(const std::function<SkyLuminance(size_t hour)>& sky) const;

    // What one point receives per unit of each basis: [patch] per cd/m2 of the patch
    // (patch 0 the ground), [bin] per lx of a sun in that bin, scattered at least once.
    struct Point {
        std::vector<double> sky, sun;
        std::vector<double> direct;  // [hour]: straight from that hour's sun, per lx
        bool covered = false;        // covered by furniture: left out
    };
    struct Sampler {
        size_t index;  // in Scene::samplers
        std::vector<Point> points;
    };
    const std::vector<Sampler>& samplers() const { return samplers_; }
    const std::vector<std::string>& unsupported() const { return unsupported_; }
    const SkyPatches& skyPatches() const { return sky_; }
    int sunBins() const { return int(sunBinDirections_.size()); }
    // The sun bin of hour k (-1: its sun is down).
    int sunBinOf(size_t hour) const { return hourBins_[hour]; }

private:
    const Scene* scene_;
    std::vector<DaylightInstant> hours_;
    DaylightCoefficientOptions options_;
    SkyPatches sky_, sunPatches_;
    std::vector<Vec3> sunBinDirections_;  // the basis disks' centres
    std::vector<int> hourBins_;
    std::vector<Sampler> samplers_;
    std::vector<std::string> unsupported_;
};

}  // namespace luxplan
