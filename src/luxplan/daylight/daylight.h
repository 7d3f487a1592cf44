// Daylight from a scene's "daylight" object (docs/scene-format.md): parameters, their validation,
// the time steps it covers, and the baked DaylightEnvironment (time-averaged sky map + sun
// disks) that the path tracer uses. Models: Preetham (PSS99), CIE overcast, uniform, and
// the ISO 15469 general skies, and the Perez all-weather sky of a weather file's hours. See
// docs/daylight.md.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/error.h>
#include <luxplan/core/limits.h>
#include <luxplan/daylight/daylight_params.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/daylight/perez_sky.h>
#include <luxplan/daylight/solar_position.h>

namespace luxplan {

// How finely the sky is baked: an equirectangular width x height map (height even),
// each pixel the average of supersample^2 directions. 512 x 256 gives 0.7 deg pixels.
struct DaylightBakeOptions {
    int width = 512;
    int height = 256;
    int supersample = 2;
    // Called after each time step's sky is baked, with how many of how many (the skies
    // that follow the sun: Preetham, CIE general, Perez); a long period takes a while.
    std::function<void(int baked, int total)> onStep;
};

// Every problem with params and site, with JSON paths into the scene ("/daylight/sky/turbidity",
// "/site/latitude", ...); `file` is left empty for the caller to fill. Empty when valid.
std::vector<Diagnostic> validateDaylight(const DaylightParams& params, const Site& site);

// Upper bound on the number of time steps (a year hourly is 8760; baking costs ~16 ms per
// daytime step on one core at 512 x 256).
// The limit is core/limits.h's kMaxTimeSteps.
inline constexpr int kMaxDaylightSteps = int(limits::kMaxTimeSteps);

// One time step of the average (or the fixed sun): the sun's position and direct normal
// illuminance (0 when it is below the horizon or disabled).
struct DaylightInstant {
    std::optional<DateTime> time;  // unset for a fixed-sun override or a time-independent sky
    bool hasSunPosition = false;   // false for uniform / overcast skies without a time
    double sunAltitudeDeg = 0, sunAzimuthDeg = 0;  // apparent altitude; azimuth from true north
    Vec3 sunDirection;                             // scene coordinates
    double sunNormalIlluminanceLx = 0;
    // With a weather file (sky model perez): the index of the instant's hour in
    // DaylightParams::weather->hours; the instant is at that hour's middle.
    std::optional<size_t> weatherHour;
    // Whether the instant has a sun disk: its sun up and shining.
    bool sunUp() const { return hasSunPosition && sunAltitudeDeg >= 0 && sunNormalIlluminanceLx > 0; }
};

// The instants averaged: from, from + step, ... up to and including `to` (when it falls on
// the grid); one instant without `to`, with a sun override, or for a time-independent sky.
// Sky model perez: one instant per hour of the weather file whose middle lies in
// [from, to] (weatherHoursIn: the year ignored; only `from`: the hour containing it;
// neither: every hour), at the hour's middle, its sun from the SPA and its direct normal
// illuminance from the Perez model. Throws SceneError if validateDaylight() reports
// problems, FileError ("FILE:LINE: ...") for an hour with the sun up whose direct normal
// or diffuse horizontal irradiance the file marks missing.
std::vector<DaylightInstant> daylightInstants(const DaylightParams& params, const Site& site);

// The Perez model's reading of a perez instant's hour (epsilon, Delta, illuminances,
// coefficients); not lit for the sun below the horizon. Throws FileError for missing data
// as daylightInstants does, std::invalid_argument for an instant without a weather hour.
PerezSkyCondition perezConditionOf(const DaylightParams& params, const DaylightInstant& instant);

// The sky of one instant as the bake uses it, for every sky model: luminance (cd/m2) in a
// scene direction w (unit, pointing to the sky); 0 for w below the horizon and for a sun-
// dependent sky whose sun is down. buildDaylight's map is the weighted sum of these
// (weight 1/N), averaged over each pixel's sub-samples. Expects the instant from
// daylightInstants(params, ...).
std::function<double(const Vec3&)> skyLuminanceAt(const DaylightParams& params, const DaylightInstant& instant);

// Bakes the time-averaged sky into a map, lists one sun disk per instant with the sun up
// (weight 1/N each, N = number of instants), and adds the ground. Throws SceneError if
// validateDaylight() reports problems.
DaylightEnvironment buildDaylight(const DaylightParams& params, const Site& site,
                                  const DaylightBakeOptions& options = {});

// Whether an hour counts for annual results: its middle (local time, as
// WeatherFile::middleOf gives it) lies in [hours[0], hours[1]) on one of `weekdays`.
bool occupiedAt(const DaylightParams::Occupancy& occupied, const DateTime& localMiddleOfHour);

}  // namespace luxplan
