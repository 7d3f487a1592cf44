// Path-traced perspective pictures: per-pixel jittered luminance samples from the
// photometric path tracer, tone mapped to 8-bit grey, and a side-by-side helper for
// "initial vs optimized".
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <luxplan/output/denoise.h>
#include <luxplan/output/image.h>
#include <luxplan/pathtracer/path_tracer.h>

namespace luxplan {

struct Camera {
    Vec3 position{0, 0, 1.6};
    Vec3 lookAt{1, 0, 1.6};
    Vec3 up{0, 0, 1};
    double fovDeg = 65;  // vertical field of view
};

// From `eye` towards `target` (distinct points), with +z up unless the view is
// vertical (then +y is up in the picture).
Camera lookingAt(Vec3 eye, Vec3 target, double fovDeg);

// From high in the corner of the room nearest its south-west (x, y minimal), looking at
// the opposite lower corner; for scenes without a room shell, from outside the bounds
// of all geometry.
Camera defaultCamera(const Scene& scene);

struct RenderOptions {
    int width = 480, height = 360;
    int samplesPerPixel = 8;  // the demo office: ~6 s on 2 cores
    uint64_t seed = 1;
    double exposure = 0;    // multiplies luminance before the tone curve; 0: automatic
    bool denoise = true;    // renderPerspective: edge-avoiding à-trous filter (denoise.h)
    // Once true, rows not yet begun stay black (the caller discards the image).
    const std::atomic<bool>* cancel = nullptr;
};

// Luminance (cd/m^2) per pixel, row-major, top row first.
struct LuminanceImage {
    int width = 0, height = 0;
    std::vector<double> values;
    // renderLuminance only: the variance of each pixel's mean, and the part of the mean
    // from samples whose camera ray hits a luminaire (the denoiser leaves it out, so that
    // a lamp's edge stays sharp and its light does not spread over the ceiling). Both
    // exclude the emitter samples.
    std::vector<double> variance, emitters;
};

// Each pixel averages samplesPerPixel radianceSample()s through jittered positions in
// the pixel, seeded from (seed, tag, pixel, sample).
LuminanceImage renderLuminance(const PathTracer& tracer, const Camera& camera, const RenderOptions& options = {});

// Reinhard's key: 0.18 / the log-average luminance (Reinhard et al. 2002); 1 for a black image.
double autoExposure(const LuminanceImage& image);

// Reinhard's extended curve L (1 + L / W^2) / (1 + L) on L = exposure x luminance, with
// the white point W = 1.5 (about 8x the log-average luminance under autoExposure, so bright
// windows reach white), then the sRGB transfer curve. The pixels are grey: the path tracer
// carries luminance only, no colour.
Image toneMap(const LuminanceImage& image, double exposure);

// What the camera sees at each pixel's centre: first hit, normal, material (the guide
// of the denoiser).
GuideBuffer cameraGuide(const EmbreeScene& rt, const Camera& camera, int width, int height);

// renderLuminance, denoiseLuminance (unless options.denoise is off) and toneMap
// (exposure from the options, or autoExposure).
Image renderPerspective(const PathTracer& tracer, const Camera& camera, const RenderOptions& options = {});

// The two images next to each other on white, each with its label above (heights may differ).
Image sideBySide(const Image& a, const Image& b, const std::string& labelA = "initial",
                 const std::string& labelB = "optimized");

}  // namespace luxplan
