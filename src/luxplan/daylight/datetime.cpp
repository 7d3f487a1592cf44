// ISO 8601 parsing/printing and Julian days for DateTime.
#include <luxplan/daylight/datetime.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace luxplan {
namespace {

bool isLeap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

// Days from 1970-01-01 to y-m-d in the proleptic Gregorian calendar (H. Hinnant's
// days_from_civil, http://howardhinnant.github.io/date_algorithms.html).
int64_t daysFromCivil(int y, int m, int d) {
    y -= m <= 2;
    const int64_t era = (y >= 0 ? y : y - 399) / 400;
    const int64_t yoe = y - era * 400;
    const int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

// Inverse of daysFromCivil.
void civilFromDays(int64_t z, int& y, int& m, int& d) {
    z += 719468;
    const int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const int64_t doe = z - era * 146097;
    const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const int64_t mp = (5 * doy + 2) / 153;
    d = int(doy - (153 * mp + 2) / 5 + 1);
    m = int(mp < 10 ? mp + 3 : mp - 9);
    y = int(yoe + era * 400 + (m <= 2));
}

constexpr double kJulianDayUnixEpoch = 2440587.5;  // 1970-01-01T00:00Z

// Reads exactly n decimal digits at text[pos]; advances pos.
bool readDigits(std::string_view text, size_t& pos, int n, int& value) {
    if (pos + n > text.size()) return false;
    value = 0;
    for (int i = 0; i < n; ++i) {
        char c = text[pos + i];
        if (c < '0' || c > '9') return false;
        value = value * 10 + (c - '0');
    }
    pos += n;
    return true;
}

bool expectChar(std::string_view text, size_t& pos, char c) {
    if (pos >= text.size() || text[pos] != c) return false;
    ++pos;
    return true;
}

std::optional<DateTime> fail(std::string_view text, const std::string& why, std::string* error) {
    if (error) {
        // Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
        error->assign(1, '"');
        error->append(text).append("\": ").append(why);
    }
    return std::nullopt;
}

std::string rangeMessage(const char* field, int v, int lo, int hi) {
    return std::string(field) + " " + std::to_string(v) + " outside [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]";
}

}  // namespace

int daysInMonth(int year, int month) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12) return 0;
    return month == 2 && isLeap(year) ? 29 : kDays[month - 1];
}

int isoWeekday(int year, int month, int day) {
    // 1970-01-01 was a Thursday (ISO 4).
    const int64_t days = daysFromCivil(year, month, day);
    return int(((days % 7) + 7 + 3) % 7) + 1;
}

double DateTime::julianDayUT() const {
    double dayFraction = ((hour * 60.0 + minute - utcOffsetMinutes) * 60.0 + second) / 86400.0;
    return kJulianDayUnixEpoch + double(daysFromCivil(year, month, day)) + dayFraction;
}

DateTime DateTime::plusMinutes(double minutes) const {
    // Whole minutes are added exactly in integers; only the fraction goes through seconds.
    double whole = std::floor(minutes);
    double sec = second + (minutes - whole) * 60.0;
    int64_t total = (daysFromCivil(year, month, day) * 24 + hour) * 60 + minute + int64_t(whole);
    double carry = std::floor(sec / 60.0);
    sec -= carry * 60.0;
    total += int64_t(carry);
    // Snap rounding residue (e.g. 59.9999999999) to the next minute.
    if (sec > 60.0 - 1e-9) { sec = 0; ++total; }
    if (sec < 1e-9) sec = 0;
    int64_t days = total >= 0 ? total / 1440 : -((-total + 1439) / 1440);
    int64_t minuteOfDay = total - days * 1440;
    DateTime r = *this;
    civilFromDays(days, r.year, r.month, r.day);
    r.hour = int(minuteOfDay / 60);
    r.minute = int(minuteOfDay % 60);
    r.second = sec;
    return r;
}

