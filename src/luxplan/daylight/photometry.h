// Photometry and colour for the daylight models: CIE 1931 colour matching functions
// (V(lambda) = y-bar), spectrum -> XYZ, and CIE xyY/XYZ <-> linear sRGB (Rec. 709 primaries,
// D65 white), whose luminance() (core/math.h) is exactly the Y of XYZ.
// CIE 015:2018 Colorimetry, https://cie.co.at/datatable/cie-1931-colour-matching-functions-2-degree-observer
#pragma once

#include <span>

#include <luxplan/core/math.h>

namespace luxplan {

// Maximum luminous efficacy of radiation for photopic vision, lm/W.
inline constexpr double kLuminousEfficacy = 683.0;

// Wavelength grid of the tabulated spectra: 380..780 nm every 10 nm (41 samples).
inline constexpr double kSpectrumFirstNm = 380.0;
inline constexpr double kSpectrumStepNm = 10.0;
inline constexpr int kSpectrumSamples = 41;

// CIE 1931 2-degree colour matching functions at lambda = 380 + 10 i nm.
double cieXBar(int i);
double cieYBar(int i);  // photopic luminous efficiency V(lambda)
double cieZBar(int i);

// Tristimulus XYZ of a spectrum sampled on the grid above (values[i] at 380 + 10 i nm;
// shorter spans are zero beyond), integrated by the rectangle rule: sum v * cmf * 10 nm.
// Multiply by kLuminousEfficacy to turn a radiometric Y into a photometric one.
Vec3 spectrumToXYZ(std::span<const double> values);

// Linear sRGB (Rec. 709 primaries, D65) <-> CIE XYZ. rgbToXYZ's Y row is core's luminance().
Vec3 xyzToRGB(const Vec3& xyz);
Vec3 rgbToXYZ(const Vec3& rgb);
// Colour of chromaticity (x, y) and luminance Y as linear sRGB; luminance(result) == Y.
Vec3 xyYToRGB(double x, double y, double Y);
// Clamps negative (out-of-gamut) components to 0 and rescales so that the luminance is kept.
Vec3 clampToGamut(const Vec3& rgb);

}  // namespace luxplan
