// Preetham sky (Perez + zenith fits) and sun (spectral attenuation of PSS99's appendix).
#include <luxplan/daylight/preetham.h>

#include <algorithm>
#include <span>

#include <luxplan/daylight/photometry.h>

namespace luxplan {
namespace {

// PSS99 appendix: spectral radiance of the sun outside the atmosphere, 380..750 nm every
// 10 nm. The paper tabulates these in units of 100 W m^-2 sr^-1 nm^-1 (values 165.5 ...); scaled
// here to W m^-2 sr^-1 nm^-1, which gives the solar illuminance constant (~128 klx).
constexpr double kSolarRadiance[kSunSpectrumSamples] = {
    16559.0, 16233.7, 21127.5, 25888.2, 25829.1, 24232.3, 26760.5, 29658.3, 30545.4, 30057.5,
    30663.7, 28830.4, 28712.1, 27825.0, 27100.6, 27233.6, 26361.3, 25503.8, 25060.2, 25311.6,
    25355.9, 25134.2, 24631.5, 24173.2, 23685.3, 23212.1, 22827.7, 22339.8, 21970.2, 21526.7,
    21097.9, 20728.3, 20240.4, 19870.8, 19427.2, 19072.4, 18628.9, 18259.2,
};

// Absorption coefficients (cm^-1) from Iqbal, "An Introduction to Solar Radiation" (1983),
// as listed in PSS99's appendix: (wavelength nm, k).
struct Absorption {
    double nm, k;
};
constexpr Absorption kOzone[] = {
    {300, 10.0}, {305, 4.8}, {310, 2.7}, {315, 1.35}, {320, 0.8}, {325, 0.38}, {330, 0.16},
    {335, 0.075}, {340, 0.04}, {345, 0.019}, {350, 0.007}, {355, 0.0}, {445, 0.003}, {450, 0.003},
    {455, 0.004}, {460, 0.006}, {465, 0.008}, {470, 0.009}, {475, 0.012}, {480, 0.014}, {485, 0.017},
    {490, 0.021}, {495, 0.025}, {500, 0.03}, {505, 0.035}, {510, 0.04}, {515, 0.045}, {520, 0.048},
    {525, 0.057}, {530, 0.063}, {535, 0.07}, {540, 0.075}, {545, 0.08}, {550, 0.085}, {555, 0.095},
    {560, 0.103}, {565, 0.11}, {570, 0.12}, {575, 0.122}, {580, 0.12}, {585, 0.118}, {590, 0.115},
    {595, 0.12}, {600, 0.125}, {605, 0.13}, {610, 0.12}, {620, 0.105}, {630, 0.09}, {640, 0.079},
    {650, 0.067}, {660, 0.057}, {670, 0.048}, {680, 0.036}, {690, 0.028}, {700, 0.023}, {710, 0.018},
    {720, 0.014}, {730, 0.011}, {740, 0.01}, {750, 0.009}, {760, 0.007}, {770, 0.004}, {780, 0.0},
    {790, 0.0},
};
constexpr Absorption kMixedGas[] = {{759, 0.0}, {760, 3.0}, {770, 0.21}, {771, 0.0}};
constexpr Absorption kWaterVapour[] = {
    {689, 0.0}, {690, 0.016}, {700, 0.024}, {710, 0.0125}, {720, 1.0}, {730, 0.87}, {740, 0.061},
    {750, 0.001}, {760, 0.00001}, {770, 0.00001}, {780, 0.0006}, {790, 0.0175}, {800, 0.036},
};

// Linear interpolation in a table; 0 outside it.
double interpolate(std::span<const Absorption> table, double nm) {
    if (nm < table.front().nm || nm > table.back().nm) return 0;
    for (size_t i = 0; i + 1 < table.size(); ++i)
        if (nm <= table[i + 1].nm) {
            double t = (nm - table[i].nm) / (table[i + 1].nm - table[i].nm);
            return table[i].k + t * (table[i + 1].k - table[i].k);
        }
    return table.back().k;
}

constexpr double kOzoneThicknessCm = 0.35;
constexpr double kWaterVapourCm = 2.0;
constexpr double kAngstromAlpha = 1.3;

double clampedZenith(const Vec3& sun) { return std::acos(std::clamp(sun.z, 0.0, 1.0)); }

}  // namespace

double PerezCoefficients::gradation(double cosTheta) const {
    // Directions at or below the horizon are evaluated at the horizon (B < 0 makes the
    // exponential vanish there); the small floor avoids 0/0.
    return 1 + a * std::exp(b / std::max(cosTheta, 1e-6));
}

PerezCoefficients preethamPerezY(double t) {
    return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
            -0.0670 * t + 0.3703};
}
PerezCoefficients preethamPerezX(double t) {
    return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
            -0.0033 * t + 0.0452};
}
PerezCoefficients preethamPerezYChromaticity(double t) {
    return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
            -0.0109 * t + 0.0529};
}

double preethamZenithLuminance(double t, double sunZenith) {
    double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2 * sunZenith);
    return 1000.0 * ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192);
}

