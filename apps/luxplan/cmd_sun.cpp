// `luxplan sun --lat LAT --lon LON --time ISO`: the sun's apparent position (NREL SPA) as
// JSON {"altitude_deg", "azimuth_deg"}, azimuth clockwise from north.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.h"
#include <luxplan/core/format.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/daylight/solar_position.h>

namespace luxplan::cli {
namespace {

struct SunOptions {
    double latitude = 0, longitude = 0;
    std::string time;
    double elevation = 0;
    double pressure = kStandardPressureMbar;
    double temperature = kStandardTemperatureC;
    std::optional<double> deltaT;
    bool details = false;
    std::optional<double> turbidity;
};

void checkRange(const char* flag, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi))
        throw std::runtime_error(std::string(flag) + " " + significantDigits(v, 6) + " outside [" + significantDigits(lo, 6) + ", " +
                                 significantDigits(hi, 6) + "]");
}

void runSun(const SunOptions& o) {
    checkRange("--lat", o.latitude, -90, 90);
    checkRange("--lon", o.longitude, -180, 180);
    checkRange("--elevation", o.elevation, -500, 10000);
    checkRange("--pressure", o.pressure, 1, 2000);
    checkRange("--temperature", o.temperature, -100, 100);
    if (o.deltaT) checkRange("--delta-t", *o.deltaT, -1e5, 1e5);
    std::string why;
    std::optional<DateTime> t = parseIso8601(o.time, &why);
    if (!t) throw std::runtime_error("--time " + why);

    SolarObserver observer;
    observer.latitudeDeg = o.latitude;
    observer.longitudeDeg = o.longitude;
    observer.elevationM = o.elevation;
    observer.pressureMbar = o.pressure;
    observer.temperatureC = o.temperature;
    observer.deltaTSeconds = o.deltaT;
    const SolarPosition p = solarPosition(*t, observer);

    nlohmann::ordered_json out;
    out["altitude_deg"] = p.altitudeDeg;
    out["azimuth_deg"] = p.azimuthDeg;
    if (o.details) {
        out["zenith_deg"] = p.zenithDeg;
        out["true_altitude_deg"] = p.trueAltitudeDeg;
        out["refraction_deg"] = p.refractionDeg;
        out["declination_deg"] = p.declinationDeg;
        out["hour_angle_deg"] = std::remainder(p.topocentricHourAngleDeg, 360.0);  // (-180, 180], west positive
        out["julian_day"] = p.julianDay;
        out["delta_t_s"] = p.deltaTSeconds;
        DateTime utc = t->plusMinutes(-t->utcOffsetMinutes);
        utc.utcOffsetMinutes = 0;
        out["time_utc"] = utc.str();
    }
    if (o.turbidity) {
        // The Preetham sky and sun for this sun position, baked as a scene would bake it.
        checkRange("--turbidity", *o.turbidity, kMinTurbidity, kMaxTurbidity);
        DaylightParams params;
        params.turbidity = *o.turbidity;
        params.groundReflectance = 0;
        params.sunOverride = SunOverride{std::max(0.0, p.altitudeDeg), p.azimuthDeg, std::nullopt};
        DaylightEnvironment env = p.altitudeDeg >= 0 ? buildDaylight(params, Site{o.latitude, o.longitude, 0})
                                                     : DaylightEnvironment{};
        out["sun_normal_illuminance_lx"] = env.hasSun() ? env.sunDisks()[0].normalIlluminanceLx : 0.0;
        out["sun_horizontal_illuminance_lx"] = env.sunHorizontalIlluminance();
        out["sky_horizontal_illuminance_lx"] = env.skyHorizontalIlluminance();
        out["zenith_luminance_cd_m2"] = env.Lv({0, 0, 1});
    }
    std::cout << out.dump() << "\n";
}

}  // namespace

void registerSunCommand(CLI::App& app) {
    auto o = std::make_shared<SunOptions>();
    auto* cmd = app.add_subcommand(
        "sun", "Print the sun's apparent position (NREL SPA) as JSON {\"altitude_deg\", \"azimuth_deg\"}, "
               "azimuth clockwise from north");
    cmd->add_option("--lat", o->latitude, "Latitude in degrees, north positive, [-90, 90]")->required();
    cmd->add_option("--lon", o->longitude, "Longitude in degrees, east positive, [-180, 180]")->required();
    cmd->add_option("--time", o->time, "ISO 8601 local time with UTC offset, e.g. 2026-06-21T09:00+03:00")
        ->required();
    cmd->add_option("--elevation", o->elevation, "Site elevation above sea level in metres (default 0)");
    cmd->add_option("--pressure", o->pressure, "Air pressure for refraction in mbar (default 1010)");
    cmd->add_option("--temperature", o->temperature, "Air temperature for refraction in deg C (default 10)");
    cmd->add_option("--delta-t", o->deltaT,
                    "TT - UT in seconds (default: Espenak & Meeus polynomial for the date)");
    cmd->add_flag("--details", o->details, "Also print zenith, refraction, declination, hour angle, JD, delta T");
    cmd->add_option("--turbidity", o->turbidity,
                    "Also print the Preetham sun's normal and horizontal illuminance, the sky's horizontal "
                    "illuminance (lx) and zenith luminance (cd/m2) for this turbidity, [1.7, 10]");
    cmd->callback([o] { runSun(*o); });
}

}  // namespace luxplan::cli
