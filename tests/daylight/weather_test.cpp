// The EPW reader against Chicago O'Hare's TMY3 file (values read off its lines by hand),
// files built from it (a leap year, missing codes, CRLF) and every error it reports;
// the selection of a file's hours by date.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <luxplan/core/error.h>
#include <luxplan/core/limits.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/weather.h>

#include "support/temp_files.h"
#include "support/test_data.h"

namespace luxplan {
namespace weather_reader {

using test::TempDir;

std::vector<std::string> chicagoLines() {
    std::ifstream in(test::kChicagoEpw);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

std::string join(const std::vector<std::string>& lines, const char* end = "\n") {
    std::string s;
    for (const std::string& l : lines) s += l + end;
    return s;
}

// Field i (0-based) of a comma-separated line replaced.
std::string withField(const std::string& line, size_t i, const std::string& value) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    f.at(i) = value;
    std::string out;
    for (size_t k = 0; k < f.size(); ++k) out += (k ? "," : "") + f[k];
    return out;
}

// The message readEpw throws for `text` written to a file, "" if it reads.
std::string errorOf(const TempDir& dir, const std::string& text) {
    auto path = dir.write("bad.epw", text);
    try {
        readEpw(path);
    } catch (const FileError& e) {
        return e.what();
    }
    return "";
}

// Line numbers: the header is lines 1..8, the hour with index i is line i + 9.
constexpr size_t kJune21Hour13 = 4116;  // (151 + 20) days * 24 + 12

TEST(Epw, ReadsChicagoLocation) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    EXPECT_EQ(w.city, "Chicago Ohare Intl Ap");
    EXPECT_EQ(w.state, "IL");
    EXPECT_EQ(w.country, "USA");
    EXPECT_EQ(w.source, "TMY3");
    EXPECT_EQ(w.wmo, "725300");
    EXPECT_DOUBLE_EQ(w.latitudeDeg, 41.98);
    EXPECT_DOUBLE_EQ(w.longitudeDeg, -87.92);
    EXPECT_DOUBLE_EQ(w.timeZoneHours, -6.0);
    EXPECT_EQ(w.utcOffsetMinutes(), -360);
    EXPECT_DOUBLE_EQ(w.elevationM, 201.0);
    EXPECT_EQ(w.hours.size(), 8760u);
    // A typical year (January 1986, June 1979, ...) placed in the first year from 2001
    // that starts on DATA PERIODS' Sunday and has no 29 February: 1 January 2006 was a Sunday.
    EXPECT_EQ(w.calendarYear, 2006);
}

TEST(Epw, ReadsChicagoRows) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    // Line 9: 1986,1,1,1,0,...,-12.2,-16.1,73,99500,0,0,218,0,0,0,0,0,0,...
    const WeatherHour& first = w.hours.front();
    EXPECT_EQ(first.year, 1986);
    EXPECT_EQ(first.month, 1);
    EXPECT_EQ(first.day, 1);
    EXPECT_EQ(first.hour, 1);
    EXPECT_EQ(first.line, 9);
    EXPECT_DOUBLE_EQ(first.dewPointC, -16.1);
    EXPECT_EQ(first.globalHorizontalWm2, 0);
    // Line 4125: 1979,6,21,13,0,...,30.6,13.3,35,99000,1240,1322,405,895,734,205,96600,75500,25700,...
    const WeatherHour& noon = w.hours[kJune21Hour13];
    EXPECT_EQ(noon.year, 1979);
    EXPECT_EQ(noon.month, 6);
    EXPECT_EQ(noon.day, 21);
    EXPECT_EQ(noon.hour, 13);
    EXPECT_EQ(noon.line, 4125);
    EXPECT_DOUBLE_EQ(noon.dewPointC, 13.3);
    EXPECT_DOUBLE_EQ(noon.globalHorizontalWm2, 895);
    EXPECT_DOUBLE_EQ(noon.directNormalWm2, 734);
    EXPECT_DOUBLE_EQ(noon.diffuseHorizontalWm2, 205);
    EXPECT_DOUBLE_EQ(noon.globalHorizontalLx, 96600);
    EXPECT_DOUBLE_EQ(noon.directNormalLx, 75500);
    EXPECT_DOUBLE_EQ(noon.diffuseHorizontalLx, 25700);
    // Line 8768: 1981,12,31,24,0,...,-6.1,-8.9,...
    const WeatherHour& last = w.hours.back();
    EXPECT_EQ(last.year, 1981);
    EXPECT_EQ(last.month, 12);
    EXPECT_EQ(last.day, 31);
    EXPECT_EQ(last.hour, 24);
    EXPECT_EQ(last.line, 8768);
    EXPECT_DOUBLE_EQ(last.dewPointC, -8.9);
}

