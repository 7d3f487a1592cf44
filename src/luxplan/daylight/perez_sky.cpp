// Perez all-weather sky and Perez 1990 luminous efficacy. The tables are those of the two
// papers as Radiance's gendaylit.c (version 2.6, 2021) carries them; the special cases
// (limits on epsilon and Delta, bin 1's forms, Delta >= 0.2 in bins 2-5, the dark "error
// sky") follow gendaylit. docs/daylight.md, "The Perez all-weather sky".
#include <luxplan/daylight/perez_sky.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace luxplan {
namespace {

constexpr double kSolarConstantWm2 = 1367;  // gendaylit's; Perez 1990 normalises Delta with it
constexpr double kMinEpsilon = 1.0, kMaxEpsilon = 12.01;
constexpr double kMinDelta = 0.01, kMaxDelta = 0.6;
// The model's fits stop at a sun 87 deg high (gendaylit lowers a higher sun to 87 deg).
constexpr double kMinZenithDeg = 3;
// Lower bounds of the clearness bins 2..8 (bin 1 starts at 1).
constexpr double kBinEdges[7] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

// Perez, Seals & Michalsky 1993, Table 1: per bin, for a, b, c, d, e the four numbers
// x1..x4 of x = x1 + x2 Z + Delta (x3 + x4 Z) (bin 1's c and d: see perezCoefficients).
constexpr double kPerez1993[8][5][4] = {
    {{1.3525, -0.2576, -0.2690, -1.4366}, {-0.7670, 0.0007, 1.2734, -0.1233}, {2.8000, 0.6004, 1.2375, 1.0000},
     {1.8734, 0.6297, 0.9738, 0.2809}, {0.0356, -0.1246, -0.5718, 0.9938}},
    {{-1.2219, -0.7730, 1.4148, 1.1016}, {-0.2054, 0.0367, -3.9128, 0.9156}, {6.9750, 0.1774, 6.4477, -0.1239},
     {-1.5798, -0.5081, -1.7812, 0.1080}, {0.2624, 0.0672, -0.2190, -0.4285}},
    {{-1.1000, -0.2515, 0.8952, 0.0156}, {0.2782, -0.1812, -4.5000, 1.1766}, {24.7219, -13.0812, -37.7000, 34.8438},
     {-5.0000, 1.5218, 3.9229, -2.6204}, {-0.0156, 0.1597, 0.4199, -0.5562}},
    {{-0.5484, -0.6654, -0.2672, 0.7117}, {0.7234, -0.6219, -5.6812, 2.6297}, {33.3389, -18.3000, -62.2500, 52.0781},
     {-3.5000, 0.0016, 1.1477, 0.1062}, {0.4659, -0.3296, -0.0876, -0.0329}},
    {{-0.6000, -0.3566, -2.5000, 2.3250}, {0.2937, 0.0496, -5.6812, 1.8415}, {21.0000, -4.7656, -21.5906, 7.2492},
     {-3.5000, -0.1554, 1.4062, 0.3988}, {0.0032, 0.0766, -0.0656, -0.1294}},
    {{-1.0156, -0.3670, 1.0078, 1.4051}, {0.2875, -0.5328, -3.8500, 3.3750}, {14.0000, -0.9999, -7.1406, 7.5469},
     {-3.4000, -0.1078, -1.0750, 1.5702}, {-0.0672, 0.4016, 0.3017, -0.4844}},
    {{-1.0000, 0.0211, 0.5025, -0.5119}, {-0.3000, 0.1922, 0.7023, -1.6317}, {19.0000, -5.0000, 1.2438, -1.9094},
     {-4.0000, 0.0250, 0.3844, 0.2656}, {1.0468, -0.3788, -2.4517, 1.4656}},
    {{-1.0500, 0.0289, 0.4260, 0.3590}, {-0.3250, 0.1156, 0.7781, 0.0025}, {31.0625, -14.5000, -46.1148, 55.3750},
     {-7.2312, 0.4050, 13.3500, 0.6234}, {1.5000, -0.6426, 1.8564, 0.5636}},
};

// Perez et al. 1990, Table 4: per bin a, b, c, d of the luminous efficacies.
constexpr double kGlobalEfficacy[8][4] = {
    {96.63, -0.47, 11.50, -9.16}, {107.54, 0.79, 1.79, -1.19}, {98.73, 0.70, 4.40, -6.95},
    {92.72, 0.56, 8.36, -8.31},   {86.73, 0.98, 7.10, -10.94}, {88.34, 1.39, 6.06, -7.60},
    {78.63, 1.47, 4.93, -11.37},  {99.65, 1.86, -4.46, -3.15}};
constexpr double kDirectEfficacy[8][4] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38}, {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29}};
constexpr double kDiffuseEfficacy[8][4] = {
    {97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},   {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98}};

