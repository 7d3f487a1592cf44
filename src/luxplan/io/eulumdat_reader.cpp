// EULUMDAT photometric files (.ldt; the format of Stockmar 1990, as DIALux and Relux
// write it): one field per line in a fixed order, ISO-8859-1, decimal commas common.
// Lines 1-26 describe the luminaire, the symmetry and the number of lamp sets; then 6
// lines per lamp set, set by set (count, type, flux, colour temperature, CRI,
// wattage), 10 direct ratios, the Mc C angles, the Ng gamma angles and the stored
// planes' intensities in cd per 1000 lm of lamp flux, plane by plane.
#include <luxplan/io/photometry_io.h>
#include <luxplan/io/photometry_text.h>

#include <cmath>

#include <luxplan/core/limits.h>
#include <luxplan/json/fields.h>

namespace luxplan::io {
namespace {

using json::formatNumber;
using photometry::fail;
using photometry::quote;

class Lines {
public:
    Lines(const std::string& text, const std::string& name) : lines_(photometry::splitLines(text)), name_(name) {}

    // The number on line `n` (1-based).
    double number(int n, const std::string& what) const {
        present(n, what);
        auto v = photometry::parseNumber(lines_[size_t(n - 1)]);
        if (!v) fail(name_, n, "expected " + what + ", got " + quote(photometry::trim(lines_[size_t(n - 1)])));
        return *v;
    }
    // Line `n` must exist; its text (a lamp type, a colour temperature) is not read.
    void present(int n, const std::string& what) const {
        if (n > int(lines_.size()))
            fail(name_, int(lines_.size()), "the file ends at line " + std::to_string(lines_.size()) + "; " + what +
                                                " should be on line " + std::to_string(n));
    }
    int integer(int n, const std::string& what, int lo, int hi) const {
        double v = number(n, what);
        if (v != std::floor(v) || v < lo || v > hi)
            fail(name_, n, what + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                               formatNumber(v));
        return int(v);
    }

private:
    std::vector<std::string> lines_;
    const std::string& name_;
};

// The 1-based line of lamp set `set`'s (0-based) field `field` (0 the number of lamps,
// 2 the total flux, 5 the wattage): the sets follow line 26 one after the other.
int eulumdatLampSetLine(int set, int field) { return 27 + 6 * set + field; }

}  // namespace

PhotometricTable readEulumdat(const std::string& text, const std::string& name) {
    Lines in(text, name);
    in.integer(2, "the type indicator Ityp", 0, 3);
    const int isym = in.integer(3, "the symmetry indicator Isym", 0, 4);
    const int mc = in.integer(4, "the number of C planes Mc", 1, 3600);
    const int ng = in.integer(6, "the number of intensities per plane Ng", 2, 1801);
    if ((isym == 2 && mc % 2) || ((isym == 3 || isym == 4) && mc % 4))
        fail(name, 4, "Isym " + std::to_string(isym) + " needs Mc divisible by " + (isym == 2 ? "2" : "4") + ", got " +
                          std::to_string(mc));
    const double conversion = in.number(24, "the conversion factor for luminous intensities");
    if (!(conversion > 0)) fail(name, 24, "the conversion factor must be > 0, got " + formatNumber(conversion));
    const int sets = in.integer(26, "the number of lamp sets", 1, 20);
    // Six lines per lamp set, set by set: the number of lamps, their type, their total
    // flux (lm), colour temperature, colour rendering index and wattage. The first
    // (standard) set's flux is the one the intensities are relative to, as DIALux
    // reads them by default; the others are alternatives for the same distribution.
    // A negative lamp count marks absolute photometry: the flux is then the
    // luminaire's, and the arithmetic is the same.
    double lampFlux = 0;
    for (int set = 0; set < sets; ++set) {
        const int first = eulumdatLampSetLine(set, 0);
        const std::string whose = "lamp set " + std::to_string(set + 1) + "'s ";
        in.number(first, whose + "number of lamps");
        in.present(first + 1, whose + "lamp type");
        const double flux = in.number(first + 2, whose + "total flux (lm)");
        in.present(first + 3, whose + "colour temperature");
        in.present(first + 4, whose + "colour rendering index");
        in.present(first + 5, whose + "wattage");
        if (set == 0) lampFlux = flux;
    }
    if (!(lampFlux > 0))
        fail(name, eulumdatLampSetLine(0, 2), "the first lamp set's total flux must be > 0 lm, got " + formatNumber(lampFlux));
    const int cLine = 27 + 6 * sets + 10, gLine = cLine + mc, iLine = gLine + ng;

    // ---- the stored planes (Mc1 to Mc2 of the spec) ----
    int firstPlane = 0, planes = mc;
    CSymmetry symmetry = CSymmetry::None;
    switch (isym) {
        case 0: break;
        case 1: planes = 1, symmetry = CSymmetry::Rotational; break;
        case 2: planes = mc / 2 + 1, symmetry = CSymmetry::AboutC0C180; break;
        case 3: firstPlane = mc / 4, planes = mc / 2 + 1, symmetry = CSymmetry::AboutC90C270; break;
        case 4: planes = mc / 4 + 1, symmetry = CSymmetry::Quadrants; break;
    }
    std::vector<double> cAll(static_cast<size_t>(mc));
    for (int i = 0; i < mc; ++i) {
        cAll[size_t(i)] = in.number(cLine + i, "a C angle");
        if (cAll[size_t(i)] < 0 || cAll[size_t(i)] >= 360)
            fail(name, cLine + i, "C angle " + formatNumber(cAll[size_t(i)]) + " is outside [0, 360)");
        if (i > 0 && !(cAll[size_t(i)] > cAll[size_t(i) - 1]))
            fail(name, cLine + i, "C angles must increase (" + formatNumber(cAll[size_t(i)]) + " after " +
                                      formatNumber(cAll[size_t(i) - 1]) + ")");
    }
    PhotometricTable t;
    t.symmetry = symmetry;
    t.cDeg.assign(cAll.begin() + firstPlane, cAll.begin() + firstPlane + planes);
    // Each symmetry stores a fixed range of planes: its ends must be where it says.
    auto expectPlane = [&](int index, double deg) {
        if (std::abs(cAll[size_t(index)] - deg) > 1e-6)
            fail(name, cLine + index, "Isym " + std::to_string(isym) + " stores C " + formatNumber(deg) + " as plane " +
                                          std::to_string(index + 1) + ", but the file's C angle there is " +
                                          formatNumber(cAll[size_t(index)]));
    };
    expectPlane(0, 0);
    if (isym == 2) expectPlane(mc / 2, 180);
    if (isym == 3) expectPlane(mc / 4, 90), expectPlane(3 * mc / 4, 270);
    if (isym == 4) expectPlane(mc / 4, 90);

    for (int i = 0; i < ng; ++i) {
        double g = in.number(gLine + i, "a gamma angle");
        if (g < 0 || g > 180) fail(name, gLine + i, "gamma angle " + formatNumber(g) + " is outside [0, 180]");
        if (i > 0 && !(g > t.gammaDeg.back()))
            fail(name, gLine + i, "gamma angles must increase (" + formatNumber(g) + " after " + formatNumber(t.gammaDeg.back()) + ")");
        t.gammaDeg.push_back(g);
    }
    const double toCandela = lampFlux / 1000 * conversion;
    for (int k = 0; k < planes * ng; ++k) {
        double v = in.number(iLine + k, "an intensity (cd/klm; " + std::to_string(planes * ng) + " in all)");
        if (v < 0) fail(name, iLine + k, "negative intensity " + formatNumber(v));
        if (!(v * toCandela <= limits::kMaxCandela))
            fail(name, iLine + k, "intensity " + formatNumber(v) + " cd/klm (" + formatNumber(v * toCandela) +
                                      " cd) exceeds the limit of " + formatNumber(limits::kMaxCandela) + " cd");
        t.candela.push_back(v * toCandela);
    }
    return t;
}

}  // namespace luxplan::io