TEST(Epw, HourMiddleInLocalStandardTime) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    EXPECT_EQ(w.middleOf(w.hours[kJune21Hour13]).str(), "2006-06-21T12:30-06:00");
    EXPECT_EQ(w.middleOf(w.hours.front()).str(), "2006-01-01T00:30-06:00");
    EXPECT_EQ(w.middleOf(w.hours.back()).str(), "2006-12-31T23:30-06:00");
}

TEST(Epw, LeapYearOf8784Hours) {
    auto lines = chicagoLines();
    // 29 February after 28 February (lines 9 + 58 * 24 ..): that day's rows again, as the 29th.
    const size_t feb29 = 8 + 59 * 24;
    std::vector<std::string> extra;
    for (size_t i = feb29 - 24; i < feb29; ++i) extra.push_back(withField(lines[i], 2, "29"));
    lines.insert(lines.begin() + long(feb29), extra.begin(), extra.end());
    TempDir dir;
    WeatherFile w = readEpw(dir.write("leap.epw", join(lines)));
    ASSERT_EQ(w.hours.size(), 8784u);
    EXPECT_EQ(w.hours[59 * 24].month, 2);
    EXPECT_EQ(w.hours[59 * 24].day, 29);
    EXPECT_EQ(w.hours[59 * 24].line, 1425);
    EXPECT_EQ(w.hours[60 * 24].month, 3);
    // A leap year starting on a Sunday: 2012.
    EXPECT_EQ(w.calendarYear, 2012);
    EXPECT_EQ(w.middleOf(w.hours[59 * 24 + 12]).str(), "2012-02-29T12:30-06:00");
}

TEST(Epw, ActualYearKeepsItsYear) {
    auto lines = chicagoLines();
    for (size_t i = 8; i < lines.size(); ++i) lines[i] = withField(lines[i], 0, "2019");
    TempDir dir;
    WeatherFile w = readEpw(dir.write("2019.epw", join(lines)));
    EXPECT_EQ(w.calendarYear, 2019);
    EXPECT_EQ(w.middleOf(w.hours[kJune21Hour13]).str(), "2019-06-21T12:30-06:00");
}

TEST(Epw, MissingCodesAreNaN) {
    auto lines = chicagoLines();
    std::string& row = lines[8 + kJune21Hour13];
    row = withField(row, 7, "99.9");
    row = withField(row, 13, "9999");
    row = withField(row, 14, "9999");
    row = withField(row, 15, "10000");  // at or above the code: missing, as EnergyPlus reads it
    row = withField(row, 16, "999999");
    row = withField(row, 17, "999900");
    row = withField(row, 18, "999999");
    TempDir dir;
    WeatherFile w = readEpw(dir.write("missing.epw", join(lines)));
    const WeatherHour& h = w.hours[kJune21Hour13];
    EXPECT_TRUE(std::isnan(h.dewPointC));
    EXPECT_TRUE(std::isnan(h.globalHorizontalWm2));
    EXPECT_TRUE(std::isnan(h.directNormalWm2));
    EXPECT_TRUE(std::isnan(h.diffuseHorizontalWm2));
    EXPECT_TRUE(std::isnan(h.globalHorizontalLx));
    EXPECT_TRUE(std::isnan(h.directNormalLx));
    EXPECT_TRUE(std::isnan(h.diffuseHorizontalLx));
    // Just below the codes: values.
    EXPECT_DOUBLE_EQ(w.hours[kJune21Hour13 + 1].diffuseHorizontalWm2, 224);
}

TEST(Epw, CrlfAndNoFinalLineEnd) {
    auto lines = chicagoLines();
    TempDir dir;
    WeatherFile crlf = readEpw(dir.write("crlf.epw", join(lines, "\r\n")));
    ASSERT_EQ(crlf.hours.size(), 8760u);
    EXPECT_DOUBLE_EQ(crlf.hours[kJune21Hour13].diffuseHorizontalLx, 25700);
    EXPECT_EQ(crlf.source, "TMY3");
    std::string text = join(lines);
    text.pop_back();
    EXPECT_EQ(readEpw(dir.write("open.epw", text)).hours.size(), 8760u);
    EXPECT_EQ(readEpw(dir.write("blank.epw", join(lines) + "\n\n")).hours.size(), 8760u);
}

