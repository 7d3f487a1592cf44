// The photometric file readers: every IES LM-63 version header, each lateral
// symmetry, absolute and relative photometry, EULUMDAT's five symmetries and decimal
// commas, and each refusal with its exact FILE:LINE message.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <luxplan/core/error.h>
#include <luxplan/io/photometry_io.h>
#include <luxplan/json/fields.h>
#include "support/temp_files.h"
#include "support/test_data.h"

namespace luxplan {
namespace {

using test::kPhotometryFiles;

// An IES file: `header` (version line and keywords, up to and with TILT), then the
// numbers; lateral angles `c`, vertical {0, 45, 90}, plane i's candela i+1, i+2, i+3.
std::string ies(const std::string& header, const std::vector<double>& c, double lumens = 1000, double multiplier = 1,
                const std::string& ballast = "1 1 10") {
    std::string s = header + "\n1 " + luxplan::json::formatNumber(lumens) + " " + luxplan::json::formatNumber(multiplier) + " 3 " +
                    std::to_string(c.size()) + " 1 2 0.1 0.1 0\n" + ballast + "\n0 45 90\n";
    for (double a : c) s += luxplan::json::formatNumber(a) + " ";
    s += "\n";
    for (size_t i = 0; i < c.size(); ++i)
        s += std::to_string(i + 1) + " " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
    return s;
}
const std::string k2002 = "IESNA:LM-63-2002\n[TEST] t\nTILT=NONE";

// The IoError message of reading `text` as a file called "f.ies" / "f.ldt".
std::string iesError(const std::string& text) {
    try {
        io::readIes(text, "f.ies");
    } catch (const IoError& e) {
        return e.what();
    }
    return "no error";
}
std::string ldtError(const std::string& text) {
    try {
        io::readEulumdat(text, "f.ldt");
    } catch (const IoError& e) {
        return e.what();
    }
    return "no error";
}

TEST(IesReader, ReadsEveryVersionHeader) {
    for (std::string header : {"IESNA:LM-63-1995\n[TEST] a", "IESNA:LM-63-2002\n[TEST] a", "IESNA:LM-63-2019\n[TEST] a\n[ISSUEDATE] 2026-12-01",
                               "IESNA91\n[TEST] a", "[TEST] 1986: no version line"}) {
        auto t = io::readIes(ies(header + "\nTILT=NONE", {0, 90, 180, 270, 360}), "f.ies");
        EXPECT_EQ(t.cDeg.size(), 5u) << header;
        EXPECT_EQ(t.gammaDeg, (std::vector<double>{0, 45, 90})) << header;
        EXPECT_EQ(t.candela[3 * 2 + 1], 4.0) << header;  // plane 3 (C 270), gamma 45
        EXPECT_EQ(t.symmetry, CSymmetry::None);
    }
}

TEST(IesReader, EachLateralSymmetry) {
    EXPECT_EQ(io::readIes(ies(k2002, {0}), "f").symmetry, CSymmetry::Rotational);
    EXPECT_EQ(io::readIes(ies(k2002, {0, 45, 90}), "f").symmetry, CSymmetry::Quadrants);
    EXPECT_EQ(io::readIes(ies(k2002, {0, 90, 180}), "f").symmetry, CSymmetry::AboutC0C180);
    EXPECT_EQ(io::readIes(ies(k2002, {90, 180, 270}), "f").symmetry, CSymmetry::AboutC90C270);
    EXPECT_EQ(io::readIes(ies(k2002, {0, 120, 240, 360}), "f").symmetry, CSymmetry::None);
    // And what each means once expanded: C 270 of a 0-180 file is its C 90.
    IntensityDistribution d(io::readIes(ies(k2002, {0, 90, 180}), "f"));
    EXPECT_DOUBLE_EQ(d.intensity(PhotometricAngles{1.5 * kPi, kPi / 4}), 3);
}

TEST(IesReader, AppliesTheMultiplierAndBallastFactors) {
    // Absolute photometry (lumens -1): candela x multiplier x ballast factor.
    auto t = io::readIes(ies(k2002, {0}, -1, 2, "0.5 1 10"), "f");
    EXPECT_EQ(t.candela, (std::vector<double>{1, 2, 3}));
    // LM-63-1995's ballast-lamp photometric factor multiplies too; 2002's "future use" does not.
    t = io::readIes(ies("IESNA:LM-63-1995\nTILT=NONE", {0}, 1000, 1, "1 0.5 10"), "f");
    EXPECT_EQ(t.candela, (std::vector<double>{0.5, 1, 1.5}));
    t = io::readIes(ies(k2002, {0}, 1000, 1, "1 0.5 10"), "f");
    EXPECT_EQ(t.candela, (std::vector<double>{1, 2, 3}));
    // Relative photometry reads the same: the candela are the luminaire's with its rated lamps.
    t = io::readIes(ies(k2002, {0}, 3000, 1), "f");
    EXPECT_EQ(t.candela, (std::vector<double>{1, 2, 3}));
}

TEST(IesReader, ToleratesCommasAndLineBreaksBetweenNumbers) {
    std::string text = "IESNA:LM-63-2019\r\n[TEST] t\r\nTILT=NONE\r\n1,-1,1,3,1,1,2,0,0,0\r\n1 1\r\n10\r\n0\r\n45 90 0\r\n1\r\n2 3\r\n";
    auto t = io::readIes(text, "f");
    EXPECT_EQ(t.candela, (std::vector<double>{1, 2, 3}));
}

TEST(IesReader, ReportsEachProblemWithItsLine) {
    EXPECT_EQ(iesError("IESNA:LM-63-2030\nTILT=NONE\n"),
              "f.ies:1: unsupported IES version \"IESNA:LM-63-2030\" (IESNA:LM-63-1995, IESNA:LM-63-2002, IESNA:LM-63-2019 or IESNA91)");
    EXPECT_EQ(iesError("IESNA:LM-63-2002\n[TEST] t\n"), "f.ies:2: no TILT= line: not an IES LM-63 file");
    EXPECT_EQ(iesError("IESNA:LM-63-2002\n[TEST] t\nTILT=INCLUDE\n1\n"),
              "f.ies:3: TILT=INCLUDE is not supported (only TILT=NONE: lamp tilt factors are not applied)");
    EXPECT_EQ(iesError("IESNA:LM-63-2002\nTILT=lamp.tlt\n"),
              "f.ies:2: TILT=lamp.tlt is not supported (only TILT=NONE: lamp tilt factors are not applied)");
    std::string good = ies(k2002, {0, 90, 180});  // numbers from line 4 on
    auto replace = [&](const std::string& from, const std::string& to) {
        std::string s = good;
        s.replace(s.find(from), from.size(), to);
        return s;
    };
    EXPECT_EQ(iesError(replace("1 1000 1 3 3 1 2", "1 1000 1 3 3 2 2")),
              "f.ies:4: photometric type 2 (type B) is not supported: only type C (1)");
    EXPECT_EQ(iesError(replace("1 1000 1 3 3 1 2", "1 0 1 3 3 1 2")),
              "f.ies:4: lumens per lamp must be > 0, or -1 for absolute photometry, got 0");
    EXPECT_EQ(iesError(replace("1 1000 1 3 3 1 2", "1 1000 1 3.5 3 1 2")),
              "f.ies:4: the number of vertical angles must be a positive integer, got 3.5");
    EXPECT_EQ(iesError(replace("1 1000 1 3 3 1 2", "1 1000 x 3 3 1 2")),
              "f.ies:4: expected the candela multiplier, got \"x\"");
    EXPECT_EQ(iesError(replace("0 45 90", "0 95 90")), "f.ies:6: vertical angles must increase (90 after 95)");
    EXPECT_EQ(iesError(replace("0 45 90", "0 45 190")), "f.ies:6: vertical angle 190 is outside [0, 180]");
    EXPECT_EQ(iesError(replace("0 90 180", "0 90 200")),
              "f.ies:7: horizontal angles from 0 to 200: type C runs from 0 to 0, 90, 180 or 360, or from 90 to 270");
    // A full circle may leave out C 360 when its last step closes it.
    EXPECT_EQ(iesError(replace("0 90 180", "0 120 240")), "no error");
    EXPECT_EQ(iesError(replace("2 3 4", "2 -3 4")), "f.ies:9: negative candela value -3");
    std::string cut = good.substr(0, good.rfind("3 4 5"));
    EXPECT_EQ(iesError(cut), "f.ies:9: the file ends where a candela value (9 in all) should be");
}

TEST(EulumdatReader, ReadsTheAsymmetricFileWithDecimalCommas) {
    auto d = io::loadPhotometry(kPhotometryFiles + "asymmetric.ldt");
    // cd/klm x 2000 lm / 1000: C 90 is 500 250 75 0 cd/klm.
    EXPECT_DOUBLE_EQ(d->intensity(PhotometricAngles{kPi / 2, kPi / 6}), 500);
    EXPECT_DOUBLE_EQ(d->intensity(PhotometricAngles{kPi, kPi / 3}), 300);
    EXPECT_DOUBLE_EQ(d->intensity(PhotometricAngles{1.5 * kPi, kPi / 6}), 900);
}

// An EULUMDAT file: Isym, Mc planes every 360 / Mc degrees, gammas {0, 45, 90},
// stored plane k's intensities (k+1) * {3, 2, 1} cd/klm, one set of 1000 lm lamps.
std::string ldt(int isym, int mc, int stored) {
    std::vector<std::string> l = {"company", "1", std::to_string(isym), std::to_string(mc), luxplan::json::formatNumber(360.0 / mc), "3", "45",
                                  "r", "n", "1", "f.ldt", "d", "100", "100", "10", "100", "100", "0", "0", "0", "0", "100",
                                  "100", "1", "0", "1", "1", "LED", "1000", "3000", "80", "10"};
    for (int i = 0; i < 10; ++i) l.push_back("0,5");
    for (int i = 0; i < mc; ++i) l.push_back(luxplan::json::formatNumber(360.0 * i / mc));
    for (const char* g : {"0", "45", "90"}) l.push_back(g);
    for (int k = 0; k < stored; ++k)
        for (int g = 0; g < 3; ++g) l.push_back(std::to_string((k + 1) * (3 - g)));
    std::string s;
    for (const auto& x : l) s += x + "\n";
    return s;
}

TEST(EulumdatReader, EachSymmetry) {
    struct Case {
        int isym, mc, stored;
        CSymmetry symmetry;
        std::vector<double> c;
    };
    for (const Case& k : {Case{0, 4, 4, CSymmetry::None, {0, 90, 180, 270}}, Case{1, 1, 1, CSymmetry::Rotational, {0}},
                          Case{2, 4, 3, CSymmetry::AboutC0C180, {0, 90, 180}},
                          Case{3, 8, 5, CSymmetry::AboutC90C270, {90, 135, 180, 225, 270}},
                          Case{4, 8, 3, CSymmetry::Quadrants, {0, 45, 90}}}) {
        auto t = io::readEulumdat(ldt(k.isym, k.mc, k.stored), "f.ldt");
        EXPECT_EQ(t.symmetry, k.symmetry) << k.isym;
        EXPECT_EQ(t.cDeg, k.c) << k.isym;
        ASSERT_EQ(t.candela.size(), size_t(k.stored) * 3) << k.isym;
        EXPECT_EQ(t.candela[1], 2.0) << k.isym;  // 2 cd/klm x 1000 lm
        IntensityDistribution d(t);                // expands
    }
    // Isym 3: C 0 is the mirror of the stored C 180 (the third stored plane).
    IntensityDistribution m(io::readEulumdat(ldt(3, 8, 5), "f"));
    EXPECT_DOUBLE_EQ(m.intensity(PhotometricAngles{0, kPi / 4}), 3 * 2);
}

TEST(EulumdatReader, ReportsEachProblemWithItsLine) {
    std::string good = ldt(2, 4, 3);
    auto line = [&](int n, const std::string& to) {
        std::string s = good;
        size_t at = 0;
        for (int i = 1; i < n; ++i) at = s.find('\n', at) + 1;
        s.replace(at, s.find('\n', at) - at, to);
        return s;
    };
    EXPECT_EQ(ldtError(line(3, "5")), "f.ldt:3: the symmetry indicator Isym must be an integer in [0, 4], got 5");
    EXPECT_EQ(ldtError(line(4, "3")), "f.ldt:4: Isym 2 needs Mc divisible by 2, got 3");
    EXPECT_EQ(ldtError(line(29, "0")), "f.ldt:29: the first lamp set's total flux must be > 0 lm, got 0");
    EXPECT_EQ(ldtError(line(27, "one")), "f.ldt:27: expected lamp set 1's number of lamps, got \"one\"");
    EXPECT_EQ(ldtError(line(24, "one")), "f.ldt:24: expected the conversion factor for luminous intensities, got \"one\"");
    EXPECT_EQ(ldtError(line(46, "100")), "f.ldt:46: C angles must increase (100 after 180)");
    EXPECT_EQ(ldtError(line(45, "170")), "f.ldt:45: Isym 2 stores C 180 as plane 3, but the file's C angle there is 170");
    EXPECT_EQ(ldtError(line(43, "10")), "f.ldt:43: Isym 2 stores C 0 as plane 1, but the file's C angle there is 10");
    EXPECT_EQ(ldtError(line(48, "100")), "f.ldt:49: gamma angles must increase (90 after 100)");
    EXPECT_EQ(ldtError(line(52, "-1")), "f.ldt:52: negative intensity -1");
    // Latin-1 bytes are quoted as UTF-8.
    EXPECT_EQ(ldtError(line(24, "\xb5")), "f.ldt:24: expected the conversion factor for luminous intensities, got \"\xc2\xb5\"");
    std::string cut = good.substr(0, good.size() - 2);  // the last intensity's line
    EXPECT_EQ(ldtError(cut), "f.ldt:57: the file ends at line 57; an intensity (cd/klm; 9 in all) should be on line 58");
}

// Found by luxplan_fuzz (tests/fuzz/regressions/wrong-accept-photometry.candela-bad-*):
// a finite but absurd intensity passed, and with it a luminaire of 10^300 lm.
TEST(PhotometryLimits, AnIntensityAboveTheLimitIsRefusedWithItsLine) {
    std::string good = ies(k2002, {0, 90, 180});
    std::string text = good;
    text.replace(text.find("2 3 4"), 5, "2 3e300 4");
    EXPECT_NE(iesError(text).find("f.ies:9: candela value 3e+300"), std::string::npos) << iesError(text);
    EXPECT_NE(iesError(text).find("exceeds the limit of 1000000000 cd"), std::string::npos) << iesError(text);
    // Through the multiplier too.
    text = good;
    text.replace(text.find("1 1000 1 3 3 1 2"), 16, "1 1000 1e9 3 3 1 2");
    EXPECT_NE(iesError(text).find("exceeds the limit of 1000000000 cd"), std::string::npos) << iesError(text);
    std::string l = ldt(2, 4, 3);
    size_t at = 0;
    for (int i = 1; i < 52; ++i) at = l.find('\n', at) + 1;
    l.replace(at, l.find('\n', at) - at, "1e300");
    EXPECT_NE(ldtError(l).find("f.ldt:52: intensity 1e+300 cd/klm"), std::string::npos) << ldtError(l);
    EXPECT_NE(ldtError(l).find("exceeds the limit of 1000000000 cd"), std::string::npos) << ldtError(l);
}

TEST(PhotometryFile, ChosenByExtensionAndRefusedWithItsName) {
    auto file = io::loadPhotometry(kPhotometryFiles + "asymmetric.ies");
    EXPECT_DOUBLE_EQ(file->intensity(PhotometricAngles{kPi / 2, kPi / 6}), 600);
    test::TempDir dir;
    auto upper = dir.write("LUM.IES", ies(k2002, {0}));
    EXPECT_NO_THROW(io::loadPhotometry(upper));
    auto txt = dir.write("lum.txt", "x");
    EXPECT_THROW(
        {
            try {
                io::loadPhotometry(txt);
            } catch (const IoError& e) {
                EXPECT_EQ(std::string(e.what()), txt.string() + ": unsupported photometry format \".txt\" (use .ies or .ldt)");
                throw;
            }
        },
        IoError);
    try {
        io::loadPhotometry(dir.path() / "none.ies");
        ADD_FAILURE();
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), (dir.path() / "none.ies").string() + ": no such file");
    }
    // A file's own flux divides "flux_lm": a faint one (here 1e-6 cd everywhere) is refused.
    auto faint = dir.write("faint.ies", "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 90\n0\n1e-6 1e-6\n");
    try {
        io::loadPhotometry(faint);
        ADD_FAILURE();
    } catch (const IoError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind(faint.string() + ": the distribution's flux of ", 0), 0u) << m;
        EXPECT_NE(m.find(" lm is below the limit of 0.001 lm"), std::string::npos) << m;
    }
    auto dark = dir.write("dark.ies", "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 2 1 1 2 0 0 0\n1 1 0\n0 90\n0\n0 0\n");
    try {
        io::loadPhotometry(dark);
        ADD_FAILURE();
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), dark.string() + ": the distribution emits no light (every intensity is 0)");
    }
}

}  // namespace

