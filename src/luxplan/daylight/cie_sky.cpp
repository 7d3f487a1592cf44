// CIE overcast, uniform and ISO 15469 general skies.
#include <luxplan/daylight/cie_sky.h>

#include <stdexcept>
#include <string>

namespace luxplan {
namespace {

// Gradation groups I..VI (a, b) and indicatrix groups 1..6 (c, d, e) of ISO 15469 Table 1.
constexpr double kGradation[6][2] = {{4.0, -0.70}, {1.1, -0.8}, {0.0, -1.0}, {-1.0, -0.55}, {-1.0, -0.32}, {-1.0, -0.15}};
constexpr double kIndicatrix[6][3] = {{0, -1.0, 0}, {2, -1.5, 0.15}, {5, -2.5, 0.30},
                                      {10, -3.0, 0.45}, {16, -3.0, 0.30}, {24, -2.8, 0.15}};
// Sky type 1..15 -> (gradation group, indicatrix group), zero-based.
constexpr int kTypeGroups[15][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {2, 3},
                                    {3, 1}, {3, 2}, {3, 3}, {4, 3}, {4, 4}, {5, 4}, {5, 5}};

}  // namespace

CieOvercastSky::CieOvercastSky(double horizontalIlluminanceLx) : zenith_(9 * horizontalIlluminanceLx / (7 * kPi)) {}

double CieOvercastSky::luminance(const Vec3& w) const {
    return zenith_ * (1 + 2 * std::clamp(w.z, 0.0, 1.0)) / 3;
}

CieGeneralSkyParameters cieGeneralSkyParameters(int type) {
    if (type < 1 || type > 15)
        throw std::invalid_argument("CIE general sky type " + std::to_string(type) + " outside [1, 15]");
    const double* g = kGradation[kTypeGroups[type - 1][0]];
    const double* f = kIndicatrix[kTypeGroups[type - 1][1]];
    return {g[0], g[1], f[0], f[1], f[2]};
}

CieGeneralSky::CieGeneralSky(int type, const Vec3& sunDirection, double horizontalIlluminanceLx)
    : p_(cieGeneralSkyParameters(type)), sun_(normalize(sunDirection)) {
    const double zs = std::acos(std::clamp(sun_.z, 0.0, 1.0));
    const double fs = 1 + p_.c * (std::exp(p_.d * zs) - std::exp(p_.d * kPi / 2)) + p_.e * std::cos(zs) * std::cos(zs);
    const double phi0 = 1 + p_.a * std::exp(p_.b);
    norm_ = 1 / (fs * phi0);
    // Horizontal illuminance of the relative distribution: midpoint rule in (cos theta, phi),
    // where cells have equal solid angle; 128 x 256 cells resolve the circumsolar peak.
    const int nz = 128, nphi = 256;
    double sum = 0;
    for (int i = 0; i < nz; ++i) {
        double z = (i + 0.5) / nz, r = std::sqrt(1 - z * z);
        for (int j = 0; j < nphi; ++j) {
            double phi = 2 * kPi * (j + 0.5) / nphi;
            sum += relativeLuminance({r * std::cos(phi), r * std::sin(phi), z}) * z;
        }
    }
    const double relativeIlluminance = sum * (1.0 / nz) * (2 * kPi / nphi);
    zenith_ = horizontalIlluminanceLx / relativeIlluminance;
}

double CieGeneralSky::relativeLuminance(const Vec3& w) const {
    const double cz = std::clamp(w.z, 1e-6, 1.0);
    const double chi = std::acos(std::clamp(dot(w, sun_), -1.0, 1.0));
    const double gradation = 1 + p_.a * std::exp(p_.b / cz);
    const double indicatrix =
        1 + p_.c * (std::exp(p_.d * chi) - std::exp(p_.d * kPi / 2)) + p_.e * std::cos(chi) * std::cos(chi);
    return indicatrix * gradation * norm_;
}

}  // namespace luxplan
