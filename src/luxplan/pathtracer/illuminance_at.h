// Illuminance at given points: the plan's work plane (output/plan.h) and the planned
// start's empty room (optimizer/path_traced_lighting.h) both measure a grid this way.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {

struct PointIlluminance {
    std::vector<double> values;  // lx, one per point
    std::vector<double> errors;  // the standard error of each
};

// Illuminance (lx) at each point over the hemisphere around the unit `normal`, from
// `paths` samples each (at least 1), each seeded from (seed, tag, point, path): results
// do not depend on the thread count.
PointIlluminance illuminanceAt(const PathTracer& tracer, const std::vector<Vec3>& points, const Vec3& normal, int paths,
                               uint64_t seed, uint64_t tag);

}  // namespace luxplan
