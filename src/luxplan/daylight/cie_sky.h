// CIE skies: the standard overcast sky (Moon & Spencer 1942, CIE S 003), a uniform sky,
// and the 15 CIE standard general skies (ISO 15469:2004 / CIE S 011/E:2003,
// https://cie.co.at/publications/spatial-distribution-daylight-cie-standard-general-sky).
// Luminance in cd/m^2; directions are unit vectors with +z the zenith.
#pragma once

#include <luxplan/core/math.h>

namespace luxplan {

// CIE standard overcast sky L(theta) = Lz (1 + 2 cos theta) / 3, scaled so that the open
// horizontal plane receives `horizontalIlluminanceLx`: Lz = 9 E_h / (7 pi).
// An open vertical plane then receives E_v = Lz (pi/6 + 4/9) = 0.396 E_h.
class CieOvercastSky {
public:
    explicit CieOvercastSky(double horizontalIlluminanceLx);
    double zenithLuminance() const { return zenith_; }
    double luminance(const Vec3& w) const;  // w.z clamped to [0, 1]

private:
    double zenith_;
};

// The same luminance in every direction above the horizon: E_h = pi L.
class UniformSky {
public:
    explicit UniformSky(double luminance) : luminance_(luminance) {}
    double luminance(const Vec3&) const { return luminance_; }

private:
    double luminance_;
};

// ISO 15469 general sky of type 1..15: relative luminance
//   L / Lz = f(chi) phi(Z) / (f(Z_s) phi(0)),
//   phi(Z) = 1 + a exp(b / cos Z)   (gradation; phi = 1 at the horizon),
//   f(chi) = 1 + c (exp(d chi) - exp(d pi / 2)) + e cos^2 chi   (scattering indicatrix),
// with Z the zenith angle of the view direction, chi its angle to the sun and Z_s the sun's
// zenith angle. Lz is chosen so that the open horizontal plane receives `horizontalIlluminanceLx`
// (the sky alone, without the sun), integrated numerically at construction.
struct CieGeneralSkyParameters {
    double a, b, c, d, e;
};
CieGeneralSkyParameters cieGeneralSkyParameters(int type);  // type in [1, 15]

class CieGeneralSky {
public:
    CieGeneralSky(int type, const Vec3& sunDirection, double horizontalIlluminanceLx);
    double zenithLuminance() const { return zenith_; }
    double relativeLuminance(const Vec3& w) const;  // L / Lz
    double luminance(const Vec3& w) const { return zenith_ * relativeLuminance(w); }

private:
    CieGeneralSkyParameters p_;
    Vec3 sun_;
    double norm_ = 1;  // 1 / (f(Z_s) phi(0))
    double zenith_ = 0;
};

}  // namespace luxplan
