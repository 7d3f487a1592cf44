// Daylight parameters -> validated time steps -> baked, time-averaged DaylightEnvironment.
#include <luxplan/daylight/daylight.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <luxplan/core/format.h>
#include <luxplan/daylight/cie_sky.h>
#include <luxplan/daylight/perez_sky.h>
#include <luxplan/daylight/preetham.h>
#include <luxplan/daylight/solar_position.h>

namespace luxplan {
namespace {

std::string inQuotes(std::string_view s) {
    std::string r(1, '"');  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "x" + string
    r.append(s).push_back('"');
    return r;
}

// Does the sun's brightness come from Preetham's model (and so need a valid turbidity)?
bool sunFromPreetham(const DaylightParams& p) {
    return p.sunEnabled() && !(p.sunOverride && p.sunOverride->normalIlluminanceLx);
}

bool usesTurbidity(const DaylightParams& p) {
    return p.model == SkyModelType::Preetham || (p.model == SkyModelType::CieGeneral && sunFromPreetham(p));
}

// Does the sky's shape depend on where the sun is, given by a time or a fixed sun?
bool needsSunPosition(SkyModelType m) { return m == SkyModelType::Preetham || m == SkyModelType::CieGeneral; }
// Does the model bring its own sun? (Perez: the weather file's, at each hour's time.)
bool hasOwnSun(SkyModelType m) { return needsSunPosition(m) || m == SkyModelType::Perez; }

// Day of the year of a month and day in a year of 365 days (as gendaylit's jdate; 29
// February counts as 1 March), for the sun's distance in the Perez brightness.
int dayOfYear(int month, int day) {
    int n = day;
    for (int m = 1; m < month; ++m) n += daysInMonth(2001, m);
    return n;
}

// Number of instants from..to every step (to included when on the grid), in floating
// point: a tiny step gives a count beyond any integer, compared with the limit before
// it is converted or allocated.
double stepCount(const DateTime& from, const DateTime& to, double stepMinutes) {
    const double spanMinutes = (to.julianDayUT() - from.julianDayUT()) * 1440.0;
    return std::floor(spanMinutes / stepMinutes + 1e-9) + 1;
}

}  // namespace

const EnumNames<SkyModelType>& skyModelNames() {
    static const EnumNames<SkyModelType> names{{{SkyModelType::Preetham, "preetham"},
                                                {SkyModelType::CieOvercast, "cie_overcast"},
                                                {SkyModelType::Uniform, "uniform"},
                                                {SkyModelType::CieGeneral, "cie_general"},
                                                {SkyModelType::Perez, "perez"}}};
    return names;
}

bool DaylightParams::sunEnabled() const {
    if (sunOverride) return true;
    if (sun) return *sun;
    return hasOwnSun(model);
}

std::vector<Diagnostic> validateDaylight(const DaylightParams& p, const Site& site) {
    std::vector<Diagnostic> d;
    auto add = [&](std::string path, std::string message) { d.push_back({"", std::move(path), std::move(message)}); };
    auto range = [&](const char* path, const char* key, double v, double lo, double hi) {
        if (!(v >= lo && v <= hi)) add(path, std::string(key) + " " + formatNumber(v) + " outside [" + formatNumber(lo) + ", " + formatNumber(hi) + "]");
    };

    range("/site/latitude", "latitude", site.latitudeDeg, -90, 90);
    range("/site/longitude", "longitude", site.longitudeDeg, -180, 180);
    if (!std::isfinite(site.northDeg)) add("/site/north_deg", "north_deg must be a finite number");

    const std::string model(skyModelNames().name(p.model));
    if (usesTurbidity(p)) range("/daylight/sky/turbidity", "turbidity", p.turbidity, kMinTurbidity, kMaxTurbidity);
    if (p.model == SkyModelType::CieOvercast || p.model == SkyModelType::CieGeneral) {
        if (!p.horizontalIlluminanceLx)
            add("/daylight/sky", "sky model " + inQuotes(model) + " needs \"horizontal_illuminance_lx\"");
        else if (!(*p.horizontalIlluminanceLx > 0) || !std::isfinite(*p.horizontalIlluminanceLx))
            add("/daylight/sky/horizontal_illuminance_lx",
                "horizontal_illuminance_lx " + formatNumber(*p.horizontalIlluminanceLx) + " must be > 0");
        else if (*p.horizontalIlluminanceLx > limits::kMaxIlluminanceLx)
            add("/daylight/sky/horizontal_illuminance_lx", "horizontal_illuminance_lx " + formatNumber(*p.horizontalIlluminanceLx) +
                                                               " exceeds the limit of " + formatNumber(limits::kMaxIlluminanceLx));
    }
    if (p.model == SkyModelType::Perez && !p.weather)
        add("/daylight/sky/model", "sky model \"perez\" needs \"weather\" (an EPW file): it builds each hour's sky from the file");
    if (p.model == SkyModelType::Uniform) {
        if (!p.luminanceNits)
            add("/daylight/sky", "sky model \"uniform\" needs \"luminance_nits\"");
        else if (!(*p.luminanceNits >= 0) || !std::isfinite(*p.luminanceNits))
            add("/daylight/sky/luminance_nits", "luminance_nits " + formatNumber(*p.luminanceNits) + " must be >= 0");
        else if (*p.luminanceNits > limits::kMaxLuminanceNits)
            add("/daylight/sky/luminance_nits",
                "luminance_nits " + formatNumber(*p.luminanceNits) + " exceeds the limit of " + formatNumber(limits::kMaxLuminanceNits));
    }
    if (p.model == SkyModelType::CieGeneral && (p.cieSkyType < 1 || p.cieSkyType > 15))
        add("/daylight/sky/type", "type " + std::to_string(p.cieSkyType) + " outside [1, 15]");

    if (p.sunOverride) {
        const SunOverride& s = *p.sunOverride;
        range("/daylight/sun/altitude_deg", "altitude_deg", s.altitudeDeg, 0, 90);
        range("/daylight/sun/azimuth_deg", "azimuth_deg", s.azimuthDeg, 0, 360);
        if (s.normalIlluminanceLx && (!(*s.normalIlluminanceLx >= 0) || !std::isfinite(*s.normalIlluminanceLx)))
            add("/daylight/sun/normal_illuminance_lx",
                "normal_illuminance_lx " + formatNumber(*s.normalIlluminanceLx) + " must be >= 0");
        else if (s.normalIlluminanceLx && *s.normalIlluminanceLx > limits::kMaxIlluminanceLx)
            add("/daylight/sun/normal_illuminance_lx", "normal_illuminance_lx " + formatNumber(*s.normalIlluminanceLx) +
                                                           " exceeds the limit of " + formatNumber(limits::kMaxIlluminanceLx));
        if (p.from || p.to) add("/daylight/sun", "only one of \"sun\" override and \"from\"/\"to\"");
    }
    if (p.model == SkyModelType::Perez && p.sunOverride)
        add("/daylight/sun", "sky model \"perez\" takes its sun from the weather file; \"sun\" may only be true or false");
    if (!hasOwnSun(p.model) && p.sunEnabled() && !(p.sunOverride && p.sunOverride->normalIlluminanceLx))
        add("/daylight/sun", "sky model " + inQuotes(model) +
                                 " has no sun of its own; set \"sun\": false or give a fixed sun with "
                                 "\"normal_illuminance_lx\"");
    if (needsSunPosition(p.model) && !p.sunOverride && !p.from)
        add("/daylight", "sky model " + inQuotes(model) +
                             " needs a time (\"from\") or a fixed \"sun\" {\"altitude_deg\", \"azimuth_deg\"}");
    if (p.to && !p.from) add("/daylight/to", "\"to\" needs \"from\"");
    if (p.weather) {
        // The steps are the file's hours, and from/to a span of its year that may wrap
        // over New Year (weatherHoursIn): no order or step count to check.
    } else if (!(p.stepMinutes > 0) || !std::isfinite(p.stepMinutes))
        add("/daylight/step_minutes", "step_minutes " + formatNumber(p.stepMinutes) + " must be > 0");
    else if (p.from && p.to) {
        if (p.to->julianDayUT() < p.from->julianDayUT())
            add("/daylight/to", "\"to\" " + p.to->str() + " is before \"from\" " + p.from->str());
        else if (!(stepCount(*p.from, *p.to, p.stepMinutes) <= kMaxDaylightSteps))
            add("/daylight/step_minutes", "from..to every " + formatNumber(p.stepMinutes) + " minutes is " +
                                              formatNumber(stepCount(*p.from, *p.to, p.stepMinutes)) +
                                              " time steps, which exceeds the limit of " + std::to_string(kMaxDaylightSteps));
    }
    if (p.model == SkyModelType::Perez && p.weather && weatherHoursIn(*p.weather, p.from, p.to).empty())
        add(p.to ? "/daylight/to" : "/daylight/from",
            "no hour of the weather file has its middle in " + (p.from ? p.from->str() : std::string("...")) +
                (p.to ? " to " + p.to->str() : std::string()) + " (compared by month, day and time of day)");
    range("/daylight/ground_reflectance", "ground_reflectance", p.groundReflectance, 0, 1);
    if (!(p.pressureMbar > 0) || !std::isfinite(p.pressureMbar))
        add("/daylight/pressure_mbar", "pressure_mbar " + formatNumber(p.pressureMbar) + " must be > 0");
    if (!(p.temperatureC > -273.15) || !std::isfinite(p.temperatureC))
        add("/daylight/temperature_c", "temperature_c " + formatNumber(p.temperatureC) + " must be > -273.15");
    return d;
}

std::vector<DaylightInstant> daylightInstants(const DaylightParams& p, const Site& site) {
    if (auto diags = validateDaylight(p, site); !diags.empty()) throw SceneError(std::move(diags));
    std::vector<DaylightInstant> out;
    const bool sunOn = p.sunEnabled();
    auto sunIlluminance = [&](double altitudeDeg) {
        if (!sunOn || altitudeDeg < 0) return 0.0;
        if (p.sunOverride && p.sunOverride->normalIlluminanceLx) return *p.sunOverride->normalIlluminanceLx;
        return preethamSunNormalIlluminance(p.turbidity, radians(90 - altitudeDeg));
    };

    if (p.model == SkyModelType::Perez) {
        const WeatherFile& weather = *p.weather;
        SolarObserver observer;
        observer.latitudeDeg = site.latitudeDeg;
        observer.longitudeDeg = site.longitudeDeg;
        observer.pressureMbar = p.pressureMbar;
        observer.temperatureC = p.temperatureC;
        const std::vector<size_t> hours = weatherHoursIn(weather, p.from, p.to);
        out.reserve(hours.size());
        for (size_t index : hours) {
            DaylightInstant i;
            i.weatherHour = index;
            i.time = weather.middleOf(weather.hours[index]);
            SolarPosition sp = solarPosition(*i.time, observer);
            i.hasSunPosition = true;
            i.sunAltitudeDeg = sp.altitudeDeg;
            i.sunAzimuthDeg = sp.azimuthDeg;
            i.sunDirection = horizonToScene(sp.altitudeDeg, sp.azimuthDeg, site.northDeg);
            if (sunOn && sp.altitudeDeg >= 0) i.sunNormalIlluminanceLx = perezConditionOf(p, i).directNormalLx;
            out.push_back(i);
        }
    } else if (p.sunOverride) {
        DaylightInstant i;
        i.hasSunPosition = true;
        i.sunAltitudeDeg = p.sunOverride->altitudeDeg;
        i.sunAzimuthDeg = p.sunOverride->azimuthDeg;
        i.sunDirection = horizonToScene(i.sunAltitudeDeg, i.sunAzimuthDeg, site.northDeg);
        i.sunNormalIlluminanceLx = sunIlluminance(i.sunAltitudeDeg);
        out.push_back(i);
    } else if (p.from) {
        SolarObserver observer;
        observer.latitudeDeg = site.latitudeDeg;
        observer.longitudeDeg = site.longitudeDeg;
        observer.pressureMbar = p.pressureMbar;
        observer.temperatureC = p.temperatureC;
        const long long n = p.to ? (long long)stepCount(*p.from, *p.to, p.stepMinutes) : 1;  // validated above
        out.reserve(size_t(n));
        for (long long k = 0; k < n; ++k) {
            DaylightInstant i;
            i.time = p.from->plusMinutes(double(k) * p.stepMinutes);
            SolarPosition sp = solarPosition(*i.time, observer);
            i.hasSunPosition = true;
            i.sunAltitudeDeg = sp.altitudeDeg;
            i.sunAzimuthDeg = sp.azimuthDeg;
            i.sunDirection = horizonToScene(sp.altitudeDeg, sp.azimuthDeg, site.northDeg);
            i.sunNormalIlluminanceLx = sunIlluminance(sp.altitudeDeg);
            out.push_back(i);
        }
    } else {
        out.push_back(DaylightInstant{});  // time-independent sky (uniform, overcast)
    }
    return out;
}

PerezSkyCondition perezConditionOf(const DaylightParams& p, const DaylightInstant& i) {
    if (!p.weather || !i.weatherHour || *i.weatherHour >= p.weather->hours.size())
        throw std::invalid_argument("perezConditionOf: the instant has no hour of the scene's weather file");
    const WeatherHour& h = p.weather->hours[*i.weatherHour];
    PerezSkyInput in;
    in.sunZenithDeg = 90 - i.sunAltitudeDeg;
    if (!(in.sunZenithDeg < 90)) return {};  // night: whatever the file says, a dark sky
    for (auto [value, what] : {std::pair{h.directNormalWm2, "direct normal"}, std::pair{h.diffuseHorizontalWm2, "diffuse horizontal"}})
        if (std::isnan(value))
            throw FileError(p.weather->file.string(), std::to_string(h.line),
                            "the " + std::string(what) + " irradiance of " + i.time.value_or(p.weather->middleOf(h)).str() +
                                " is missing (the file's code 9999), with the sun up: the Perez sky of that hour needs it");
    in.directNormalWm2 = h.directNormalWm2;
    in.diffuseHorizontalWm2 = h.diffuseHorizontalWm2;
    in.dayOfYear = dayOfYear(h.month, h.day);
    in.dewPointC = h.dewPointC;  // missing (NaN): 2 cm of water, gendaylit's default
    return perezSkyCondition(in);
}

std::function<double(const Vec3&)> skyLuminanceAt(const DaylightParams& p, const DaylightInstant& i) {
    const bool sunUp = i.hasSunPosition && i.sunAltitudeDeg >= 0;
    switch (p.model) {
        case SkyModelType::CieOvercast: {
            const CieOvercastSky sky(*p.horizontalIlluminanceLx);
            return [sky](const Vec3& w) { return w.z < 0 ? 0.0 : sky.luminance(w); };
        }
        case SkyModelType::Uniform: {
            const double l = *p.luminanceNits;
            return [l](const Vec3& w) { return w.z < 0 ? 0.0 : l; };
        }
        case SkyModelType::Preetham:
            if (!sunUp) break;
            return [sky = PreethamSky(p.turbidity, i.sunDirection)](const Vec3& w) {
                return w.z < 0 ? 0.0 : luminance(sky.row(w.z).rgb(w));
            };
        case SkyModelType::CieGeneral:
            if (!sunUp) break;
            return [sky = CieGeneralSky(p.cieSkyType, i.sunDirection, *p.horizontalIlluminanceLx)](const Vec3& w) {
                return w.z < 0 ? 0.0 : sky.luminance(w);
            };
        case SkyModelType::Perez:
            if (!sunUp) break;
            return [sky = PerezAllWeatherSky(perezConditionOf(p, i), i.sunDirection)](const Vec3& w) { return sky.luminance(w); };
    }
    return [](const Vec3&) { return 0.0; };
}

DaylightEnvironment buildDaylight(const DaylightParams& p, const Site& site, const DaylightBakeOptions& options) {
    const std::vector<DaylightInstant> instants = daylightInstants(p, site);
    SkyMap map(options.width, options.height);
    const int skyRows = options.height / 2, ss = std::max(1, options.supersample);
    const double weight = 1.0 / double(instants.size());

    // The sky: time-independent models are baked once, the others once per instant with the
    // sun up (a sun below the horizon leaves that instant's sky dark; twilight is not modelled).
    if (p.model == SkyModelType::CieOvercast) {
        CieOvercastSky sky(*p.horizontalIlluminanceLx);
        map.accumulate([&](double) { return [&](const Vec3& w) { double l = sky.luminance(w); return Vec3(l, l, l); }; },
                       1.0, ss, 0, skyRows);
    } else if (p.model == SkyModelType::Uniform) {
        const double l = *p.luminanceNits;
        map.accumulate([&](double) { return [&](const Vec3&) { return Vec3(l, l, l); }; }, 1.0, 1, 0, skyRows);
    } else {
        int total = 0, baked = 0;
        for (const DaylightInstant& i : instants) total += i.hasSunPosition && i.sunAltitudeDeg >= 0;
        for (const DaylightInstant& i : instants) {
            if (!i.hasSunPosition || i.sunAltitudeDeg < 0) continue;
            if (p.model == SkyModelType::Preetham) {
                PreethamSky sky(p.turbidity, i.sunDirection);
                map.accumulate([&](double z) { return [row = sky.row(z)](const Vec3& w) { return row.rgb(w); }; },
                               weight, ss, 0, skyRows);
            } else if (p.model == SkyModelType::Perez) {
                const PerezSkyCondition c = perezConditionOf(p, i);
                if (c.lit && c.diffuseHorizontalLx > 0) {  // an unlit hour leaves its share dark
                    const PerezAllWeatherSky sky(c, i.sunDirection);
                    map.accumulate(
                        [&](double z) {
                            return [row = sky.row(z)](const Vec3& w) { double l = row.luminance(w); return Vec3(l, l, l); };
                        },
                        weight, ss, 0, skyRows);
                }
            } else {
                CieGeneralSky sky(p.cieSkyType, i.sunDirection, *p.horizontalIlluminanceLx);
                map.accumulate(
                    [&](double) { return [&](const Vec3& w) { double l = sky.luminance(w); return Vec3(l, l, l); }; },
                    weight, ss, 0, skyRows);
            }
            if (options.onStep) options.onStep(++baked, total);
        }
    }

    // One sharp disk per instant with the sun up, carrying that instant's share of the average.
    std::vector<SunDisk> disks;
    for (const DaylightInstant& i : instants) {
        if (!i.sunUp()) continue;
        SunDisk s;
        s.direction = i.sunDirection;
        s.altitudeDeg = i.sunAltitudeDeg;
        s.azimuthDeg = i.sunAzimuthDeg;
        s.weight = weight;
        s.normalIlluminanceLx = i.sunNormalIlluminanceLx;
        s.luminance = weight * i.sunNormalIlluminanceLx / kSunDiskProjectedSolidAngle;
        s.color = usesTurbidity(p) ? preethamSunColor(p.turbidity, radians(90 - i.sunAltitudeDeg)) : Vec3(1, 1, 1);
        disks.push_back(s);
    }
    return DaylightEnvironment(std::move(map), std::move(disks), p.groundReflectance);
}

bool occupiedAt(const DaylightParams::Occupancy& occupied, const DateTime& t) {
    const double hour = t.hour + t.minute / 60.0 + t.second / 3600.0;
    if (!(hour >= occupied.hours[0] && hour < occupied.hours[1])) return false;
    const int weekday = isoWeekday(t.year, t.month, t.day);
    return std::find(occupied.weekdays.begin(), occupied.weekdays.end(), weekday) != occupied.weekdays.end();
}

}  // namespace luxplan
