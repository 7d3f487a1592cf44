// The paper's three light samplers (section 4), measured by the path tracer:
// planar (illuminance at grid points), directional (max over strata of the mean
// luminance in a pyramidal frustum) and volume (mean spherical luminance at points
// in an oriented box). Samplers on entities follow the layout.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {

// Where one sampler measures, in world space for the current layout.
struct SamplerGeometry {
    std::vector<Vec3> points;   // planar/volume points; for directional, the apex once
    Vec3 normal;                // planar
    Vec3 forward, right, up;    // directional frame
    double tanHalfFov = 0;
    int strata = 0;
};

SamplerGeometry samplerGeometry(const LightSamplerSpec& spec, const Transform& worldFromEntity);

struct SamplerResult {
    double value = 0;              // lx (planar) or cd/m^2
    double standardError = 0;      // of `value`, from the per-point sample variances
    std::vector<double> points;    // per point (planar: row-major over grid; volume: per point)
                                   // or per stratum (directional: row-major, right fastest, bottom row first)
    std::vector<double> pointErrors;
    double penalty = 0;            // Eq. 2 with alpha = 1 and the sampler's tolerance
};

struct MeasureOptions {
    int pathsPerPoint = 1000;
    uint64_t seed = 1;
    int threads = 0;  // 0: all cores
};

struct MeasureResult {
    std::vector<SamplerResult> samplers;  // in Scene::samplers order
    RayStats rays;
    uint64_t paths = 0;
};

// Measures every sampler of the scene for the path tracer's current layout. Each path is
// seeded from (seed, sampler, point, path), so results do not depend on the thread count.
MeasureResult measureSamplers(const PathTracer& tracer, const MeasureOptions& options);

}  // namespace luxplan