// ---- errors: each with its FILE:LINE ----

TEST(EpwErrors, FileAsAWhole) {
    TempDir dir;
    const std::string missing = (dir.path() / "none.epw").string();
    try {
        readEpw(missing);
        FAIL();
    } catch (const FileError& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": no such file");
    }
    const std::string file = (dir.path() / "bad.epw").string();
    EXPECT_EQ(errorOf(dir, ""), file + ": empty file (an EPW file starts with its LOCATION line)");
    try {
        readEpw(dir.path());
        FAIL();
    } catch (const FileError& e) {
        EXPECT_EQ(std::string(e.what()), dir.path().string() + ": not a regular file (a folder, FIFO or device cannot be read)");
    }
    // A sparse file just over the limit: refused before it is read.
    auto big = dir.write("big.epw", "LOCATION");
    std::filesystem::resize_file(big, limits::kMaxWeatherFileBytes + 1);
    try {
        readEpw(big);
        FAIL();
    } catch (const FileError& e) {
        EXPECT_EQ(std::string(e.what()), big.string() + ": file of " + std::to_string(limits::kMaxWeatherFileBytes + 1) +
                                             " bytes exceeds the limit of " +
                                             std::to_string(limits::kMaxWeatherFileBytes) + " bytes");
    }
}

TEST(EpwErrors, Location) {
    auto lines = chicagoLines();
    TempDir dir;
    const std::string f = (dir.path() / "bad.epw").string();
    auto with = [&](const std::string& location) {
        auto l = lines;
        l[0] = location;
        return errorOf(dir, join(l));
    };
    EXPECT_EQ(with("1986,1,1,1,0"), f + ":1: expected the LOCATION line (LOCATION,city,state,country,source,WMO,latitude,"
                                         "longitude,time zone,elevation), got \"1986,1,1,1,0\"");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,41.98,-87.92,-6.0"),
              f + ":1: LOCATION has 9 fields, expected 10 (LOCATION,city,state,country,source,WMO,latitude,"
                  "longitude,time zone,elevation)");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,north,-87.92,-6.0,201.0"),
              f + ":1: field 7 (LOCATION latitude) is \"north\", not a number");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,41.98,,-6.0,201.0"),
              f + ":1: field 8 (LOCATION longitude) is empty, expected a number");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,41.98,-87.92,CST,201.0"),
              f + ":1: field 9 (LOCATION time zone) is \"CST\", not a number");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,91,-87.92,-6.0,201.0"),
              f + ":1: LOCATION latitude 91 outside [-90, 90]");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,41.98,-187.92,-6.0,201.0"),
              f + ":1: LOCATION longitude -187.92 outside [-180, 180]");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,41.98,-87.92,-13,201.0"),
              f + ":1: LOCATION time zone -13 h outside [-12, 14]");
    EXPECT_EQ(with("LOCATION,Chicago,IL,USA,TMY3,725300,41.98,-87.92,5.33,201.0"),
              f + ":1: LOCATION time zone 5.33 h is not a whole number of minutes");
    // India's +5:30 and Nepal's +5:45 are whole minutes.
    auto l = lines;
    l[0] = "LOCATION,Kathmandu,-,NPL,TMY3,444540,27.7,85.37,5.75,1337";
    EXPECT_EQ(readEpw(dir.write("npl.epw", join(l))).utcOffsetMinutes(), 345);
}

TEST(EpwErrors, Header) {
    auto lines = chicagoLines();
    TempDir dir;
    const std::string f = (dir.path() / "bad.epw").string();
    EXPECT_EQ(errorOf(dir, join({lines.begin(), lines.begin() + 5})),
              f + ":5: the file ends in its header: an EPW file has 8 header lines, then one line per hour");
    auto l = lines;
    l.erase(l.begin() + 6);  // COMMENTS 2: the first hour becomes the 8th line
    EXPECT_EQ(errorOf(dir, join(l)),
              f + ":8: expected the DATA PERIODS line (the 8th header line of an EPW file), got \"" + lines[8].substr(0, 40) + "\"");
    l = lines;
    l[7] = "DATA PERIODS,1,4,Data,Sunday, 1/ 1,12/31";
    EXPECT_EQ(errorOf(dir, join(l)),
              f + ":8: DATA PERIODS gives 4 records per hour; only hourly files (1 record per hour) are read");
    l[7] = "DATA PERIODS,1,1,Data,Sun, 1/ 1,12/31";
    EXPECT_EQ(errorOf(dir, join(l)),
              f + ":8: DATA PERIODS start weekday \"Sun\" is not a weekday name (Sunday .. Saturday)");
}

