// ISO 8601 parsing, printing, Julian days and minute arithmetic of DateTime.
#include <gtest/gtest.h>

#include <luxplan/daylight/datetime.h>

namespace luxplan {
namespace {

DateTime parseOk(const char* s) {
    std::string err;
    auto t = parseIso8601(s, &err);
    EXPECT_TRUE(t.has_value()) << s << ": " << err;
    return t.value_or(DateTime{});
}

std::string parseError(const char* s) {
    std::string err;
    auto t = parseIso8601(s, &err);
    EXPECT_FALSE(t.has_value()) << s;
    return err;
}

TEST(DateTime, ParsesFieldsAndOffset) {
    DateTime t = parseOk("2026-06-21T09:00+03:00");
    EXPECT_EQ(t.year, 2026);
    EXPECT_EQ(t.month, 6);
    EXPECT_EQ(t.day, 21);
    EXPECT_EQ(t.hour, 9);
    EXPECT_EQ(t.minute, 0);
    EXPECT_EQ(t.second, 0);
    EXPECT_EQ(t.utcOffsetMinutes, 180);

    DateTime u = parseOk("2003-10-17T12:30:30.25-07:00");
    EXPECT_EQ(u.second, 30.25);
    EXPECT_EQ(u.utcOffsetMinutes, -420);
    EXPECT_EQ(parseOk("2024-02-29T23:59:59Z").utcOffsetMinutes, 0);
    EXPECT_EQ(parseOk("2024-01-01T00:00-09:30").utcOffsetMinutes, -570);
    EXPECT_EQ(parseOk("2024-01-01T00:00+05:45").utcOffsetMinutes, 345);
}

TEST(DateTime, RejectsInvalidInputWithReason) {
    EXPECT_EQ(parseError("2026-13-01T09:00+03:00"), "\"2026-13-01T09:00+03:00\": month 13 outside [1, 12]");
    EXPECT_EQ(parseError("2026-06-21T09:00"),
              "\"2026-06-21T09:00\": has no UTC offset (append Z or an offset such as +03:00)");
    EXPECT_NE(parseError("2025-02-29T09:00Z").find("day 29 outside [1, 28]"), std::string::npos);
    EXPECT_NE(parseError("2026-04-31T09:00Z").find("day 31 outside [1, 30]"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T24:00Z").find("hour 24 outside [0, 23]"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:60Z").find("minute 60 outside [0, 59]"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:00:60Z").find("second 60 outside [0, 60)"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:00+19:00").find("outside [-18:00, +18:00]"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:00+03").find("+hh:mm"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:00+03:00x").find("after the UTC offset"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21 09:00+03:00").find("expected YYYY-MM-DDThh:mm"), std::string::npos);
    EXPECT_NE(parseError("26-06-21T09:00Z").find("expected YYYY-MM-DDThh:mm"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:00:3Z").find("expected"), std::string::npos);
    EXPECT_NE(parseError("2026-06-21T09:00:30.Z").find("expected"), std::string::npos);
    EXPECT_NE(parseError("").find("expected"), std::string::npos);
    EXPECT_FALSE(parseIso8601("2026-06-21T09:00"));  // no error sink is fine
}

TEST(DateTime, JulianDayMatchesReferenceEpochs) {
    // J2000.0 and the NREL SPA worked example (JD 2452930.312847, Reda and Andreas 2004; docs/daylight.md, "Validation").
    EXPECT_DOUBLE_EQ(parseOk("2000-01-01T12:00Z").julianDayUT(), 2451545.0);
    EXPECT_NEAR(parseOk("2003-10-17T12:30:30-07:00").julianDayUT(), 2452930.312847, 5e-7);
    // Meeus, Astronomical Algorithms, example 7.a: 1957-10-04.81 -> JD 2436116.31.
    EXPECT_NEAR(parseOk("1957-10-04T19:26:24Z").julianDayUT(), 2436116.31, 1e-9);
    // The same instant in two offsets has the same Julian day.
    EXPECT_DOUBLE_EQ(parseOk("2026-06-21T09:00+03:00").julianDayUT(), parseOk("2026-06-21T06:00Z").julianDayUT());
}

TEST(DateTime, PlusMinutesNormalizesAcrossBoundaries) {
    DateTime t = parseOk("2024-12-31T23:50:30+02:00");
    DateTime u = t.plusMinutes(15);
    EXPECT_EQ(u.str(), "2025-01-01T00:05:30+02:00");
    EXPECT_NEAR(u.julianDayUT() - t.julianDayUT(), 15.0 / 1440.0, 1e-9);
    EXPECT_EQ(parseOk("2024-03-01T00:10Z").plusMinutes(-20).str(), "2024-02-29T23:50Z");
    EXPECT_EQ(parseOk("2026-06-21T09:00+03:00").plusMinutes(0.5).str(), "2026-06-21T09:00:30+03:00");
    EXPECT_EQ(parseOk("2026-06-21T09:00:45+03:00").plusMinutes(0.25).str(), "2026-06-21T09:01+03:00");
    EXPECT_EQ(parseOk("2026-06-21T09:00Z").plusMinutes(3 * 1440).str(), "2026-06-24T09:00Z");
    // Many small steps do not drift.
    DateTime w = parseOk("2026-06-21T09:00+03:00");
    for (int i = 0; i < 12; ++i) w = w.plusMinutes(15);
    EXPECT_EQ(w.str(), "2026-06-21T12:00+03:00");
}

TEST(DateTime, StrRoundTrips) {
    for (const char* s : {"2026-06-21T09:00+03:00", "2003-10-17T12:30:30-07:00", "2024-02-29T23:59:59.125Z",
                          "1999-01-01T00:00-09:30"}) {
        DateTime t = parseOk(s);
        EXPECT_EQ(t.str(), s);
        DateTime back = parseOk(t.str().c_str());
        EXPECT_DOUBLE_EQ(back.julianDayUT(), t.julianDayUT());
    }
}

}  // namespace

// Issue 58 reported a daylight time with fractional seconds hanging measure. They are
// read, rounded once, and the instants from them are as many as the period holds.
namespace fractional_seconds {

TEST(DateTimeFractions, AreReadAndWrittenBack) {
    std::string err;
    auto t = parseIso8601("2026-06-21T09:00:00.5Z", &err);
    ASSERT_TRUE(t) << err;
    EXPECT_EQ(t->second, 0.5);
    EXPECT_EQ(t->str(), "2026-06-21T09:00:00.500Z");
    EXPECT_NEAR(t->julianDayUT() - parseIso8601("2026-06-21T09:00Z")->julianDayUT(), 0.5 / 86400, 1e-9);  // ~0.1 ms
    // Rounded once: 0.3 is the double nearest 0.3, not 3 x 0.1.
    EXPECT_EQ(parseIso8601("2026-06-21T09:00:00.3Z")->second, 0.3);
    EXPECT_EQ(parseIso8601("2026-06-21T09:00:59.123456789+03:00")->second, 59.123456789);
    // As many digits as one likes, read in one pass.
    const std::string many = "2026-06-21T09:00:01." + std::string(100000, '5') + "Z";
    EXPECT_NEAR(parseIso8601(many)->second, 1.5555555555555556, 1e-15);
}

TEST(DateTimeFractions, ASecondThatRoundsTo60IsRefusedAsWritten) {
    std::string err;
    EXPECT_FALSE(parseIso8601("2026-06-21T09:00:59.99999999999999999Z", &err));
    EXPECT_EQ(err, "\"2026-06-21T09:00:59.99999999999999999Z\": second 59.99999999999999999 outside [0, 60) (it rounds to 60)");
    EXPECT_FALSE(parseIso8601("2026-06-21T09:00:60.5Z", &err));
    EXPECT_EQ(err, "\"2026-06-21T09:00:60.5Z\": second 60.5 outside [0, 60)");
    EXPECT_FALSE(parseIso8601("2026-06-21T09:00:00.Z", &err));
    EXPECT_NE(err.find("expected YYYY-MM-DDThh:mm[:ss[.fff]]"), std::string::npos) << err;
}

}  // namespace fractional_seconds

namespace iso_weekday {

// Weekdays read off a calendar: 1 = Monday .. 7 = Sunday.
TEST(IsoWeekday, KnownDates) {
    EXPECT_EQ(isoWeekday(2026, 12, 7), 1);  // Monday
    EXPECT_EQ(isoWeekday(1970, 1, 1), 4);   // Thursday: the Unix epoch
    EXPECT_EQ(isoWeekday(2000, 1, 1), 6);   // Saturday
    EXPECT_EQ(isoWeekday(2024, 2, 29), 4);  // Thursday, a leap day
    EXPECT_EQ(isoWeekday(2006, 1, 1), 7);   // Sunday
    EXPECT_EQ(isoWeekday(1900, 3, 1), 4);   // Thursday, after a 28-day February of a century
    EXPECT_EQ(isoWeekday(1582, 10, 15), 5); // Friday: the Gregorian calendar's first day
    // Seven days on, the same weekday; one day on, the next.
    for (int d = 1; d <= 24; ++d) {
        EXPECT_EQ(isoWeekday(2026, 12, d + 7), isoWeekday(2026, 12, d));
        EXPECT_EQ(isoWeekday(2026, 12, d + 1), isoWeekday(2026, 12, d) % 7 + 1);
    }
}

}  // namespace iso_weekday
}  // namespace luxplan
