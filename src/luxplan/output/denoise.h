// Edge-avoiding à-trous filtering of a path-traced luminance image (Dammertz et al.
// 2010, with the variance-guided luminance weight of Schied et al. 2017, SVGF): five
// passes of a 5 x 5 B3-spline kernel with holes (steps 1, 2, 4, 8, 16 pixels), each tap
// weighted by whether it sees the same surface (material), the same plane (normal and
// distance off the plane) and a luminance within a few standard deviations of the
// pixel's own noise. Flat regions lose their noise; edges between objects, materials
// and shadow boundaries above the noise level stay. For pictures only: the sampler
// measurements never go through it.
#pragma once

#include <cstdint>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

// What the camera sees at each pixel's centre (row-major, top row first).
struct GuideBuffer {
    int width = 0, height = 0;
    std::vector<Vec3> position;    // first hit (world)
    std::vector<Vec3> normal;      // unit, facing the camera
    std::vector<int32_t> surface;  // material index of the first hit; -1: nothing hit (left as is)
};

struct DenoiseOptions {
    int passes = 5;
    double normalPower = 64;       // weight max(0, n_p . n_q)^power
    double planeTolerance = 0.02;  // m off the pixel's plane per metre of its distance from the camera
    double luminanceSigma = 4;     // standard deviations of the pixel's noise
};

// Filters `luminance` (per pixel mean) in place; `variance` is the variance of each
// pixel's mean (sample variance / samples), filtered along with it.
void denoiseLuminance(std::vector<double>& luminance, std::vector<double> variance, const GuideBuffer& guide,
                      const Vec3& cameraPosition, const DenoiseOptions& options = {});

}  // namespace luxplan