TEST(EpwErrors, Rows) {
    auto lines = chicagoLines();
    TempDir dir;
    const std::string f = (dir.path() / "bad.epw").string();
    const size_t at = 8 + kJune21Hour13;  // line 4125
    auto with = [&](size_t index, const std::string& row) {
        auto l = lines;
        l[index] = row;
        return errorOf(dir, join(l));
    };
    EXPECT_EQ(with(at, lines[at].substr(0, lines[at].rfind(','))), f + ":4125: 34 fields, an hourly row has 35");
    EXPECT_EQ(with(at, withField(lines[at], 7, "x")), f + ":4125: field 8 (dew point temperature) is \"x\", not a number");
    EXPECT_EQ(with(at, withField(lines[at], 14, "7e")), f + ":4125: field 15 (direct normal radiation) is \"7e\", not a number");
    EXPECT_EQ(with(at, withField(lines[at], 18, "")), f + ":4125: field 19 (diffuse horizontal illuminance) is empty, expected a number");
    EXPECT_EQ(with(at, withField(lines[at], 3, "12.5")), f + ":4125: field 4 (hour) is 12.5, expected a whole number");
    EXPECT_EQ(with(at, withField(lines[at], 1, "13")), f + ":4125: month 13 outside [1, 12]");
    EXPECT_EQ(with(at, withField(lines[at], 2, "31")), f + ":4125: day 31 does not exist in June (1 to 30)");
    EXPECT_EQ(with(at, withField(lines[at], 3, "25")), f + ":4125: hour 25 outside [1, 24] (hour h covers [h-1, h])");
    EXPECT_EQ(with(at, withField(lines[at], 3, "0")), f + ":4125: hour 0 outside [1, 24] (hour h covers [h-1, h])");
    EXPECT_EQ(with(at, withField(lines[at], 3, "14")),
              f + ":4125: 21 June hour 14 after 21 June hour 12: the rows must be the year's hours one after another");
    EXPECT_EQ(with(8, withField(lines[8], 2, "2")),
              f + ":9: the first hourly row is 2 January hour 1; a weather file's year starts on 1 January hour 1");
    EXPECT_EQ(with(at, ""), f + ":4125: empty line among the hourly rows");
}

TEST(EpwErrors, HoursOfTheYear) {
    auto lines = chicagoLines();
    TempDir dir;
    const std::string f = (dir.path() / "bad.epw").string();
    auto l = lines;
    l.pop_back();  // 8759 rows: the year ends at 31 December hour 23
    EXPECT_EQ(errorOf(dir, join(l)),
              f + ":8767: 8759 hourly rows, expected 8760 (a whole year, 1 January hour 1 to 31 December hour 24; "
                  "8784 with 29 February)");
    l = lines;
    l.push_back(lines.back());
    EXPECT_EQ(errorOf(dir, join(l)), f + ":8769: a row after 31 December hour 24: the year has ended");
    // The last line cut short, with no line end after it.
    std::string text = join(lines);
    text.resize(text.size() - 60);
    EXPECT_EQ(errorOf(dir, text), f + ":8768: the last line is truncated: 23 fields and no line end, an hourly row has 35");
    // Only the header.
    EXPECT_EQ(errorOf(dir, join({lines.begin(), lines.begin() + 8})),
              f + ":8: 0 hourly rows, expected 8760 (a whole year, 1 January hour 1 to 31 December hour 24; 8784 with 29 February)");
}

TEST(EpwErrors, LeapDayOfAnActualYear) {
    auto lines = chicagoLines();
    for (size_t i = 8; i < lines.size(); ++i) lines[i] = withField(lines[i], 0, "2019");
    const size_t feb29 = 8 + 59 * 24;
    std::vector<std::string> extra;
    for (size_t i = feb29 - 24; i < feb29; ++i) extra.push_back(withField(lines[i], 2, "29"));
    lines.insert(lines.begin() + long(feb29), extra.begin(), extra.end());
    TempDir dir;
    const std::string f = (dir.path() / "bad.epw").string();
    EXPECT_EQ(errorOf(dir, join(lines)), f + ":1425: 29 February in 2019, which is not a leap year");
}

