// Civil date-times with a UTC offset (ISO 8601, as the scene format writes them) and
// their Julian day, the time scale the solar-position algorithm starts from.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace luxplan {

// A civil local time with its UTC offset, as written in ISO 8601 (e.g. 2026-06-21T09:00+03:00).
// Dates are proleptic Gregorian. UT = local time - utcOffsetMinutes.
struct DateTime {
    int year = 2000, month = 1, day = 1, hour = 0, minute = 0;
    double second = 0;
    int utcOffsetMinutes = 0;

    // Julian day of the instant (UT), e.g. 2000-01-01T12:00Z -> 2451545.0.
    double julianDayUT() const;
    // The instant `minutes` later (earlier if negative), written with the same offset and
    // normalized fields (second in [0, 60), minute < 60, hour < 24, valid day of month).
    DateTime plusMinutes(double minutes) const;
    // ISO 8601 with offset: YYYY-MM-DDThh:mm, then :ss (and .fff) only if seconds are
    // non-zero, then Z for offset 0 or +hh:mm / -hh:mm. parseIso8601(str()) gives it back.
    std::string str() const;
};

// Parses YYYY-MM-DDThh:mm[:ss[.fff]](Z|+hh:mm|-hh:mm). An offset is required.
// On failure returns nullopt and, if error != nullptr, a one-line reason
// (e.g. "\"2026-13-01T09:00+03:00\": month 13 outside [1, 12]" or "... has no UTC offset").
std::optional<DateTime> parseIso8601(std::string_view text, std::string* error = nullptr);

// Days in a month of the proleptic Gregorian calendar.
int daysInMonth(int year, int month);

// ISO 8601's weekday of a date of the proleptic Gregorian calendar: 1 = Monday .. 7 = Sunday.
int isoWeekday(int year, int month, int day);

}  // namespace luxplan
