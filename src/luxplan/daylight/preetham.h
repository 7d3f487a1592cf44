// Preetham, Shirley & Smits (1999) "A Practical Analytic Model for Daylight", SIGGRAPH 99,
// https://doi.org/10.1145/311535.311545: clear-sky luminance and chromaticity from turbidity
// (Perez distribution with turbidity-linear coefficients) and the sun's spectral attenuation
// (appendix) giving the direct normal illuminance. Formulas: the paper and its appendix (docs/daylight.md).
// Directions are unit vectors with +z the zenith; angles in radians unless named *Deg.
#pragma once

#include <array>

#include <luxplan/core/math.h>

namespace luxplan {

// The sun's disk: 0.533 deg apparent diameter (mean), its half-angle and solid angle.
inline constexpr double kSunAngularDiameterDeg = 0.533;
inline const double kSunHalfAngle = radians(kSunAngularDiameterDeg / 2);
inline const double kSunCosHalfAngle = std::cos(kSunHalfAngle);
inline const double kSunSolidAngle = 2 * kPi * (1 - std::cos(kSunHalfAngle));  // sr
// Illuminance at normal incidence from a uniform disk of unit luminance: pi sin^2(half-angle).
inline const double kSunDiskProjectedSolidAngle = kPi * std::sin(kSunHalfAngle) * std::sin(kSunHalfAngle);

// Turbidity range accepted (the fit is for 2..6; beyond 10 the zenith luminance turns negative
// near sunset, below ~1.2 the Perez B coefficient turns positive).
inline constexpr double kMinTurbidity = 1.7;
inline constexpr double kMaxTurbidity = 10.0;

// Perez et al. (1993) all-weather distribution
// F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma).
struct PerezCoefficients {
    double a = 0, b = 0, c = 0, d = 0, e = 0;
    double operator()(double cosTheta, double gamma) const { return gradation(cosTheta) * indicatrix(gamma, std::cos(gamma)); }
    // The two factors: zenith-angle (evaluated at cos theta >= 1e-6, i.e. at the horizon for
    // directions at or below it) and sun-angle.
    double gradation(double cosTheta) const;
    double indicatrix(double gamma, double cosGamma) const { return 1 + c * std::exp(d * gamma) + e * cosGamma * cosGamma; }
};
// PSS99 table 2 (paper's 4-decimal values) for luminance Y and chromaticities x, y.
PerezCoefficients preethamPerezY(double turbidity);
PerezCoefficients preethamPerezX(double turbidity);
PerezCoefficients preethamPerezYChromaticity(double turbidity);

// Zenith luminance in cd/m^2 (PSS99 fit is in kcd/m^2; multiplied by 1000 here).
double preethamZenithLuminance(double turbidity, double sunZenith);
// Zenith chromaticity (x, y) of PSS99 appendix A.2.
Vec2 preethamZenithChromaticity(double turbidity, double sunZenith);

// The sky for one sun position. Luminance in cd/m^2, colour as linear sRGB with
// luminance(rgb) == luminance (out-of-gamut colours are clamped, keeping the luminance). Valid above the horizon (directions below are treated as
// horizontal); the sun may be anywhere from the zenith to the horizon.
class PreethamSky {
public:
    PreethamSky(double turbidity, const Vec3& sunDirection);

    double zenithLuminance() const { return zenithY_; }
    double luminance(const Vec3& w) const;
    Vec3 xyY(const Vec3& w) const;  // (x, y, Y)
    Vec3 rgb(const Vec3& w) const;

    // Evaluates directions that share one cos(theta) (a row of a map) with the zenith-angle
    // factors computed once; results equal xyY()/rgb().
    class Row {
    public:
        Vec3 xyY(const Vec3& w) const;
        Vec3 rgb(const Vec3& w) const;

    private:
        friend class PreethamSky;
        const PreethamSky* sky_ = nullptr;
        double x_ = 0, yc_ = 0, y_ = 0;  // normalization x gradation per channel
    };
    Row row(double cosTheta) const;

private:
    Vec3 sun_;
    PerezCoefficients perezY_, perezX_, perezYc_;
    double zenithY_ = 0, zenithX_ = 0, zenithYc_ = 0;
    double normY_ = 0, normX_ = 0, normYc_ = 0;  // zenith value / F(0, theta_s)
};

// Relative optical air mass of PSS99 appendix (Kasten 1966):
// m = 1 / (cos theta + 0.15 (93.885 - theta_deg)^-1.253).
double relativeAirMass(double sunZenith);

// Spectral radiance of the sun's disk after the atmosphere (W m^-2 sr^-1 nm^-1) at
// 380..750 nm every 10 nm: PSS99 appendix extraterrestrial solar radiance attenuated by
// Rayleigh scattering, Angstrom aerosol turbidity (alpha 1.3, beta 0.04608 T - 0.04586),
// ozone (l = 0.35 cm), mixed gases and water vapour (w = 2 cm) along air mass m.
// airMass 0 gives the extraterrestrial spectrum.
inline constexpr int kSunSpectrumSamples = 38;
std::array<double, kSunSpectrumSamples> preethamSunSpectralRadiance(double turbidity, double airMass);

// Direct normal illuminance (lx) of the Preetham sun: 683 lm/W * integral of radiance * V(lambda)
// times the disk's pi sin^2(half-angle). 0 when the sun is at or below the horizon.
double preethamSunNormalIlluminance(double turbidity, double sunZenith);
// The same outside the atmosphere (air mass 0): about 128 klx.
double extraterrestrialSunIlluminance();
// Colour of the attenuated sun as linear sRGB scaled to luminance 1 (clamped to the gamut).
Vec3 preethamSunColor(double turbidity, double sunZenith);

}  // namespace luxplan
