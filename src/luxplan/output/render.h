// Path-traced perspective pictures: per-pixel jittered luminance samples from the
// photometric path tracer, coloured by what each pixel sees and tone mapped to 8-bit
// sRGB; the same view in false colour of luminance with a cd/m2 legend; and a
// side-by-side helper for "initial vs optimized".
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <luxplan/output/denoise.h>
#include <luxplan/output/false_color.h>
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
    bool color = true;      // colour by what each pixel sees (seenColor); false: grey
    // Once true, rows not yet begun stay black (the caller discards the image).
    const std::atomic<bool>* cancel = nullptr;
    // Counts the rows traced so far (for a progress line), if set.
    std::atomic<int>* rowsDone = nullptr;
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
    // With RenderOptions::color: per pixel the colour (linear sRGB, luminance 1) of what
    // it sees, weighted over its samples by their luminance; empty: grey.
    std::vector<Vec3> chroma;
};

// The colour (linear sRGB scaled to luminance 1) of what a camera ray sees first: a
// surface's reflectance (a glossy one's base plus its coat), a luminaire's black body
// at its cct_k, or the sky, sun and ground of the daylight (white at night). Glass is
// looked through and mirrors along, up to 8 surfaces. The path tracer carries
// luminance only, so this colours a pixel by its first visible surface: the hue of
// interreflected and of coloured light is not rendered (a deliberate simplification,
// docs/outputs.md).
Vec3 seenColor(const PathTracer& tracer, Ray ray);

// Each pixel averages samplesPerPixel radianceSample()s through jittered positions in
// the pixel, seeded from (seed, tag, pixel, sample).
LuminanceImage renderLuminance(const PathTracer& tracer, const Camera& camera, const RenderOptions& options = {});

// Reinhard's key: 0.18 / the log-average luminance (Reinhard et al. 2002); 1 for a black image.
double autoExposure(const LuminanceImage& image);

// Reinhard's extended curve L (1 + L / W^2) / (1 + L) on L = exposure x luminance, with
// the white point W = 1.5 (about 8x the log-average luminance under autoExposure, so bright
// windows reach white), then the sRGB transfer curve. With `chroma`, each pixel is its
// colour at the tone-mapped luminance (channels clipped at 1); without, grey.
Image toneMap(const LuminanceImage& image, double exposure);

// A scale for luminance pictures: logarithmic over four decades up to a round number
// at or above the 99.5th percentile, so luminaires and windows are told apart from the
// surfaces they light.
FalseColor luminanceFalseColor(const LuminanceImage& image);

// Luminance in false colour (as Radiance's falsecolor), with its legend in cd/m2 on
// the right.
Image falseColorView(const LuminanceImage& image, const FalseColor& scale);

// What the camera sees at each pixel's centre: first hit, normal, material (the guide
// of the denoiser).
GuideBuffer cameraGuide(const EmbreeScene& rt, const Camera& camera, int width, int height);

// renderLuminance, then denoiseLuminance unless options.denoise is off.
LuminanceImage renderView(const PathTracer& tracer, const Camera& camera, const RenderOptions& options = {});

// renderView and toneMap (exposure from the options, or autoExposure).
Image renderPerspective(const PathTracer& tracer, const Camera& camera, const RenderOptions& options = {});

// The two images next to each other on white, each with its label above (heights may differ).
Image sideBySide(const Image& a, const Image& b, const std::string& labelA = "initial",
                 const std::string& labelB = "optimized");

}  // namespace luxplan
