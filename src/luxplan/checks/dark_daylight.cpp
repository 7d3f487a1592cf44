// Daylight intervals after sunset or before sunrise.
#include <luxplan/checks/scene_warnings.h>

#include <luxplan/daylight/daylight.h>

namespace luxplan {

std::vector<Diagnostic> darkDaylight(const Scene& scene) {
    std::vector<Diagnostic> out;
    if (!scene.daylight || !scene.daylight->from || scene.daylight->sunOverride) return out;
    const DaylightParams& d = *scene.daylight;
    // The other skies do not depend on the sun's position.
    if (d.model != SkyModelType::Preetham && d.model != SkyModelType::CieGeneral) return out;
    int dark = 0, steps = 0;
    std::string firstDark;
    for (const DaylightInstant& i : daylightInstants(d, scene.site)) {
        ++steps;
        if (i.sunAltitudeDeg >= 0) continue;
        if (!dark++) firstDark = i.time->str();
    }
    if (!dark) return out;
    const std::string interval = d.to ? d.from->str() + " to " + d.to->str() : d.from->str();
    std::string message =
        dark == steps
            ? "the sun is below the horizon " + std::string(d.to ? "throughout " : "at ") + interval +
                  " (after sunset or before sunrise): the daylight adds no light; leave \"daylight\" out for a night scene"
            : "the sun is below the horizon at " + std::to_string(dark) + " of the " + std::to_string(steps) +
                  " steps of " + interval + " (from " + firstDark + "): they add no light but count in the average";
    out.push_back({scene.file.string(), "/daylight/from", message});
    return out;
}

}  // namespace luxplan