const double* efficacyRow(const double (&table)[8][4], int bin) { return table[std::clamp(bin, 1, 8) - 1]; }

}  // namespace

double perezAirMass(double zenithDeg) {
    const double z = std::min(zenithDeg, 90.0);
    return 1 / (std::cos(radians(z)) + 0.15 * std::pow(93.885 - z, -1.253));
}

double perezEccentricity(int dayOfYear) {
    const double g = 2 * kPi * (dayOfYear - 1) / 365;
    return 1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2 * g) +
           0.000077 * std::sin(2 * g);
}

double perezPrecipitableWater(double dewPointC) {
    // gendaylit keeps its default (W = 2 cm, Td = 10.97 C) outside [-40, 40] C.
    if (!(dewPointC >= -40 && dewPointC <= 40)) return 2.0;
    return std::exp(0.07 * dewPointC - 0.075);
}

double perezClearness(double directNormalWm2, double diffuseHorizontalWm2, double zenithDeg) {
    const double z = radians(zenithDeg), k = 1.041 * z * z * z;
    if (!(diffuseHorizontalWm2 > 0)) return directNormalWm2 > 0 ? std::numeric_limits<double>::infinity() : 1.0;
    return ((diffuseHorizontalWm2 + directNormalWm2) / diffuseHorizontalWm2 + k) / (1 + k);
}

double perezBrightness(double diffuseHorizontalWm2, double zenithDeg, int dayOfYear) {
    return diffuseHorizontalWm2 * perezAirMass(zenithDeg) / (kSolarConstantWm2 * perezEccentricity(dayOfYear));
}

int perezClearnessBin(double epsilon) {
    int bin = 1;
    for (double edge : kBinEdges) bin += epsilon >= edge;
    return bin;
}

std::array<double, 5> perezCoefficients(int bin, double zenithRad, double delta) {
    bin = std::clamp(bin, 1, 8);
    // gendaylit's correction ("correction de modele de Perez solar energy"): in bins 2-5 a
    // brightness below 0.2 is outside the fit and gives unphysical skies.
    if (bin >= 2 && bin <= 5) delta = std::max(delta, 0.2);
    const double z = zenithRad;
    auto linear = [&](const double* x) { return x[0] + x[1] * z + delta * (x[2] + x[3] * z); };
    const auto& t = kPerez1993[bin - 1];
    std::array<double, 5> k{linear(t[0]), linear(t[1]), linear(t[2]), linear(t[3]), linear(t[4])};
    if (bin == 1) {  // the paper's own forms for the overcast bin
        k[2] = std::exp(std::pow(delta * (t[2][0] + t[2][1] * z), t[2][2])) - t[2][3];
        k[3] = -std::exp(delta * (t[3][0] + t[3][1] * z)) + t[3][2] + delta * t[3][3];
    }
    return k;
}

double perezDiffuseEfficacy(int bin, double w, double zenithDeg, double delta) {
    const double* r = efficacyRow(kDiffuseEfficacy, bin);
    return r[0] + r[1] * w + r[2] * std::cos(radians(zenithDeg)) + r[3] * std::log(delta);
}

double perezGlobalEfficacy(int bin, double w, double zenithDeg, double delta) {
    const double* r = efficacyRow(kGlobalEfficacy, bin);
    return r[0] + r[1] * w + r[2] * std::cos(radians(zenithDeg)) + r[3] * std::log(delta);
}

double perezDirectEfficacy(int bin, double w, double zenithDeg, double delta) {
    const double* r = efficacyRow(kDirectEfficacy, bin);
    return std::max(0.0, r[0] + r[1] * w + r[2] * std::exp(5.73 * radians(zenithDeg) - 5) + r[3] * delta);
}

double perezRelativeLuminance(const std::array<double, 5>& k, double cosTheta, double gamma) {
    const double ct = std::max(cosTheta, 1e-6);
    const double cg = std::cos(gamma);
    // A few (epsilon, Delta, Z) give a negative value somewhere; luminance cannot be.
    return std::max(0.0, (1 + k[0] * std::exp(k[1] / ct)) * (1 + k[2] * std::exp(k[3] * gamma) + k[4] * cg * cg));
}

