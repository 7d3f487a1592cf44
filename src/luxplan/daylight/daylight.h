// Daylight from a scene's "daylight" object (docs/scene-format.md): parameters, their validation,
// the time steps it covers, and the baked DaylightEnvironment (time-averaged sky map + sun
// disks) that the path tracer uses. Models: Preetham (PSS99), CIE overcast, uniform, and
// the ISO 15469 general skies. See docs/daylight.md.
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
#include <luxplan/daylight/solar_position.h>

namespace luxplan {

// How finely the sky is baked: an equirectangular width x height map (height even),
// each pixel the average of supersample^2 directions. 512 x 256 gives 0.7 deg pixels.
struct DaylightBakeOptions {
    int width = 512;
    int height = 256;
    int supersample = 2;
    // Called after each time step's sky is baked, with how many of how many (the skies
    // that follow the sun: Preetham, CIE general); a long period takes a while.
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
    // Whether the instant has a sun disk: its sun up and shining.
    bool sunUp() const { return hasSunPosition && sunAltitudeDeg >= 0 && sunNormalIlluminanceLx > 0; }
};

// The instants averaged: from, from + step, ... up to and including `to` (when it falls on
// the grid); one instant without `to`, with a sun override, or for a time-independent sky.
// Throws SceneError if validateDaylight() reports problems.
std::vector<DaylightInstant> daylightInstants(const DaylightParams& params, const Site& site);

// Bakes the time-averaged sky into a map, lists one sun disk per instant with the sun up
// (weight 1/N each, N = number of instants), and adds the ground. Throws SceneError if
// validateDaylight() reports problems.
DaylightEnvironment buildDaylight(const DaylightParams& params, const Site& site,
                                  const DaylightBakeOptions& options = {});

// Whether an hour counts for annual results: its middle (local time, as
// WeatherFile::middleOf gives it) lies in [hours[0], hours[1]) on one of `weekdays`.
bool occupiedAt(const DaylightParams::Occupancy& occupied, const DateTime& localMiddleOfHour);

}  // namespace luxplan
