// The EPW reader (EnergyPlus Auxiliary Programs, "Weather Converter Program": the
// EPW data dictionary) and the selection of a weather file's hours by date.
#include <luxplan/daylight/weather.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

#include <luxplan/core/error.h>
#include <luxplan/core/format.h>
#include <luxplan/core/limits.h>

namespace luxplan {
namespace epw {

constexpr int kHeaderLines = 8;
constexpr size_t kRowFields = 35;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const char* const kMonthNames[12] = {"January", "February", "March",     "April",   "May",      "June",
                                     "July",    "August",   "September", "October", "November", "December"};
// DATA PERIODS' weekday names, in ISO order (1 = Monday).
const char* const kWeekdayNames[7] = {"Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday", "Sunday"};

bool leapYear(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// EPW fields hold no quoting: a comma always ends a field (EnergyPlus and Ladybug split
// every line at each comma).
std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> out;
    size_t start = 0;
    for (;;) {
        size_t comma = line.find(',', start);
        out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return out;
}

std::string dateText(int month, int day, int hour) {
    return std::to_string(day) + " " + kMonthNames[month - 1] + " hour " + std::to_string(hour);
}

struct Line {
    std::string_view text;  // without its line end ("\n" or "\r\n")
    int number = 0;
    bool ended = false;  // a line end follows it
};

class Reader {
public:
    explicit Reader(std::string name) : name_(std::move(name)) {}

    [[noreturn]] void fail(int line, const std::string& message) const {
        throw FileError(name_, std::to_string(line), message);
    }

    // A field that must be a finite number; `what` names it for the message.
    double number(const Line& line, std::string_view field, int column, const char* what) const {
        std::string text(trim(field));
        const std::string where = "field " + std::to_string(column) + " (" + what + ")";
        if (text.empty()) fail(line.number, where + " is empty, expected a number");
        char* end = nullptr;
        double v = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size() || !std::isfinite(v))
            fail(line.number, where + " is \"" + text + "\", not a number");
        return v;
    }

    int integer(const Line& line, std::string_view field, int column, const char* what) const {
        double v = number(line, field, column, what);
        if (v != std::floor(v) || std::abs(v) > 1e9)
            fail(line.number, "field " + std::to_string(column) + " (" + what + ") is " + formatNumber(v) +
                                  ", expected a whole number");
        return int(v);
    }

    // A measured value, NaN at or above the file's missing code (as EnergyPlus reads it).
    double measured(const Line& line, std::string_view field, int column, const char* what, double missingAt) const {
        double v = number(line, field, column, what);
        return v >= missingAt ? kNaN : v;
    }

private:
    std::string name_;
};

std::vector<Line> splitLines(const std::string& text) {
    std::vector<Line> lines;
    size_t start = 0;
    int number = 1;
    while (start < text.size()) {
        size_t nl = text.find('\n', start);
        Line l;
        l.number = number++;
        l.ended = nl != std::string::npos;
        std::string_view s(text.data() + start, (l.ended ? nl : text.size()) - start);
        if (!s.empty() && s.back() == '\r') s.remove_suffix(1);  // CRLF files
        l.text = s;
        lines.push_back(l);
        if (!l.ended) break;
        start = nl + 1;
    }
    return lines;
}

std::string readWhole(const std::filesystem::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw FileError(name, "", "no such file");
    // Never opened otherwise: a FIFO would block, a device such as /dev/zero never end.
    if (!std::filesystem::is_regular_file(file, ec))
        throw FileError(name, "", "not a regular file (a folder, FIFO or device cannot be read)");
    if (auto size = std::filesystem::file_size(file, ec); !ec && size > limits::kMaxWeatherFileBytes)
        throw FileError(name, "", "file of " + std::to_string(size) + " bytes exceeds the limit of " +
                                      std::to_string(limits::kMaxWeatherFileBytes) + " bytes");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw FileError(name, "", "cannot open the file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

void readLocation(const Reader& r, const Line& line, WeatherFile& w) {
    auto f = splitFields(line.text);
    if (trim(f[0]) != "LOCATION")
        r.fail(line.number, "expected the LOCATION line (LOCATION,city,state,country,source,WMO,latitude,longitude,"
                            "time zone,elevation), got \"" + std::string(line.text.substr(0, 40)) + "\"");
    if (f.size() < 10)
        r.fail(line.number, "LOCATION has " + std::to_string(f.size()) +
                                " fields, expected 10 (LOCATION,city,state,country,source,WMO,latitude,longitude,"
                                "time zone,elevation)");
    w.city = std::string(trim(f[1]));
    w.state = std::string(trim(f[2]));
    w.country = std::string(trim(f[3]));
    w.source = std::string(trim(f[4]));
    w.wmo = std::string(trim(f[5]));
    w.latitudeDeg = r.number(line, f[6], 7, "LOCATION latitude");
    w.longitudeDeg = r.number(line, f[7], 8, "LOCATION longitude");
    w.timeZoneHours = r.number(line, f[8], 9, "LOCATION time zone");
    w.elevationM = r.number(line, f[9], 10, "LOCATION elevation");
    if (!(w.latitudeDeg >= -90 && w.latitudeDeg <= 90))
        r.fail(line.number, "LOCATION latitude " + formatNumber(w.latitudeDeg) + " outside [-90, 90]");
    if (!(w.longitudeDeg >= -180 && w.longitudeDeg <= 180))
        r.fail(line.number, "LOCATION longitude " + formatNumber(w.longitudeDeg) + " outside [-180, 180]");
    // Every civil time zone lies in [-12, +14] hours.
    if (!(w.timeZoneHours >= -12 && w.timeZoneHours <= 14))
        r.fail(line.number, "LOCATION time zone " + formatNumber(w.timeZoneHours) + " h outside [-12, 14]");
    const double minutes = w.timeZoneHours * 60;
    if (std::abs(minutes - std::round(minutes)) > 1e-6)
        r.fail(line.number, "LOCATION time zone " + formatNumber(w.timeZoneHours) + " h is not a whole number of minutes");
}

// DATA PERIODS,<periods>,<records per hour>,<name>,<start weekday>,<start>,<end>:
// the file's hourly step and the weekday of its first day. Returns that weekday (ISO).
int readDataPeriods(const Reader& r, const Line& line) {
    auto f = splitFields(line.text);
    if (trim(f[0]) != "DATA PERIODS")
        r.fail(line.number, "expected the DATA PERIODS line (the 8th header line of an EPW file), got \"" +
                                std::string(line.text.substr(0, 40)) + "\"");
    if (f.size() < 5)
        r.fail(line.number, "DATA PERIODS has " + std::to_string(f.size()) +
                                " fields, expected at least 5 (DATA PERIODS,periods,records per hour,name,start weekday)");
    int perHour = r.integer(line, f[2], 3, "DATA PERIODS records per hour");
    if (perHour != 1)
        r.fail(line.number, "DATA PERIODS gives " + std::to_string(perHour) +
                                " records per hour; only hourly files (1 record per hour) are read");
    std::string day(trim(f[4]));
    std::string lower = day;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (int i = 0; i < 7; ++i) {
        std::string name = kWeekdayNames[i];
        std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (lower == name) return i + 1;
    }
    r.fail(line.number, "DATA PERIODS start weekday \"" + day + "\" is not a weekday name (Sunday .. Saturday)");
}

WeatherHour readRow(const Reader& r, const Line& line) {
    auto f = splitFields(line.text);
    if (f.size() < kRowFields) {
        if (!line.ended)
            r.fail(line.number, "the last line is truncated: " + std::to_string(f.size()) +
                                    " fields and no line end, an hourly row has 35");
        r.fail(line.number, std::to_string(f.size()) + " fields, an hourly row has 35");
    }
    WeatherHour h;
    h.line = line.number;
    h.year = r.integer(line, f[0], 1, "year");
    h.month = r.integer(line, f[1], 2, "month");
    h.day = r.integer(line, f[2], 3, "day");
    h.hour = r.integer(line, f[3], 4, "hour");
    if (h.month < 1 || h.month > 12) r.fail(line.number, "month " + std::to_string(h.month) + " outside [1, 12]");
    // 29 February is a day of some year: whether the file's year has it is checked apart.
    const int days = daysInMonth(2000, h.month);
    if (h.day < 1 || h.day > days)
        r.fail(line.number, "day " + std::to_string(h.day) + " does not exist in " + kMonthNames[h.month - 1] +
                                " (1 to " + std::to_string(days) + ")");
    if (h.hour < 1 || h.hour > 24)
        r.fail(line.number, "hour " + std::to_string(h.hour) + " outside [1, 24] (hour h covers [h-1, h])");
    // Column numbers 1-based, as the EPW data dictionary counts the fields (N1 .. N35).
    h.dewPointC = r.measured(line, f[7], 8, "dew point temperature", 99.9);
    h.globalHorizontalWm2 = r.measured(line, f[13], 14, "global horizontal radiation", 9999);
    h.directNormalWm2 = r.measured(line, f[14], 15, "direct normal radiation", 9999);
    h.diffuseHorizontalWm2 = r.measured(line, f[15], 16, "diffuse horizontal radiation", 9999);
    h.globalHorizontalLx = r.measured(line, f[16], 17, "global horizontal illuminance", 999900);
    h.directNormalLx = r.measured(line, f[17], 18, "direct normal illuminance", 999900);
    h.diffuseHorizontalLx = r.measured(line, f[18], 19, "diffuse horizontal illuminance", 999900);
    return h;
}

// Whether `next` is the hour after `prev` in a calendar that may or may not hold 29 February.
bool follows(const WeatherHour& prev, const WeatherHour& next) {
    if (prev.hour < 24) return next.month == prev.month && next.day == prev.day && next.hour == prev.hour + 1;
    if (next.hour != 1) return false;
    if (prev.month == 2 && prev.day == 28) return (next.month == 2 && next.day == 29) || (next.month == 3 && next.day == 1);
    if (prev.day < daysInMonth(2000, prev.month)) return next.month == prev.month && next.day == prev.day + 1;
    return next.month == prev.month + 1 && next.day == 1;
}

}  // namespace epw

int WeatherFile::utcOffsetMinutes() const { return int(std::lround(timeZoneHours * 60)); }

DateTime WeatherFile::middleOf(const WeatherHour& h) const {
    DateTime t;
    t.year = calendarYear;
    t.month = h.month;
    t.day = h.day;
    t.hour = h.hour - 1;
    t.minute = 30;
    t.utcOffsetMinutes = utcOffsetMinutes();
    return t;
}

WeatherFile readEpw(const std::filesystem::path& file) {
    const std::string name = file.string();
    const std::string text = epw::readWhole(file);
    if (text.empty()) throw FileError(name, "", "empty file (an EPW file starts with its LOCATION line)");
    const epw::Reader r(name);
    std::vector<epw::Line> lines = epw::splitLines(text);
    // Blank lines after the last row are no rows.
    while (!lines.empty() && epw::trim(lines.back().text).empty()) lines.pop_back();
    if (lines.empty()) throw FileError(name, "", "the file holds only blank lines (an EPW file starts with its LOCATION line)");

    WeatherFile w;
    w.file = file;
    epw::readLocation(r, lines[0], w);
    if (lines.size() < size_t(epw::kHeaderLines))
        r.fail(lines.back().number, "the file ends in its header: an EPW file has 8 header lines, then one line per hour");
    const int firstWeekday = epw::readDataPeriods(r, lines[epw::kHeaderLines - 1]);

    w.hours.reserve(8784);
    bool sameYear = true, hasLeapDay = false;
    for (size_t i = epw::kHeaderLines; i < lines.size(); ++i) {
        const epw::Line& line = lines[i];
        if (epw::trim(line.text).empty()) r.fail(line.number, "empty line among the hourly rows");
        WeatherHour h = epw::readRow(r, line);
        if (w.hours.empty()) {
            if (h.month != 1 || h.day != 1 || h.hour != 1)
                r.fail(line.number, "the first hourly row is " + epw::dateText(h.month, h.day, h.hour) +
                                        "; a weather file's year starts on 1 January hour 1");
        } else {
            const WeatherHour& prev = w.hours.back();
            if (prev.month == 12 && prev.day == 31 && prev.hour == 24)
                r.fail(line.number, "a row after 31 December hour 24: the year has ended");
            if (!epw::follows(prev, h))
                r.fail(line.number, epw::dateText(h.month, h.day, h.hour) + " after " +
                                        epw::dateText(prev.month, prev.day, prev.hour) +
                                        ": the rows must be the year's hours one after another");
            sameYear = sameYear && h.year == prev.year;
        }
        hasLeapDay = hasLeapDay || (h.month == 2 && h.day == 29);
        w.hours.push_back(h);
    }
    const size_t expected = hasLeapDay ? 8784 : 8760;
    if (w.hours.size() != expected) {
        const int at = w.hours.empty() ? lines.back().number : w.hours.back().line;
        r.fail(at, std::to_string(w.hours.size()) + " hourly rows, expected " + std::to_string(expected) +
                       " (a whole year, 1 January hour 1 to 31 December hour 24" +
                       (hasLeapDay ? ", with 29 February)" : "; 8784 with 29 February)"));
    }
    if (sameYear) {
        w.calendarYear = w.hours.front().year;
        if (hasLeapDay && !epw::leapYear(w.calendarYear)) {
            auto leap = std::find_if(w.hours.begin(), w.hours.end(), [](const WeatherHour& h) { return h.month == 2 && h.day == 29; });
            r.fail(leap->line, "29 February in " + std::to_string(w.calendarYear) + ", which is not a leap year");
        }
    } else {
        // A typical year: its weekdays run on from DATA PERIODS' first day, as EnergyPlus
        // counts them; 28 years hold every combination of weekday and leap year.
        w.calendarYear = 0;
        for (int y = 2001; y < 2001 + 28 && !w.calendarYear; ++y)
            if (epw::leapYear(y) == hasLeapDay && isoWeekday(y, 1, 1) == firstWeekday) w.calendarYear = y;
    }
    return w;
}

std::vector<size_t> weatherHoursIn(const WeatherFile& weather, const std::optional<DateTime>& from,
                                   const std::optional<DateTime>& to) {
    std::vector<size_t> out;
    const int offset = weather.utcOffsetMinutes();
    // Month, day and minute of day as one ordered number, in the file's time zone.
    auto key = [](int month, int day, double minuteOfDay) { return (month * 32 + day) * 1440.0 + minuteOfDay; };
    auto local = [&](const DateTime& t) {
        DateTime l = t.plusMinutes(double(offset - t.utcOffsetMinutes));
        l.utcOffsetMinutes = offset;
        return key(l.month, l.day, l.hour * 60 + l.minute + l.second / 60);
    };
    if (!from && !to) {
        out.resize(weather.hours.size());
        for (size_t i = 0; i < out.size(); ++i) out[i] = i;
        return out;
    }
    if (!to) {
        const double k = local(*from);
        for (size_t i = 0; i < weather.hours.size(); ++i) {
            const WeatherHour& h = weather.hours[i];
            const double start = key(h.month, h.day, (h.hour - 1) * 60.0);
            if (k >= start && k < start + 60) out.push_back(i);
        }
        return out;
    }
    const double lo = from ? local(*from) : key(1, 1, 0), hi = local(*to);
    for (size_t i = 0; i < weather.hours.size(); ++i) {
        const WeatherHour& h = weather.hours[i];
        const double m = key(h.month, h.day, (h.hour - 1) * 60.0 + 30);
        if (lo <= hi ? (m >= lo && m <= hi) : (m >= lo || m <= hi)) out.push_back(i);
    }
    return out;
}

}  // namespace luxplan