std::string DateTime::str() const {
    DateTime t = *this;
    long long ms = std::llround(t.second * 1000.0);
    if (ms >= 60000) {
        t.second = 0;
        t = t.plusMinutes(1);
        ms = 0;
    }
    char buf[64];
    int n = std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d", t.year, t.month, t.day, t.hour, t.minute);
    std::string s(buf, size_t(n));
    if (ms != 0) {
        if (ms % 1000 == 0) n = std::snprintf(buf, sizeof buf, ":%02lld", ms / 1000);
        else n = std::snprintf(buf, sizeof buf, ":%02lld.%03lld", ms / 1000, ms % 1000);
        s.append(buf, size_t(n));
    }
    if (utcOffsetMinutes == 0) {
        s += "Z";
    } else {
        int a = std::abs(utcOffsetMinutes);
        n = std::snprintf(buf, sizeof buf, "%c%02d:%02d", utcOffsetMinutes < 0 ? '-' : '+', a / 60, a % 60);
        s.append(buf, size_t(n));
    }
    return s;
}

std::optional<DateTime> parseIso8601(std::string_view text, std::string* error) {
    const std::string shape = "expected YYYY-MM-DDThh:mm[:ss[.fff]] and a UTC offset (Z, +hh:mm or -hh:mm)";
    DateTime t;
    size_t pos = 0;
    if (!readDigits(text, pos, 4, t.year) || !expectChar(text, pos, '-') || !readDigits(text, pos, 2, t.month) ||
        !expectChar(text, pos, '-') || !readDigits(text, pos, 2, t.day) || !expectChar(text, pos, 'T') ||
        !readDigits(text, pos, 2, t.hour) || !expectChar(text, pos, ':') || !readDigits(text, pos, 2, t.minute))
        return fail(text, shape, error);
    std::string_view secondText;  // as written, for a message
    if (pos < text.size() && text[pos] == ':') {
        ++pos;
        const size_t start = pos;
        int whole = 0;
        if (!readDigits(text, pos, 2, whole)) return fail(text, shape, error);
        t.second = whole;
        if (pos < text.size() && text[pos] == '.') {
            ++pos;
            const size_t digits = pos;
            while (pos < text.size() && text[pos] >= '0' && text[pos] <= '9') ++pos;
            if (pos == digits) return fail(text, shape, error);
            // Rounded once, as strtod rounds "ss.fff" (digit by digit, 0.1 steps add up
            // their own rounding errors).
            t.second = std::strtod(std::string(text.substr(start, pos - start)).c_str(), nullptr);
        }
        secondText = text.substr(start, pos - start);
    }
    if (t.month < 1 || t.month > 12) return fail(text, rangeMessage("month", t.month, 1, 12), error);
    int dim = daysInMonth(t.year, t.month);
    if (t.day < 1 || t.day > dim) return fail(text, rangeMessage("day", t.day, 1, dim), error);
    if (t.hour > 23) return fail(text, rangeMessage("hour", t.hour, 0, 23), error);
    if (t.minute > 59) return fail(text, rangeMessage("minute", t.minute, 0, 59), error);
    if (t.second >= 60)
        return fail(text, "second " + std::string(secondText) + " outside [0, 60)" +
                              (secondText < "60" ? " (it rounds to 60)" : ""),
                    error);

    if (pos == text.size()) return fail(text, "has no UTC offset (append Z or an offset such as +03:00)", error);
    char sign = text[pos];
    if (sign == 'Z') {
        ++pos;
        t.utcOffsetMinutes = 0;
    } else if (sign == '+' || sign == '-') {
        ++pos;
        int oh = 0, om = 0;
        if (!readDigits(text, pos, 2, oh) || !expectChar(text, pos, ':') || !readDigits(text, pos, 2, om))
            return fail(text, "UTC offset must be Z, +hh:mm or -hh:mm", error);
        if (om > 59) return fail(text, rangeMessage("UTC offset minute", om, 0, 59), error);
        int total = oh * 60 + om;
        if (total > 18 * 60)
            return fail(text, std::string("UTC offset ") + sign + std::string(text.substr(pos - 5, 5)) +
                                  " outside [-18:00, +18:00]", error);
        t.utcOffsetMinutes = sign == '-' ? -total : total;
    } else {
        return fail(text, "unexpected \"" + std::string(text.substr(pos)) + "\" where a UTC offset (Z, +hh:mm or -hh:mm) should be", error);
    }
    if (pos != text.size())
        return fail(text, "unexpected \"" + std::string(text.substr(pos)) + "\" after the UTC offset", error);
    return t;
}

}  // namespace luxplan
