// Weather files: EnergyPlus weather (EPW), as Radiance/Honeybee and Ladybug read them.
// A file gives the site (its LOCATION line) and one record per hour of a year; hour h
// of a day covers [h-1, h] local standard time. docs/daylight.md, "Weather files".
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <luxplan/daylight/datetime.h>

namespace luxplan {

// One hour of the file. A field the file marks missing (EnergyPlus's codes: a value at
// or above 9999 for irradiances, 999900 for illuminances, 99.9 for the dew point) is NaN.
struct WeatherHour {
    int year = 0, month = 1, day = 1, hour = 1;  // as the file gives them; hour 1..24
    double dewPointC = 0;
    double globalHorizontalWm2 = 0, directNormalWm2 = 0, diffuseHorizontalWm2 = 0;
    double globalHorizontalLx = 0, directNormalLx = 0, diffuseHorizontalLx = 0;
    int line = 0;  // in the file, for messages
};

struct WeatherFile {
    std::filesystem::path file;
    std::string city, country, source;  // LOCATION's fields 2, 4 and 5
    std::string state, wmo;             // LOCATION's fields 3 and 6
    double latitudeDeg = 0, longitudeDeg = 0;  // north and east positive
    double timeZoneHours = 0;                  // local standard time - UT
    double elevationM = 0;
    std::vector<WeatherHour> hours;  // 8760 or 8784 (a leap year), in file order
    // The calendar year the hours are placed in (their sun, their weekday): the rows'
    // own year when every row has the same one (an actual year); for a typical year,
    // whose months come from different years, the first year from 2001 on that starts
    // on DATA PERIODS' weekday and has 29 February exactly when the file does.
    int calendarYear = 2001;

    // The middle of `h` in local standard time with the file's offset (hour 13 of
    // 21 June: 12:30) in calendarYear: where its sun is placed and how it is reported.
    DateTime middleOf(const WeatherHour& h) const;
    // The file's time zone as a UTC offset in minutes.
    int utcOffsetMinutes() const;
};

// Reads an EPW file: 8 header lines (LOCATION first, DATA PERIODS last), then one line
// of at least 35 comma-separated fields per hour, from 1 January hour 1 hour by hour to
// 31 December hour 24. Throws FileError (core/error.h) "FILE:LINE: message" for a
// missing or unreadable file, a missing or malformed LOCATION, a line with too few
// fields or a non-numeric field that is read, a date out of order or that does not
// exist, or a count of hours other than 8760 or 8784; "FILE: message" for a file that
// is missing, empty or larger than limits::kMaxWeatherFileBytes.
WeatherFile readEpw(const std::filesystem::path& file);

// The indices of the hours whose middle lies in [from, to], compared by month, day and
// time of day in the file's time zone (the year ignored: a period whose `to` comes
// before its `from` in the year wraps over New Year). Only `from`: the one hour whose
// span [h-1, h) contains it. Neither: every hour.
std::vector<size_t> weatherHoursIn(const WeatherFile& weather, const std::optional<DateTime>& from,
                                   const std::optional<DateTime>& to);

}  // namespace luxplan
