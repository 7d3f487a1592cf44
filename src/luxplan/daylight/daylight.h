// Daylight from a scene's "daylight" object (SCENE-FORMAT.md): parameters, their validation,
// the time steps it covers, and the baked DaylightEnvironment (time-averaged sky map + sun
// disks) that the path tracer uses. Models: Preetham (PSS99), CIE overcast, uniform, and
// the ISO 15469 general skies. See docs/daylight.md.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/error.h>
#include <luxplan/core/names.h>
#include <luxplan/daylight/datetime.h>
#include <luxplan/daylight/environment.h>
#include <luxplan/daylight/solar_position.h>

namespace luxplan {

// The scene's "site": where the building is and how it is turned.
struct Site {
    double latitudeDeg = 0;   // [-90, 90], north positive
    double longitudeDeg = 0;  // [-180, 180], east positive
    double northDeg = 0;      // clockwise angle from true north to scene +y
};

// "sky.model": preetham | cie_overcast | uniform | cie_general.
enum class SkyModelType { Preetham, CieOvercast, Uniform, CieGeneral };
// The scene file's names of the sky models ("preetham", "cie_overcast", ...).
const EnumNames<SkyModelType>& skyModelNames();

// "sun": {"altitude_deg", "azimuth_deg", "normal_illuminance_lx"?}: a fixed sun.
struct SunOverride {
    double altitudeDeg = 45;   // apparent altitude, [0, 90]
    double azimuthDeg = 180;   // clockwise from true north, [0, 360]
    std::optional<double> normalIlluminanceLx;  // unset: from the sky model (Preetham's sun)
};

// Mirror of the scene's "daylight" object; the scene loader fills it. Units in the names.
struct DaylightParams {
    SkyModelType model = SkyModelType::Preetham;         // sky.model
    double turbidity = 3.0;                              // sky.turbidity, [1.7, 10] (Preetham; the
                                                         // general skies use it for their sun)
    std::optional<double> horizontalIlluminanceLx;       // sky.horizontal_illuminance_lx (> 0):
                                                         // cie_overcast, cie_general (sky only)
    std::optional<double> luminanceNits;                 // sky.luminance_nits (>= 0): uniform
    int cieSkyType = 12;                                 // sky.type, [1, 15]: cie_general
    // "sun": true/false; unset means true for preetham/cie_general and false otherwise.
    std::optional<bool> sun;
    std::optional<SunOverride> sunOverride;              // "sun": {...}; implies a sun
    double groundReflectance = 0.2;                      // ground_reflectance, [0, 1]
    std::optional<DateTime> from, to;                    // from, to (to unset: one instant)
    double stepMinutes = 15;                             // step_minutes, > 0
    double pressureMbar = 1010, temperatureC = 10;       // for refraction (standard atmosphere)

    bool sunEnabled() const;
};

// How finely the sky is baked: an equirectangular width x height map (height even),
// each pixel the average of supersample^2 directions. 512 x 256 gives 0.7 deg pixels.
struct DaylightBakeOptions {
    int width = 512;
    int height = 256;
    int supersample = 2;
};

// Every problem with params and site, with JSON paths into the scene ("/daylight/sky/turbidity",
// "/site/latitude", ...); `file` is left empty for the caller to fill. Empty when valid.
std::vector<Diagnostic> validateDaylight(const DaylightParams& params, const Site& site);

// Upper bound on the number of time steps (a year hourly is 8760; baking costs ~16 ms per
// daytime step on one core at 512 x 256).
inline constexpr int kMaxDaylightSteps = 10000;

// One time step of the average (or the fixed sun): the sun's position and direct normal
// illuminance (0 when it is below the horizon or disabled).
struct DaylightInstant {
    std::optional<DateTime> time;  // unset for a fixed-sun override or a time-independent sky
    bool hasSunPosition = false;   // false for uniform / overcast skies without a time
    double sunAltitudeDeg = 0, sunAzimuthDeg = 0;  // apparent altitude; azimuth from true north
    Vec3 sunDirection;                             // scene coordinates
    double sunNormalIlluminanceLx = 0;
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

}  // namespace luxplan