// Lamp sets are six lines each, set by set (issue 58: they were read field by field,
// and a file of several sets took another set's field for the first set's flux).
namespace eulumdat_lamp_sets {

// The rotationally symmetric test files: gamma 0-90 every 15 deg, 100 cd/klm throughout,
// conversion factor 1. By hand: I = 100 cd/klm x (first set's flux) / 1000 lm, and,
// I constant over the lower hemisphere, flux = 2 pi I.
std::string ldtFileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    EXPECT_TRUE(in.good()) << path;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct LdtSetsCase {
    const char* file;
    double firstSetLm;
};

TEST(EulumdatLampSets, TheFirstSetsFluxScalesTheIntensities) {
    for (const LdtSetsCase& k : {LdtSetsCase{"one_set.ldt", 2000}, LdtSetsCase{"two_sets.ldt", 2000},
                                 LdtSetsCase{"three_sets.ldt", 1500}}) {
        const auto d = io::loadPhotometry(kPhotometryFiles + k.file);
        const double candela = 100 * k.firstSetLm / 1000;
        for (double gammaDeg : {0.0, 7.5, 45.0, 90.0})
            for (double cDeg : {0.0, 120.0, 270.0})
                EXPECT_NEAR(d->intensity(PhotometricAngles{radians(cDeg), radians(gammaDeg)}), candela, 0.01 * candela)
                    << k.file << " C " << cDeg << " gamma " << gammaDeg;
        EXPECT_NEAR(d->flux(), 2 * kPi * candela, 0.01 * 2 * kPi * candela) << k.file;
    }
}

TEST(EulumdatLampSets, MoreSetsReadAsTheFirstAlone) {
    // The two-set file is the one-set file with a second set of 5000 lm added.
    const auto one = io::readEulumdat(ldtFileText(kPhotometryFiles + "one_set.ldt"), "one_set.ldt");
    const auto two = io::readEulumdat(ldtFileText(kPhotometryFiles + "two_sets.ldt"), "two_sets.ldt");
    EXPECT_EQ(one.candela, two.candela);
    EXPECT_EQ(one.cDeg, two.cDeg);
    EXPECT_EQ(one.gammaDeg, two.gammaDeg);
    ASSERT_FALSE(one.candela.empty());
    EXPECT_EQ(one.candela[0], 200.0);  // 100 cd/klm x 2000 lm
}

// `text` up to and with its line `n` (1-based).
std::string ldtLinesUpTo(const std::string& text, int n) {
    size_t at = 0;
    for (int i = 0; i < n; ++i) at = text.find('\n', at) + 1;
    return text.substr(0, at);
}

TEST(EulumdatLampSets, TruncatedSetDataNamesTheLineAndTheField) {
    const std::string two = ldtFileText(kPhotometryFiles + "two_sets.ldt");
    // Line 26: two sets; set 1 is lines 27-32, set 2 lines 33-38.
    EXPECT_EQ(ldtError(ldtLinesUpTo(two, 26)),
              "f.ldt:26: the file ends at line 26; lamp set 1's number of lamps should be on line 27");
    EXPECT_EQ(ldtError(ldtLinesUpTo(two, 30)),
              "f.ldt:30: the file ends at line 30; lamp set 1's colour rendering index should be on line 31");
    EXPECT_EQ(ldtError(ldtLinesUpTo(two, 34)),
              "f.ldt:34: the file ends at line 34; lamp set 2's total flux (lm) should be on line 35");
    EXPECT_EQ(ldtError(ldtLinesUpTo(two, 37)),
              "f.ldt:37: the file ends at line 37; lamp set 2's wattage should be on line 38");
    // Set data written field by field (counts, then types, ...) is refused, not misread.
    std::string fieldMajor = two;
    const std::string sets = "1\r\nLED 830\r\n2000\r\n3000 K\r\n80\r\n20,5\r\n2\r\nLED 840\r\n5000\r\n4000 K\r\n90\r\n41,0\r\n";
    const size_t at = fieldMajor.find(sets);
    ASSERT_NE(at, std::string::npos);
    fieldMajor.replace(at, sets.size(),
                       "1\r\n2\r\nLED 830\r\nLED 840\r\n2000\r\n5000\r\n3000 K\r\n4000 K\r\n80\r\n90\r\n20,5\r\n41,0\r\n");
    EXPECT_EQ(ldtError(fieldMajor), "f.ldt:29: expected lamp set 1's total flux (lm), got \"LED 830\"");
}

}  // namespace eulumdat_lamp_sets
}  // namespace luxplan