// ---- hours by date ----

DateTime at(const char* iso) { return parseIso8601(iso).value(); }

TEST(WeatherHoursIn, AllWithoutAPeriod) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    auto all = weatherHoursIn(w, std::nullopt, std::nullopt);
    ASSERT_EQ(all.size(), 8760u);
    EXPECT_EQ(all.front(), 0u);
    EXPECT_EQ(all.back(), 8759u);
}

TEST(WeatherHoursIn, ByMonthDayAndTimeInTheFilesZone) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    // Middles 12:30 and 13:30 lie in [12:00, 14:00]; the year is ignored.
    std::vector<size_t> noon{kJune21Hour13, kJune21Hour13 + 1};
    EXPECT_EQ(weatherHoursIn(w, at("2026-06-21T12:00-06:00"), at("2026-06-21T14:00-06:00")), noon);
    // The same instants written in UT.
    EXPECT_EQ(weatherHoursIn(w, at("1999-06-21T18:00Z"), at("1999-06-21T20:00Z")), noon);
    // Ends inclusive: [12:30, 13:30] still holds both middles.
    EXPECT_EQ(weatherHoursIn(w, at("2026-06-21T12:30-06:00"), at("2026-06-21T13:30-06:00")), noon);
    // A whole year.
    EXPECT_EQ(weatherHoursIn(w, at("2026-01-01T00:00-06:00"), at("2026-12-31T23:59-06:00")).size(), 8760u);
}

TEST(WeatherHoursIn, WrapsOverNewYear) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    // 31 December 22:30 and 23:30, 1 January 00:30 and 01:30.
    std::vector<size_t> expected{0, 1, 8758, 8759};
    EXPECT_EQ(weatherHoursIn(w, at("2026-12-31T22:00-06:00"), at("2027-01-01T02:00-06:00")), expected);
}

TEST(WeatherHoursIn, OneInstantIsItsHour) {
    WeatherFile w = readEpw(test::kChicagoEpw);
    // Hour 13 covers [12:00, 13:00).
    std::vector<size_t> hour13{kJune21Hour13};
    EXPECT_EQ(weatherHoursIn(w, at("2026-06-21T12:00-06:00"), std::nullopt), hour13);
    EXPECT_EQ(weatherHoursIn(w, at("2026-06-21T12:59-06:00"), std::nullopt), hour13);
    EXPECT_EQ(weatherHoursIn(w, at("2026-06-21T19:00+01:00"), std::nullopt), hour13);
    // 29 February in a file without it: no hour.
    EXPECT_TRUE(weatherHoursIn(w, at("2024-02-29T12:00-06:00"), std::nullopt).empty());
}

// ---- occupancy ----

TEST(OccupiedAt, HoursAndWeekdays) {
    DaylightParams::Occupancy office;
    office.hours = {8, 18};
    office.weekdays = {1, 2, 3, 4, 5};
    // 2026-12-07 is a Monday, 2026-12-12 a Saturday.
    EXPECT_TRUE(occupiedAt(office, at("2026-12-07T08:30-06:00")));
    EXPECT_TRUE(occupiedAt(office, at("2026-12-07T08:00-06:00")));
    EXPECT_TRUE(occupiedAt(office, at("2026-12-07T17:30-06:00")));
    EXPECT_FALSE(occupiedAt(office, at("2026-12-07T18:00-06:00")));  // [8, 18): 18:00 is out
    EXPECT_FALSE(occupiedAt(office, at("2026-12-07T07:30-06:00")));
    EXPECT_FALSE(occupiedAt(office, at("2026-12-12T12:30-06:00")));
    EXPECT_TRUE(occupiedAt(office, at("2026-12-11T12:30-06:00")));  // Friday
    // The default counts every hour.
    DaylightParams::Occupancy always;
    EXPECT_TRUE(occupiedAt(always, at("2026-12-12T00:30-06:00")));
    EXPECT_TRUE(occupiedAt(always, at("2026-12-13T23:30-06:00")));
    // A year of Chicago's hours: 8..18 on weekdays of 2006 (260 weekdays) is 2600 hours.
    WeatherFile w = readEpw(test::kChicagoEpw);
    int n = 0;
    for (const WeatherHour& h : w.hours) n += occupiedAt(office, w.middleOf(h));
    EXPECT_EQ(n, 2600);
}

}  // namespace weather_reader
}  // namespace luxplan
