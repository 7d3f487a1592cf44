#include <luxplan/lightsamplers/light_samplers.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <luxplan/core/penalty.h>

namespace luxplan {
namespace {

// Halton radical inverse: well-spread, deterministic volume points.
double radicalInverse(int base, uint64_t i) {
    double inv = 1.0 / base, f = inv, r = 0;
    while (i > 0) {
        r += f * double(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

// One unit of work: one point (or stratum) of one sampler.
struct WorkItem {
    int sampler = 0;
    int point = 0;
};

}  // namespace

SamplerGeometry samplerGeometry(const LightSamplerSpec& s, const Transform& world) {
    SamplerGeometry g;
    switch (s.type) {
        case LightSamplerType::Planar: {
            Vec3 n = normalize(s.normal);
            Vec3 up = normalize(s.up - n * dot(s.up, n));
            Vec3 side = normalize(cross(up, n));  // the w direction
            for (int j = 0; j < s.grid[1]; ++j)
                for (int i = 0; i < s.grid[0]; ++i) {
                    double a = ((i + 0.5) / s.grid[0] - 0.5) * s.size.x, b = ((j + 0.5) / s.grid[1] - 0.5) * s.size.y;
                    g.points.push_back(world.applyPoint(s.center + side * a + up * b));
                }
            g.normal = normalize(world.applyVector(n));
            break;
        }
        case LightSamplerType::Directional: {
            g.points = {world.applyPoint(s.origin)};
            g.forward = normalize(world.applyVector(s.direction));
            Vec3 up = world.applyVector(s.up);
            g.right = normalize(cross(g.forward, up));
            g.up = cross(g.right, g.forward);
            g.tanHalfFov = std::tan(radians(s.fovDeg) / 2);
            g.strata = s.strata;
            break;
        }
        case LightSamplerType::Volume: {
            Vec3 corner = s.center - (s.axes[0] + s.axes[1] + s.axes[2]) * 0.5;
            for (int i = 0; i < s.points; ++i) {
                // Halton points 1..N in the unit cube, mapped onto the box.
                Vec3 u(radicalInverse(2, i + 1), radicalInverse(3, i + 1), radicalInverse(5, i + 1));
                g.points.push_back(world.applyPoint(corner + s.axes[0] * u.x + s.axes[1] * u.y + s.axes[2] * u.z));
            }
            break;
        }
    }
    return g;
}

MeasureResult measureSamplers(const PathTracer& tracer, const MeasureOptions& options) {
    const EmbreeScene& rt = tracer.rayTracer();
    const Scene& scene = rt.scene();
    MeasureResult result;
    std::vector<SamplerGeometry> geometry;
    std::vector<WorkItem> items;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const LightSamplerSpec& s = scene.samplers[k];
        geometry.push_back(samplerGeometry(s, s.entity >= 0 ? rt.worldFromEntity(s.entity) : Transform()));
        int count = s.type == LightSamplerType::Directional ? s.strata * s.strata : int(geometry.back().points.size());
        for (int i = 0; i < count; ++i) items.push_back({int(k), i});
    }
    std::vector<double> mean(items.size()), error(items.size());
    std::vector<RayStats> stats(items.size());
    const int paths = std::max(1, options.pathsPerPoint);

    auto measureItem = [&](size_t index) {
        const WorkItem& item = items[index];
        const LightSamplerSpec& spec = scene.samplers[item.sampler];
        const SamplerGeometry& g = geometry[item.sampler];
        double sum = 0, sumSq = 0;
        for (int path = 0; path < paths; ++path) {
            Rng rng(hashValues({options.seed, uint64_t(item.sampler), uint64_t(item.point), uint64_t(path)}));
            double x = 0;
            switch (spec.type) {
                case LightSamplerType::Planar:
                    x = tracer.illuminanceSample(g.points[item.point], g.normal, rng, stats[index]);
                    break;
                case LightSamplerType::Volume:
                    x = tracer.sphericalLuminanceSample(g.points[item.point], rng, stats[index]);
                    break;
                case LightSamplerType::Directional: {
                    // A direction spread uniformly over the stratum's cell of the image plane.
                    int i = item.point % g.strata, j = item.point / g.strata;
                    double a = (-1 + 2 * (i + rng.uniform()) / g.strata) * g.tanHalfFov;
                    double b = (-1 + 2 * (j + rng.uniform()) / g.strata) * g.tanHalfFov;
                    Vec3 d = normalize(g.forward + g.right * a + g.up * b);
                    x = tracer.radianceSample({g.points[0], d}, rng, stats[index]);
                    break;
                }
            }
            sum += x;
            sumSq += x * x;
        }
        mean[index] = sum / paths;
        double variance = std::max(0.0, sumSq / paths - mean[index] * mean[index]) * paths / std::max(1, paths - 1);
        error[index] = std::sqrt(variance / paths);
    };
    auto run = [&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, items.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i != r.end(); ++i) measureItem(i);
        });
    };
    if (options.threads > 0) tbb::task_arena(options.threads).execute(run);
    else run();

    // Reduce per sampler, in a fixed order.
    result.samplers.resize(scene.samplers.size());
    for (size_t i = 0; i < items.size(); ++i) {
        SamplerResult& r = result.samplers[items[i].sampler];
        r.points.push_back(mean[i]);
        r.pointErrors.push_back(error[i]);
        result.rays += stats[i];
    }
    result.paths = uint64_t(items.size()) * paths;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        SamplerResult& r = result.samplers[k];
        if (r.points.empty()) continue;
        if (scene.samplers[k].type == LightSamplerType::Directional) {
            size_t best = 0;
            for (size_t i = 1; i < r.points.size(); ++i)
                if (r.points[i] > r.points[best]) best = i;
            r.value = r.points[best];
            r.standardError = r.pointErrors[best];
        } else {
            double sum = 0, var = 0;
            for (size_t i = 0; i < r.points.size(); ++i) sum += r.points[i], var += r.pointErrors[i] * r.pointErrors[i];
            r.value = sum / r.points.size();
            r.standardError = std::sqrt(var) / r.points.size();
        }
        const LightSamplerSpec& spec = scene.samplers[k];
        r.penalty = penalty(r.value, spec.targetMin, spec.targetMax, spec.tolerance, /*alpha=*/1.0);  // Eq. 3
    }
    return result;
}

}  // namespace luxplan
