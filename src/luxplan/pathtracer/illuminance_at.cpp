#include <luxplan/pathtracer/illuminance_at.h>

#include <algorithm>

#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>
#include <luxplan/core/rng.h>

namespace luxplan {

PointIlluminance illuminanceAt(const PathTracer& tracer, const std::vector<Vec3>& points, const Vec3& normal, int paths,
                               uint64_t seed, uint64_t tag) {
    PointIlluminance out;
    out.values.assign(points.size(), 0.0);
    out.errors.assign(points.size(), 0.0);
    paths = std::max(1, paths);
    parallelFor(points.size(), [&](size_t i) {
        RayStats stats;
        MeanEstimator estimate;
        for (int path = 0; path < paths; ++path) {
            Rng rng(hashValues({seed, tag, uint64_t(i), uint64_t(path)}));
            estimate.add(tracer.illuminanceSample(points[i], normal, rng, stats));
        }
        out.values[i] = estimate.mean();
        out.errors[i] = estimate.standardError();
    });
    return out;
}

}  // namespace luxplan