Vec2 preethamZenithChromaticity(double t, double th) {
    double th2 = th * th, th3 = th2 * th, t2 = t * t;
    double x = t2 * (0.00166 * th3 - 0.00375 * th2 + 0.00209 * th) +
               t * (-0.02903 * th3 + 0.06377 * th2 - 0.03202 * th + 0.00394) +
               (0.11693 * th3 - 0.21196 * th2 + 0.06052 * th + 0.25886);
    double y = t2 * (0.00275 * th3 - 0.00610 * th2 + 0.00317 * th) +
               t * (-0.04214 * th3 + 0.08970 * th2 - 0.04153 * th + 0.00516) +
               (0.15346 * th3 - 0.26756 * th2 + 0.06670 * th + 0.26688);
    return {x, y};
}

PreethamSky::PreethamSky(double turbidity, const Vec3& sunDirection)
    : sun_(normalize(sunDirection)),
      perezY_(preethamPerezY(turbidity)),
      perezX_(preethamPerezX(turbidity)),
      perezYc_(preethamPerezYChromaticity(turbidity)) {
    double thetaS = clampedZenith(sun_);
    zenithY_ = preethamZenithLuminance(turbidity, thetaS);
    Vec2 c = preethamZenithChromaticity(turbidity, thetaS);
    zenithX_ = c.x;
    zenithYc_ = c.y;
    // Normalise each channel so that it equals its zenith value at the zenith: F(0, theta_s).
    normY_ = zenithY_ / perezY_(1.0, thetaS);
    normX_ = zenithX_ / perezX_(1.0, thetaS);
    normYc_ = zenithYc_ / perezYc_(1.0, thetaS);
}

PreethamSky::Row PreethamSky::row(double cosTheta) const {
    Row r;
    r.sky_ = this;
    r.x_ = normX_ * perezX_.gradation(cosTheta);
    r.yc_ = normYc_ * perezYc_.gradation(cosTheta);
    r.y_ = normY_ * perezY_.gradation(cosTheta);
    return r;
}

Vec3 PreethamSky::Row::xyY(const Vec3& w) const {
    const double cg = std::clamp(dot(w, sky_->sun_), -1.0, 1.0), gamma = std::acos(cg);
    return {x_ * sky_->perezX_.indicatrix(gamma, cg), yc_ * sky_->perezYc_.indicatrix(gamma, cg),
            y_ * sky_->perezY_.indicatrix(gamma, cg)};
}

Vec3 PreethamSky::Row::rgb(const Vec3& w) const {
    Vec3 c = xyY(w);
    return clampToGamut(xyYToRGB(c.x, c.y, c.z));
}

double PreethamSky::luminance(const Vec3& w) const {
    const double cg = std::clamp(dot(w, sun_), -1.0, 1.0);
    return normY_ * perezY_.gradation(w.z) * perezY_.indicatrix(std::acos(cg), cg);
}

Vec3 PreethamSky::xyY(const Vec3& w) const { return row(w.z).xyY(w); }

Vec3 PreethamSky::rgb(const Vec3& w) const { return row(w.z).rgb(w); }

double relativeAirMass(double sunZenith) {
    double deg = degrees(sunZenith);
    return 1.0 / (std::cos(sunZenith) + 0.15 * std::pow(93.885 - deg, -1.253));
}

std::array<double, kSunSpectrumSamples> preethamSunSpectralRadiance(double turbidity, double m) {
    std::array<double, kSunSpectrumSamples> out{};
    const double beta = 0.04608 * turbidity - 0.04586;
    for (int i = 0; i < kSunSpectrumSamples; ++i) {
        const double nm = kSpectrumFirstNm + kSpectrumStepNm * i;
        const double um = nm / 1000.0;
        const double tauRayleigh = std::exp(-0.008735 * std::pow(um, -4.08) * m);
        const double tauAerosol = std::exp(-beta * std::pow(um, -kAngstromAlpha) * m);
        const double tauOzone = std::exp(-interpolate(kOzone, nm) * kOzoneThicknessCm * m);
        const double kg = interpolate(kMixedGas, nm);
        const double tauGas = std::exp(-1.41 * kg * m / std::pow(1 + 118.93 * kg * m, 0.45));
        const double kwa = interpolate(kWaterVapour, nm);
        const double tauWater =
            std::exp(-0.2385 * kwa * kWaterVapourCm * m / std::pow(1 + 20.07 * kwa * kWaterVapourCm * m, 0.45));
        out[i] = kSolarRadiance[i] * tauRayleigh * tauAerosol * tauOzone * tauGas * tauWater;
    }
    return out;
}

namespace {
double sunIlluminanceFromSpectrum(const std::array<double, kSunSpectrumSamples>& radiance) {
    // Luminance of the disk (cd/m^2) times its projected solid angle at normal incidence.
    double luminanceDisk = kLuminousEfficacy * spectrumToXYZ(radiance).y;
    return luminanceDisk * kSunDiskProjectedSolidAngle;
}
}  // namespace

double preethamSunNormalIlluminance(double turbidity, double sunZenith) {
    if (sunZenith >= kPi / 2) return 0;
    return sunIlluminanceFromSpectrum(preethamSunSpectralRadiance(turbidity, relativeAirMass(sunZenith)));
}

double extraterrestrialSunIlluminance() { return sunIlluminanceFromSpectrum(preethamSunSpectralRadiance(0, 0)); }

Vec3 preethamSunColor(double turbidity, double sunZenith) {
    double m = relativeAirMass(std::min(sunZenith, kPi / 2));
    Vec3 xyz = spectrumToXYZ(preethamSunSpectralRadiance(turbidity, m));
    if (xyz.y <= 0) return {1, 1, 1};
    return clampToGamut(xyzToRGB(xyz / xyz.y));
}

}  // namespace luxplan