PerezSkyCondition perezSkyCondition(const PerezSkyInput& in) {
    PerezSkyCondition c;
    c.precipitableWaterCm = perezPrecipitableWater(in.dewPointC);
    const double dn = std::max(0.0, in.directNormalWm2), dh = std::max(0.0, in.diffuseHorizontalWm2);
    c.zenithDeg = std::max(in.sunZenithDeg, kMinZenithDeg);
    // gendaylit's dark sky: the sun down, nothing measured, or a direct beam above the solar constant.
    if (!(in.sunZenithDeg < 90) || !(dn + dh > 0) || dn > kSolarConstantWm2) return c;

    c.epsilon = std::clamp(perezClearness(dn, dh, c.zenithDeg), kMinEpsilon, kMaxEpsilon - 0.001);
    c.delta = std::clamp(perezBrightness(dh, c.zenithDeg, in.dayOfYear), kMinDelta, kMaxDelta);
    c.bin = perezClearnessBin(c.epsilon);
    c.diffuseEfficacy = perezDiffuseEfficacy(c.bin, c.precipitableWaterCm, c.zenithDeg, c.delta);
    c.directEfficacy = perezDirectEfficacy(c.bin, c.precipitableWaterCm, c.zenithDeg, c.delta);
    c.diffuseHorizontalLx = std::max(0.0, dh * c.diffuseEfficacy);
    c.directNormalLx = std::max(0.0, dn * c.directEfficacy);
    c.coefficients = perezCoefficients(c.bin, radians(c.zenithDeg), c.delta);
    // A positive b makes the gradation term grow without bound towards the horizon. gendaylit
    // prints a dark sky then; we keep the hour's diffuse light with a flat gradation (b = 0).
    // It does not occur in Chicago's TMY3 year.
    c.coefficients[1] = std::min(c.coefficients[1], 0.0);
    c.lit = c.diffuseHorizontalLx + c.directNormalLx > 0;
    return c;
}

PerezAllWeatherSky::PerezAllWeatherSky(const PerezSkyCondition& condition, const Vec3& sunDirection, bool normalise)
    : k_(condition.coefficients), sun_(normalize(sunDirection)) {
    if (!normalise || !condition.lit || !(condition.diffuseHorizontalLx > 0)) return;
    // Horizontal illuminance of the relative distribution: midpoint rule in (cos theta, phi)
    // (equal solid angle cells), phi measured from the sun's azimuth over [0, pi] and doubled
    // (the distribution is symmetric about the sun's vertical plane). 128 x 128 cells resolve
    // the circumsolar peak (its scale 1/|d| is at least 7 deg) to a few 1e-4; the gradation
    // is one per row and the columns' sines one per sky, since a year builds thousands.
    const double sr = std::hypot(sun_.x, sun_.y);
    const Vec3 u = sr > 1e-12 ? Vec3(sun_.x / sr, sun_.y / sr, 0) : Vec3(1, 0, 0), v(-u.y, u.x, 0);
    constexpr int nz = 128, nphi = 128;
    static const std::array<Vec2, nphi> columns = [] {
        std::array<Vec2, nphi> c{};
        for (int j = 0; j < nphi; ++j) c[size_t(j)] = {std::cos(kPi * (j + 0.5) / nphi), std::sin(kPi * (j + 0.5) / nphi)};
        return c;
    }();
    double sum = 0;
    for (int i = 0; i < nz; ++i) {
        const double z = (i + 0.5) / nz, r = std::sqrt(1 - z * z), g = gradation(z);
        double row = 0;
        for (const Vec2& c : columns) {
            const Vec3 w = u * (r * c.x) + v * (r * c.y) + Vec3(0, 0, z);
            row += std::max(0.0, g * indicatrix(w));
        }
        sum += row * z;
    }
    const double relativeIlluminance = sum * (1.0 / nz) * (2 * kPi / nphi);
    if (relativeIlluminance > 0) scale_ = condition.diffuseHorizontalLx / relativeIlluminance;
}

double PerezAllWeatherSky::gradation(double cosTheta) const {
    return 1 + k_[0] * std::exp(k_[1] / std::max(cosTheta, 1e-6));
}

double PerezAllWeatherSky::indicatrix(const Vec3& w) const {
    const double cg = std::clamp(dot(w, sun_), -1.0, 1.0), gamma = std::acos(cg);
    return 1 + k_[2] * std::exp(k_[3] * gamma) + k_[4] * cg * cg;
}

double PerezAllWeatherSky::relativeLuminance(const Vec3& w) const {
    if (w.z < 0) return 0;
    return std::max(0.0, gradation(w.z) * indicatrix(w));
}

double PerezAllWeatherSky::luminance(const Vec3& w) const {
    if (w.z < 0) return 0;
    return scale_ * std::max(0.0, gradation(w.z) * indicatrix(w));
}

PerezAllWeatherSky::Row PerezAllWeatherSky::row(double cosTheta) const {
    Row r;
    r.sky_ = this;
    r.gradation_ = gradation(cosTheta);
    return r;
}

}  // namespace luxplan
