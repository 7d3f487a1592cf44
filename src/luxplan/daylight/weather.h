// Weather files: EnergyPlus weather (EPW), as Radiance/Honeybee and Ladybug read them.
// A file gives the site (its LOCATION line) and one record per hour of a year; hour h
// of a day covers [h-1, h] local standard time. docs/daylight.md, "Weather files".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <luxplan/daylight/datetime.h>

namespace luxplan {

// One hour of the file. A field the file marks missing (9999 for irradiances, 999999
// for illuminances, 99.9 for the dew point) is NaN.
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
    double latitudeDeg = 0, longitudeDeg = 0;  // north and east positive
    double timeZoneHours = 0;                  // local standard time - UT
    double elevationM = 0;
    std::vector<WeatherHour> hours;  // 8760 or 8784 (a leap year), in file order

    // The middle of `h` in local standard time with the file's offset (hour 13 of
    // 21 June: 12:30): where its sun is placed and how it is reported.
    DateTime middleOf(const WeatherHour& h) const;
};

// Reads an EPW file: 8 header lines (LOCATION first), then one line of at least 35
// comma-separated fields per hour. Throws FileError (core/error.h) "FILE:LINE: message" for a missing
// or unreadable file, a missing or malformed LOCATION, a line with too few fields or a
// non-numeric field that is read, a date out of order, or a count of hours other than
// 8760 or 8784.
WeatherFile readEpw(const std::filesystem::path& file);

}  // namespace luxplan
