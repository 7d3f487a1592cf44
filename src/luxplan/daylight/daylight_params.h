// What a scene's "site" and "daylight" objects say (docs/scene-format.md), as the scene
// model holds them; daylight.h validates them and bakes the environment.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <luxplan/core/names.h>
#include <luxplan/daylight/datetime.h>
#include <luxplan/daylight/weather.h>

namespace luxplan {

// The scene's "site": where the building is and how it is turned.
struct Site {
    double latitudeDeg = 0;   // [-90, 90], north positive
    double longitudeDeg = 0;  // [-180, 180], east positive
    double northDeg = 0;      // clockwise angle from true north to scene +y
};

// "sky.model": preetham | cie_overcast | uniform | cie_general | perez (the all-weather
// sky of each hour of a weather file).
enum class SkyModelType { Preetham, CieOvercast, Uniform, CieGeneral, Perez };
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
    // "weather": the EPW file (read by the loader, path relative to the scene); its
    // hours give the Perez sky and sun of each hour, and the site.
    std::shared_ptr<const WeatherFile> weather;
    // "occupied": the hours an annual measurement counts (local time: an hour counts
    // when its middle lies in [hours[0], hours[1]) on one of `weekdays`, ISO 8601's
    // 1 = Monday .. 7 = Sunday). Default: every hour.
    struct Occupancy {
        std::array<double, 2> hours{0, 24};
        std::vector<int> weekdays{1, 2, 3, 4, 5, 6, 7};
    } occupied;

    bool sunEnabled() const;
};

}  // namespace luxplan
