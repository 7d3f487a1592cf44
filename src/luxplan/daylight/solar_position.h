// Sun position: the NREL Solar Position Algorithm (SPA) and conversions between
// horizon coordinates (altitude, azimuth clockwise from north) and scene directions.
//
// Reda I., Andreas A. (2004), "Solar position algorithm for solar radiation
// applications", Solar Energy 76(5):577-589; NREL/TP-560-34302 (rev. 2008),
// https://www.nrel.gov/docs/fy08osti/34302.pdf. Stated accuracy +-0.0003 deg for
// years -2000..6000. Delta T: Espenak & Meeus (2006), "Five Millennium Canon of Solar
// Eclipses", NASA/TP-2006-214141, https://eclipse.gsfc.nasa.gov/SEcat5/deltatpoly.html.
#pragma once

#include <optional>

#include <luxplan/core/math.h>
#include <luxplan/daylight/datetime.h>

namespace luxplan {

// Standard atmosphere for refraction when a scene gives none (mbar, deg C).
inline constexpr double kStandardPressureMbar = 1010.0;
inline constexpr double kStandardTemperatureC = 10.0;

// Where the sun is seen from, and the air it is seen through.
struct SolarObserver {
    double latitudeDeg = 0;   // [-90, 90], north positive
    double longitudeDeg = 0;  // [-180, 180], east positive
    double elevationM = 0;    // above sea level, metres
    double pressureMbar = kStandardPressureMbar;
    double temperatureC = kStandardTemperatureC;
    // TT - UT in seconds; unset: deltaTSeconds() of the date.
    std::optional<double> deltaTSeconds;
};

// SPA output. Angles in degrees. Intermediate values are kept for tests and reports.
struct SolarPosition {
    double julianDay = 0;            // JD (UT)
    double julianEphemerisDay = 0;   // JDE (TT)
    double deltaTSeconds = 0;        // TT - UT used
    double heliocentricLongitudeDeg = 0;  // L, [0, 360)
    double heliocentricLatitudeDeg = 0;   // B
    double earthSunDistanceAU = 0;        // R
    double nutationLongitudeDeg = 0;      // delta psi
    double nutationObliquityDeg = 0;      // delta epsilon
    double trueObliquityDeg = 0;          // epsilon
    double apparentSunLongitudeDeg = 0;   // lambda
    double rightAscensionDeg = 0;         // alpha, geocentric, [0, 360)
    double declinationDeg = 0;            // delta, geocentric
    double hourAngleDeg = 0;              // H, observer local hour angle (geocentric), [0, 360)
    double topocentricRightAscensionDeg = 0;  // alpha'
    double topocentricDeclinationDeg = 0;     // delta'
    double topocentricHourAngleDeg = 0;       // H'
    double trueAltitudeDeg = 0;       // e0: topocentric, no refraction
    double refractionDeg = 0;         // delta e (0 when the sun is well below the horizon)
    double altitudeDeg = 0;           // e: topocentric apparent (refracted) altitude
    double zenithDeg = 0;             // 90 - altitudeDeg
    double azimuthDeg = 0;            // clockwise from north, [0, 360)
};

// Full SPA for the instant `t` (any UTC offset) at `observer`.
SolarPosition solarPosition(const DateTime& t, const SolarObserver& observer);
// The same from a Julian day (UT) and TT - UT in seconds.
SolarPosition solarPosition(double julianDayUT, double deltaT, const SolarObserver& observer);

// TT - UT in seconds (Espenak & Meeus 2006 polynomials, decimal year y = year + (month - 0.5)/12).
// Piecewise fits are used for 1900..2150; outside, the long-term parabola -20 + 32 u^2,
// u = (y - 1820)/100 (Morrison & Stephenson 2004), which is only good to minutes.
double deltaTSeconds(double decimalYear);
double deltaTSeconds(const DateTime& t);

// Unit direction in scene coordinates (z up) of a point in the sky at `altitudeDeg` above the
// horizon and `azimuthDeg` clockwise from true north. `northDeg` is site.north_deg: the clockwise
// angle from true north to scene +y (0: +y north, +x east).
Vec3 horizonToScene(double altitudeDeg, double azimuthDeg, double northDeg);

// Inverse of horizonToScene: altitude in [-90, 90], azimuth in [0, 360) (0 at the poles).
struct HorizonAngles {
    double altitudeDeg = 0;
    double azimuthDeg = 0;
};
HorizonAngles sceneToHorizon(const Vec3& direction, double northDeg);

}  // namespace luxplan
