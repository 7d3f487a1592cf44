// IES LM-63 photometric files (https://www.ies.org/standards/, LM-63-2019 and its
// predecessors): a version line, keyword lines up to TILT=, then whitespace- (or
// comma-) separated numbers: the lamp and luminaire data, the vertical (gamma) and
// horizontal (C) angles, and the candela values, plane by plane.
#include <luxplan/io/photometry_io.h>
#include <luxplan/io/photometry_text.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include <luxplan/core/limits.h>
#include <luxplan/json/fields.h>

namespace luxplan::io {
namespace {

using json::formatNumber;
using photometry::fail;
using photometry::quote;

struct Token {
    std::string text;
    int line = 0;
};

// The numbers after the TILT line, each with its line, read in order.
class Numbers {
public:
    Numbers(const std::string& name, std::vector<Token> tokens, int lastLine)
        : name_(name), tokens_(std::move(tokens)), lastLine_(lastLine) {}

    int line() const { return next_ < tokens_.size() ? tokens_[next_].line : lastLine_; }
    int lastReadLine() const { return next_ > 0 ? tokens_[next_ - 1].line : lastLine_; }
    double number(const std::string& what) {
        if (next_ >= tokens_.size()) fail(name_, lastLine_, "the file ends where " + what + " should be");
        const Token& t = tokens_[next_++];
        auto v = photometry::parseNumber(t.text);
        if (!v) fail(name_, t.line, "expected " + what + ", got " + quote(t.text));
        return *v;
    }
    int count(const std::string& what) {
        double v = number(what);
        if (v < 1 || v != std::floor(v) || v > 100000)
            fail(name_, lastReadLine(), what + " must be a positive integer, got " + formatNumber(v));
        return int(v);
    }

private:
    const std::string& name_;
    std::vector<Token> tokens_;
    size_t next_ = 0;
    int lastLine_;
};

// Angles that must increase within [lo, hi]; their lines, for the checks after.
std::vector<double> readAngles(Numbers& in, int n, const char* what, double lo, double hi, const std::string& name) {
    std::vector<double> a(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        a[size_t(i)] = in.number(std::string("a ") + what + " angle");
        if (a[size_t(i)] < lo || a[size_t(i)] > hi)
            fail(name, in.lastReadLine(), std::string(what) + " angle " + formatNumber(a[size_t(i)]) + " is outside [" +
                                              formatNumber(lo) + ", " + formatNumber(hi) + "]");
        if (i > 0 && !(a[size_t(i)] > a[size_t(i) - 1]))
            fail(name, in.lastReadLine(), std::string(what) + " angles must increase (" + formatNumber(a[size_t(i)]) +
                                              " after " + formatNumber(a[size_t(i) - 1]) + ")");
    }
    return a;
}

// Whether planes from C = 0 to the last reach round: C = 360 itself, or a gap to
// it no wider than the widest step between planes (files that leave out 360).
bool coversTheCircle(const std::vector<double>& c) {
    double widest = 0;
    for (size_t i = 1; i < c.size(); ++i) widest = std::max(widest, c[i] - c[i - 1]);
    return 360 - c.back() <= widest + 1e-9;
}

}  // namespace

PhotometricTable readIes(const std::string& text, const std::string& name) {
    const std::vector<std::string> lines = photometry::splitLines(text);
    if (lines.empty()) fail(name, 1, "the file is empty");
    // ---- version line: LM-63-1986 has none, later versions name themselves ----
    size_t first = 0;
    bool v1995 = false;
    std::string version(photometry::trim(lines[0]));
    if (version.rfind("IESNA", 0) == 0) {
        if (version == "IESNA:LM-63-1995") v1995 = true;
        else if (version != "IESNA:LM-63-2002" && version != "IESNA:LM-63-2019" && version != "IESNA91")
            fail(name, 1, "unsupported IES version " + quote(version) +
                              " (IESNA:LM-63-1995, IESNA:LM-63-2002, IESNA:LM-63-2019 or IESNA91)");
        first = 1;
    }
    // ---- keywords, up to TILT= ----
    size_t tilt = first;
    while (tilt < lines.size() && photometry::trim(lines[tilt]).rfind("TILT", 0) != 0) ++tilt;
    if (tilt == lines.size()) fail(name, int(lines.size()), "no TILT= line: not an IES LM-63 file");
    std::string tiltLine(photometry::trim(lines[tilt]));
    const int tiltLineNo = int(tilt) + 1;
    auto eq = tiltLine.find('=');
    std::string tiltValue(photometry::trim(eq == std::string::npos ? std::string_view() : std::string_view(tiltLine).substr(eq + 1)));
    if (tiltValue != "NONE")
        fail(name, tiltLineNo, "TILT=" + tiltValue +
                                   " is not supported (only TILT=NONE: lamp tilt factors are not applied)");

    std::vector<Token> tokens;
    for (size_t i = tilt + 1; i < lines.size(); ++i) {
        std::string_view l = lines[i];
        size_t p = 0;
        while (p < l.size()) {
            while (p < l.size() && (std::isspace((unsigned char)l[p]) || l[p] == ',')) ++p;
            size_t q = p;
            while (q < l.size() && !std::isspace((unsigned char)l[q]) && l[q] != ',') ++q;
            if (q > p) tokens.push_back({std::string(l.substr(p, q - p)), int(i) + 1});
            p = q;
        }
    }
    Numbers in(name, std::move(tokens), int(lines.size()));

    // ---- lamp and luminaire data ----
    in.count("the number of lamps");
    double lumens = in.number("the lumens per lamp");
    if (lumens <= 0 && lumens != -1)
        fail(name, in.lastReadLine(), "lumens per lamp must be > 0, or -1 for absolute photometry, got " + formatNumber(lumens));
    double multiplier = in.number("the candela multiplier");
    if (!(multiplier > 0)) fail(name, in.lastReadLine(), "the candela multiplier must be > 0, got " + formatNumber(multiplier));
    int nGamma = in.count("the number of vertical angles");
    if (nGamma < 2) fail(name, in.lastReadLine(), "needs at least two vertical angles, got 1");
    int nC = in.count("the number of horizontal angles");
    if (int64_t(nC) * nGamma > limits::kMaxPhotometryValues)
        fail(name, in.lastReadLine(), std::to_string(int64_t(nC) * nGamma) + " candela values exceed the limit of " +
                                          std::to_string(limits::kMaxPhotometryValues));
    double type = in.number("the photometric type");
    if (type != 1) {
        std::string which = type == 2 ? " (type B)" : type == 3 ? " (type A)" : "";
        fail(name, in.lastReadLine(), "photometric type " + formatNumber(type) + which + " is not supported: only type C (1)");
    }
    double units = in.number("the units type");
    if (units != 1 && units != 2) fail(name, in.lastReadLine(), "units type must be 1 (feet) or 2 (metres), got " + formatNumber(units));
    for (const char* what : {"the luminous width", "the luminous length", "the luminous height"}) in.number(what);
    double ballast = in.number("the ballast factor");
    if (!(ballast > 0)) fail(name, in.lastReadLine(), "the ballast factor must be > 0, got " + formatNumber(ballast));
    // LM-63-1995's ballast-lamp photometric factor; "future use" (2002) and the file
    // generation type (2019) multiply nothing.
    double ballastLamp = in.number(v1995 ? "the ballast-lamp photometric factor" : "the second ballast field");
    if (v1995 && !(ballastLamp > 0))
        fail(name, in.lastReadLine(), "the ballast-lamp photometric factor must be > 0, got " + formatNumber(ballastLamp));
    in.number("the input watts");

    // ---- angles and candela ----
    PhotometricTable t;
    t.gammaDeg = readAngles(in, nGamma, "vertical", 0, 180, name);
    int cLine = in.line();
    t.cDeg = readAngles(in, nC, "horizontal", 0, 360, name);
    double c0 = t.cDeg.front(), c1 = t.cDeg.back();
    if (nC == 1 && c0 == 0) t.symmetry = CSymmetry::Rotational;
    else if (c0 == 0 && c1 == 90) t.symmetry = CSymmetry::Quadrants;
    else if (c0 == 0 && c1 == 180) t.symmetry = CSymmetry::AboutC0C180;
    else if (c0 == 90 && c1 == 270) t.symmetry = CSymmetry::AboutC90C270;
    else if (c0 == 0 && c1 > 180 && coversTheCircle(t.cDeg)) t.symmetry = CSymmetry::None;
    else
        fail(name, cLine, "horizontal angles from " + formatNumber(c0) + " to " + formatNumber(c1) +
                              ": type C runs from 0 to 0, 90, 180 or 360, or from 90 to 270");
    const double factor = multiplier * ballast * (v1995 ? ballastLamp : 1);
    t.candela.reserve(size_t(nC) * size_t(nGamma));
    for (int c = 0; c < nC; ++c)
        for (int g = 0; g < nGamma; ++g) {
            double v = in.number("a candela value (" + std::to_string(nC * nGamma) + " in all)");
            if (v < 0) fail(name, in.lastReadLine(), "negative candela value " + formatNumber(v));
            if (!std::isfinite(v * factor))
                fail(name, in.lastReadLine(), "candela value " + formatNumber(v) + " times the multipliers is not finite");
            if (v * factor > limits::kMaxCandela)
                fail(name, in.lastReadLine(), "candela value " + formatNumber(v) + " times the multipliers (" +
                                                  formatNumber(v * factor) + " cd) exceeds the limit of " +
                                                  formatNumber(limits::kMaxCandela) + " cd");
            t.candela.push_back(v * factor);
        }
    return t;
}

}  // namespace luxplan::io
