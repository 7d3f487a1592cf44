// NREL SPA (Reda & Andreas 2004): Earth periodic terms, nutation, aberration, parallax
// and refraction; Espenak & Meeus delta T; horizon <-> scene direction conversions.
#include <luxplan/daylight/solar_position.h>

#include <cmath>
#include <span>

namespace luxplan {
namespace {

// One periodic term A cos(B + C * JME) of the Earth's heliocentric position
// (SPA report Table A4.2, abridged VSOP87). A in 1e-8 rad (or AU), B in rad, C in rad/millennium.
struct PeriodicTerm {
    double a, b, c;
};

constexpr PeriodicTerm kL0[] = {
    {175347046.0, 0, 0}, {3341656.0, 4.6692568, 6283.07585}, {34894.0, 4.6261, 12566.1517},
    {3497.0, 2.7441, 5753.3849}, {3418.0, 2.8289, 3.5231}, {3136.0, 3.6277, 77713.7715},
    {2676.0, 4.4181, 7860.4194}, {2343.0, 6.1352, 3930.2097}, {1324.0, 0.7425, 11506.7698},
    {1273.0, 2.0371, 529.691}, {1199.0, 1.1096, 1577.3435}, {990, 5.233, 5884.927},
    {902, 2.045, 26.298}, {857, 3.508, 398.149}, {780, 1.179, 5223.694},
    {753, 2.533, 5507.553}, {505, 4.583, 18849.228}, {492, 4.205, 775.523},
    {357, 2.92, 0.067}, {317, 5.849, 11790.629}, {284, 1.899, 796.298},
    {271, 0.315, 10977.079}, {243, 0.345, 5486.778}, {206, 4.806, 2544.314},
    {205, 1.869, 5573.143}, {202, 2.458, 6069.777}, {156, 0.833, 213.299},
    {132, 3.411, 2942.463}, {126, 1.083, 20.775}, {115, 0.645, 0.98},
    {103, 0.636, 4694.003}, {102, 0.976, 15720.839}, {102, 4.267, 7.114},
    {99, 6.21, 2146.17}, {98, 0.68, 155.42}, {86, 5.98, 161000.69},
    {85, 1.3, 6275.96}, {85, 3.67, 71430.7}, {80, 1.81, 17260.15},
    {79, 3.04, 12036.46}, {75, 1.76, 5088.63}, {74, 3.5, 3154.69},
    {74, 4.68, 801.82}, {70, 0.83, 9437.76}, {62, 3.98, 8827.39},
    {61, 1.82, 7084.9}, {57, 2.78, 6286.6}, {56, 4.39, 14143.5},
    {56, 3.47, 6279.55}, {52, 0.19, 12139.55}, {52, 1.33, 1748.02},
    {51, 0.28, 5856.48}, {49, 0.49, 1194.45}, {41, 5.37, 8429.24},
    {41, 2.4, 19651.05}, {39, 6.17, 10447.39}, {37, 6.04, 10213.29},
    {37, 2.57, 1059.38}, {36, 1.71, 2352.87}, {36, 1.78, 6812.77},
    {33, 0.59, 17789.85}, {30, 0.44, 83996.85}, {30, 2.74, 1349.87},
    {25, 3.16, 4690.48},
};
constexpr PeriodicTerm kL1[] = {
    {628331966747.0, 0, 0}, {206059.0, 2.678235, 6283.07585}, {4303.0, 2.6351, 12566.1517},
    {425, 1.59, 3.523}, {119, 5.796, 26.298}, {109, 2.966, 1577.344},
    {93, 2.59, 18849.23}, {72, 1.14, 529.69}, {68, 1.87, 398.15},
    {67, 4.41, 5507.55}, {59, 2.89, 5223.69}, {56, 2.17, 155.42},
    {45, 0.4, 796.3}, {36, 0.47, 775.52}, {29, 2.65, 7.11},
    {21, 5.34, 0.98}, {19, 1.85, 5486.78}, {19, 4.97, 213.3},
    {17, 2.99, 6275.96}, {16, 0.03, 2544.31}, {16, 1.43, 2146.17},
    {15, 1.21, 10977.08}, {12, 2.83, 1748.02}, {12, 3.26, 5088.63},
    {12, 5.27, 1194.45}, {12, 2.08, 4694}, {11, 0.77, 553.57},
    {10, 1.3, 6286.6}, {10, 4.24, 1349.87}, {9, 2.7, 242.73},
    {9, 5.64, 951.72}, {8, 5.3, 2352.87}, {6, 2.65, 9437.76},
    {6, 4.67, 4690.48},
};
constexpr PeriodicTerm kL2[] = {
    {52919, 0, 0}, {8720, 1.0721, 6283.0758}, {309, 0.867, 12566.152},
    {27, 0.05, 3.52}, {16, 5.19, 26.3}, {16, 3.68, 155.42},
    {10, 0.76, 18849.23}, {9, 2.06, 77713.77}, {7, 0.83, 775.52},
    {5, 4.66, 1577.34}, {4, 1.03, 7.11}, {4, 3.44, 5573.14},
    {3, 5.14, 796.3}, {3, 6.05, 5507.55}, {3, 1.19, 242.73},
    {3, 6.12, 529.69}, {3, 0.31, 398.15}, {3, 2.28, 553.57},
    {2, 4.38, 5223.69}, {2, 3.75, 0.98},
};
constexpr PeriodicTerm kL3[] = {
    {289, 5.844, 6283.076}, {35, 0, 0}, {17, 5.49, 12566.15}, {3, 5.2, 155.42},
    {1, 4.72, 3.52}, {1, 5.3, 18849.23}, {1, 5.97, 242.73},
};
constexpr PeriodicTerm kL4[] = {{114, 3.142, 0}, {8, 4.13, 6283.08}, {1, 3.84, 12566.15}};
constexpr PeriodicTerm kL5[] = {{1, 3.14, 0}};

constexpr PeriodicTerm kB0[] = {
    {280, 3.199, 84334.662}, {102, 5.422, 5507.553}, {80, 3.88, 5223.69},
    {44, 3.7, 2352.87}, {32, 4, 1577.34},
};
constexpr PeriodicTerm kB1[] = {{9, 3.9, 5507.55}, {6, 1.73, 5223.69}};

constexpr PeriodicTerm kR0[] = {
    {100013989.0, 0, 0}, {1670700.0, 3.0984635, 6283.07585}, {13956.0, 3.05525, 12566.1517},
    {3084.0, 5.1985, 77713.7715}, {1628.0, 1.1739, 5753.3849}, {1576.0, 2.8469, 7860.4194},
    {925, 5.453, 11506.77}, {542, 4.564, 3930.21}, {472, 3.661, 5884.927},
    {346, 0.964, 5507.553}, {329, 5.9, 5223.694}, {307, 0.299, 5573.143},
    {243, 4.273, 11790.629}, {212, 5.847, 1577.344}, {186, 5.022, 10977.079},
    {175, 3.012, 18849.228}, {110, 5.055, 5486.778}, {98, 0.89, 6069.78},
    {86, 5.69, 15720.84}, {86, 1.27, 161000.69}, {65, 0.27, 17260.15},
    {63, 0.92, 529.69}, {57, 2.01, 83996.85}, {56, 5.24, 71430.7},
    {49, 3.25, 2544.31}, {47, 2.58, 775.52}, {45, 5.54, 9437.76},
    {43, 6.01, 6275.96}, {39, 5.36, 4694}, {38, 2.39, 8827.39},
    {37, 0.83, 19651.05}, {37, 4.9, 12139.55}, {36, 1.67, 12036.46},
    {35, 1.84, 2942.46}, {33, 0.24, 7084.9}, {32, 0.18, 5088.63},
    {32, 1.78, 398.15}, {28, 1.21, 6286.6}, {28, 1.9, 6279.55},
    {26, 4.59, 10447.39},
};
constexpr PeriodicTerm kR1[] = {
    {103019, 1.10749, 6283.07585}, {1721, 1.0644, 12566.1517}, {702, 3.142, 0},
    {32, 1.02, 18849.23}, {31, 2.84, 5507.55}, {25, 1.32, 5223.69},
    {18, 1.42, 1577.34}, {10, 5.91, 10977.08}, {9, 1.42, 6275.96},
    {9, 0.27, 5486.78},
};
constexpr PeriodicTerm kR2[] = {
    {4359, 5.7846, 6283.0758}, {124, 5.579, 12566.152}, {12, 3.14, 0},
    {9, 3.63, 77713.77}, {6, 1.87, 5573.14}, {3, 5.47, 18849.23},
};
constexpr PeriodicTerm kR3[] = {{145, 4.273, 6283.076}, {7, 3.92, 12566.15}};
constexpr PeriodicTerm kR4[] = {{4, 2.56, 6283.08}};

// Nutation in longitude and obliquity (SPA report Table A4.3): the argument is
// sum_j y[j] * X_j; delta psi += (a + b JCE) sin(arg), delta eps += (c + d JCE) cos(arg),
// both in 0.0001 arcsec.
struct NutationTerm {
    signed char y[5];
    double a, b, c, d;
};

constexpr NutationTerm kNutation[] = {
    {{0, 0, 0, 0, 1}, -171996, -174.2, 92025, 8.9},
    {{-2, 0, 0, 2, 2}, -13187, -1.6, 5736, -3.1},
    {{0, 0, 0, 2, 2}, -2274, -0.2, 977, -0.5},
    {{0, 0, 0, 0, 2}, 2062, 0.2, -895, 0.5},
    {{0, 1, 0, 0, 0}, 1426, -3.4, 54, -0.1},
    {{0, 0, 1, 0, 0}, 712, 0.1, -7, 0},
    {{-2, 1, 0, 2, 2}, -517, 1.2, 224, -0.6},
    {{0, 0, 0, 2, 1}, -386, -0.4, 200, 0},
    {{0, 0, 1, 2, 2}, -301, 0, 129, -0.1},
    {{-2, -1, 0, 2, 2}, 217, -0.5, -95, 0.3},
    {{-2, 0, 1, 0, 0}, -158, 0, 0, 0},
    {{-2, 0, 0, 2, 1}, 129, 0.1, -70, 0},
    {{0, 0, -1, 2, 2}, 123, 0, -53, 0},
    {{2, 0, 0, 0, 0}, 63, 0, 0, 0},
    {{0, 0, 1, 0, 1}, 63, 0.1, -33, 0},
    {{2, 0, -1, 2, 2}, -59, 0, 26, 0},
    {{0, 0, -1, 0, 1}, -58, -0.1, 32, 0},
    {{0, 0, 1, 2, 1}, -51, 0, 27, 0},
    {{-2, 0, 2, 0, 0}, 48, 0, 0, 0},
    {{0, 0, -2, 2, 1}, 46, 0, -24, 0},
    {{2, 0, 0, 2, 2}, -38, 0, 16, 0},
    {{0, 0, 2, 2, 2}, -31, 0, 13, 0},
    {{0, 0, 2, 0, 0}, 29, 0, 0, 0},
    {{-2, 0, 1, 2, 2}, 29, 0, -12, 0},
    {{0, 0, 0, 2, 0}, 26, 0, 0, 0},
    {{-2, 0, 0, 2, 0}, -22, 0, 0, 0},
    {{0, 0, -1, 2, 1}, 21, 0, -10, 0},
    {{0, 2, 0, 0, 0}, 17, -0.1, 0, 0},
    {{2, 0, -1, 0, 1}, 16, 0, -8, 0},
    {{-2, 2, 0, 2, 2}, -16, 0.1, 7, 0},
    {{0, 1, 0, 0, 1}, -15, 0, 9, 0},
    {{-2, 0, 1, 0, 1}, -13, 0, 7, 0},
    {{0, -1, 0, 0, 1}, -12, 0, 6, 0},
    {{0, 0, 2, -2, 0}, 11, 0, 0, 0},
    {{2, 0, -1, 2, 1}, -10, 0, 5, 0},
    {{2, 0, 1, 2, 2}, -8, 0, 3, 0},
    {{0, 1, 0, 2, 2}, 7, 0, -3, 0},
    {{-2, 1, 1, 0, 0}, -7, 0, 0, 0},
    {{0, -1, 0, 2, 2}, -7, 0, 3, 0},
    {{2, 0, 0, 2, 1}, -7, 0, 3, 0},
    {{2, 0, 1, 0, 0}, 6, 0, 0, 0},
    {{-2, 0, 2, 2, 2}, 6, 0, -3, 0},
    {{-2, 0, 1, 2, 1}, 6, 0, -3, 0},
    {{2, 0, -2, 0, 1}, -6, 0, 3, 0},
    {{2, 0, 0, 0, 1}, -6, 0, 3, 0},
    {{0, -1, 1, 0, 0}, 5, 0, 0, 0},
    {{-2, -1, 0, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 0, 0, 1}, -5, 0, 3, 0},
    {{0, 0, 2, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 2, 0, 1}, 4, 0, 0, 0},
    {{-2, 1, 0, 2, 1}, 4, 0, 0, 0},
    {{0, 0, 1, -2, 0}, 4, 0, 0, 0},
    {{-1, 0, 1, 0, 0}, -4, 0, 0, 0},
    {{-2, 1, 0, 0, 0}, -4, 0, 0, 0},
    {{1, 0, 0, 0, 0}, -4, 0, 0, 0},
    {{0, 0, 1, 2, 0}, 3, 0, 0, 0},
    {{0, 0, -2, 2, 2}, -3, 0, 0, 0},
    {{-1, -1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, 1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, -1, 1, 2, 2}, -3, 0, 0, 0},
    {{2, -1, -1, 2, 2}, -3, 0, 0, 0},
    {{0, 0, 3, 2, 2}, -3, 0, 0, 0},
    {{2, -1, 0, 2, 2}, -3, 0, 0, 0},
};

double sumTerms(std::span<const PeriodicTerm> terms, double jme) {
    double s = 0;
    for (const PeriodicTerm& t : terms) s += t.a * std::cos(t.b + t.c * jme);
    return s;
}

// sum_i S_i JME^i / 1e8 for the series S_0, S_1, ...
double earthSeries(std::initializer_list<std::span<const PeriodicTerm>> series, double jme) {
    double result = 0, power = 1;
    for (auto terms : series) {
        result += sumTerms(terms, jme) * power;
        power *= jme;
    }
    return result / 1e8;
}


double sinDeg(double d) { return std::sin(radians(d)); }
double cosDeg(double d) { return std::cos(radians(d)); }

constexpr double kJ2000 = 2451545.0;

}  // namespace

double deltaTSeconds(double y) {
    auto poly = [](double t, std::initializer_list<double> c) {
        double r = 0, p = 1;
        for (double ci : c) { r += ci * p; p *= t; }
        return r;
    };
    if (y >= 1900 && y < 1920) return poly(y - 1900, {-2.79, 1.494119, -0.0598939, 0.0061966, -0.000197});
    if (y >= 1920 && y < 1941) return poly(y - 1920, {21.20, 0.84493, -0.076100, 0.0020936});
    if (y >= 1941 && y < 1961) return poly(y - 1950, {29.07, 0.407, -1.0 / 233, 1.0 / 2547});
    if (y >= 1961 && y < 1986) return poly(y - 1975, {45.45, 1.067, -1.0 / 260, -1.0 / 718});
    if (y >= 1986 && y < 2005)
        return poly(y - 2000, {63.86, 0.3345, -0.060374, 0.0017275, 0.000651814, 0.00002373599});
    if (y >= 2005 && y < 2050) return poly(y - 2000, {62.92, 0.32217, 0.005589});
    double u = (y - 1820) / 100;
    if (y >= 2050 && y < 2150) return -20 + 32 * u * u - 0.5628 * (2150 - y);
    return -20 + 32 * u * u;
}

double deltaTSeconds(const DateTime& t) { return deltaTSeconds(t.year + (t.month - 0.5) / 12.0); }

SolarPosition solarPosition(const DateTime& t, const SolarObserver& observer) {
    double dt = observer.deltaTSeconds ? *observer.deltaTSeconds : deltaTSeconds(t);
    return solarPosition(t.julianDayUT(), dt, observer);
}

SolarPosition solarPosition(double jd, double deltaT, const SolarObserver& obs) {
    SolarPosition p;
    p.julianDay = jd;
    p.deltaTSeconds = deltaT;
    p.julianEphemerisDay = jd + deltaT / 86400.0;
    const double jc = (jd - kJ2000) / 36525.0;
    const double jce = (p.julianEphemerisDay - kJ2000) / 36525.0;
    const double jme = jce / 10.0;

    // Earth heliocentric position, then the geocentric sun.
    p.heliocentricLongitudeDeg = wrapDegrees(degrees(earthSeries({kL0, kL1, kL2, kL3, kL4, kL5}, jme)));
    p.heliocentricLatitudeDeg = degrees(earthSeries({kB0, kB1}, jme));
    p.earthSunDistanceAU = earthSeries({kR0, kR1, kR2, kR3, kR4}, jme);
    const double theta = wrapDegrees(p.heliocentricLongitudeDeg + 180.0);
    const double beta = -p.heliocentricLatitudeDeg;

    // Nutation: mean elongation of the moon, anomalies of sun and moon, the moon's
    // argument of latitude and the longitude of its ascending node (degrees).
    const double x[5] = {
        297.85036 + 445267.111480 * jce - 0.0019142 * jce * jce + jce * jce * jce / 189474.0,
        357.52772 + 35999.050340 * jce - 0.0001603 * jce * jce - jce * jce * jce / 300000.0,
        134.96298 + 477198.867398 * jce + 0.0086972 * jce * jce + jce * jce * jce / 56250.0,
        93.27191 + 483202.017538 * jce - 0.0036825 * jce * jce + jce * jce * jce / 327270.0,
        125.04452 - 1934.136261 * jce + 0.0020708 * jce * jce + jce * jce * jce / 450000.0,
    };
    double dPsi = 0, dEps = 0;
    for (const NutationTerm& n : kNutation) {
        double arg = 0;
        for (int j = 0; j < 5; ++j) arg += n.y[j] * x[j];
        dPsi += (n.a + n.b * jce) * sinDeg(arg);
        dEps += (n.c + n.d * jce) * cosDeg(arg);
    }
    p.nutationLongitudeDeg = dPsi / 36000000.0;
    p.nutationObliquityDeg = dEps / 36000000.0;

    // True obliquity of the ecliptic (Laskar's polynomial in U = JME/10, arcsec).
    const double u = jme / 10.0;
    const double eps0 = 84381.448 +
                        u * (-4680.93 + u * (-1.55 + u * (1999.25 + u * (-51.38 + u * (-249.67 +
                        u * (-39.05 + u * (7.12 + u * (27.87 + u * (5.79 + u * 2.45)))))))));
    p.trueObliquityDeg = eps0 / 3600.0 + p.nutationObliquityDeg;

    // Aberration, apparent longitude, apparent sidereal time at Greenwich.
    const double dTau = -20.4898 / (3600.0 * p.earthSunDistanceAU);
    p.apparentSunLongitudeDeg = theta + p.nutationLongitudeDeg + dTau;
    const double nu0 = wrapDegrees(280.46061837 + 360.98564736629 * (jd - kJ2000) + 0.000387933 * jc * jc -
                                   jc * jc * jc / 38710000.0);
    const double nu = nu0 + p.nutationLongitudeDeg * cosDeg(p.trueObliquityDeg);

    // Geocentric right ascension and declination.
    const double lambda = radians(p.apparentSunLongitudeDeg), eps = radians(p.trueObliquityDeg);
    const double betaR = radians(beta);
    p.rightAscensionDeg = wrapDegrees(
        degrees(std::atan2(std::sin(lambda) * std::cos(eps) - std::tan(betaR) * std::sin(eps), std::cos(lambda))));
    p.declinationDeg = degrees(
        std::asin(std::sin(betaR) * std::cos(eps) + std::cos(betaR) * std::sin(eps) * std::sin(lambda)));
    p.hourAngleDeg = wrapDegrees(nu + obs.longitudeDeg - p.rightAscensionDeg);

    // Topocentric correction (parallax for an observer on the reference ellipsoid).
    const double xi = radians(8.794 / (3600.0 * p.earthSunDistanceAU));
    const double phi = radians(obs.latitudeDeg);
    const double uu = std::atan(0.99664719 * std::tan(phi));
    const double xt = std::cos(uu) + obs.elevationM / 6378140.0 * std::cos(phi);
    const double yt = 0.99664719 * std::sin(uu) + obs.elevationM / 6378140.0 * std::sin(phi);
    const double h = radians(p.hourAngleDeg), delta = radians(p.declinationDeg);
    const double denom = std::cos(delta) - xt * std::sin(xi) * std::cos(h);
    const double dAlpha = std::atan2(-xt * std::sin(xi) * std::sin(h), denom);
    const double deltaPrime = std::atan2((std::sin(delta) - yt * std::sin(xi)) * std::cos(dAlpha), denom);
    p.topocentricRightAscensionDeg = p.rightAscensionDeg + degrees(dAlpha);
    p.topocentricDeclinationDeg = degrees(deltaPrime);
    p.topocentricHourAngleDeg = p.hourAngleDeg - degrees(dAlpha);
    const double hp = radians(p.topocentricHourAngleDeg);

    // Altitude without and with refraction (applied while any part of the disk may be visible).
    p.trueAltitudeDeg = degrees(
        std::asin(std::sin(phi) * std::sin(deltaPrime) + std::cos(phi) * std::cos(deltaPrime) * std::cos(hp)));
    constexpr double kSunRadiusDeg = 0.26667, kHorizonRefractionDeg = 0.5667;
    const double e0 = p.trueAltitudeDeg;
    if (e0 >= -(kSunRadiusDeg + kHorizonRefractionDeg))
        p.refractionDeg = (obs.pressureMbar / 1010.0) * (283.0 / (273.0 + obs.temperatureC)) * 1.02 /
                          (60.0 * std::tan(radians(e0 + 10.3 / (e0 + 5.11))));
    p.altitudeDeg = e0 + p.refractionDeg;
    p.zenithDeg = 90.0 - p.altitudeDeg;

    // Azimuth: astronomers' (westward from south) + 180 = navigators' (eastward from north).
    const double gamma = std::atan2(std::sin(hp), std::cos(hp) * std::sin(phi) - std::tan(deltaPrime) * std::cos(phi));
    p.azimuthDeg = wrapDegrees(degrees(gamma) + 180.0);
    return p;
}

Vec3 horizonToScene(double altitudeDeg, double azimuthDeg, double northDeg) {
    double alt = radians(altitudeDeg), az = radians(azimuthDeg - northDeg);
    return {std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
}

HorizonAngles sceneToHorizon(const Vec3& d, double northDeg) {
    Vec3 w = normalize(d);
    HorizonAngles a;
    a.altitudeDeg = degrees(std::asin(std::clamp(w.z, -1.0, 1.0)));
    double horizontal = std::hypot(w.x, w.y);
    a.azimuthDeg = horizontal > 1e-12 ? wrapDegrees(degrees(std::atan2(w.x, w.y)) + northDeg) : 0.0;
    return a;
}

}  // namespace luxplan
