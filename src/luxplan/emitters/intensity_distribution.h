// A luminaire's measured luminous intensity distribution, type C (IES LM-63, EULUMDAT):
// I(C, gamma) in cd, bilinear between the file's angles, its total flux, and the
// sampling of emitted directions in proportion to it. The files are read by
// io/photometry_io.h; this is what the table means once read.
#pragma once

#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/daylight/distribution.h>

namespace luxplan {

// Which C half-planes a file stores; the others follow by mirroring (IES lateral
// angles 0, 0-90, 0-180, 90-270 or 0-360; EULUMDAT Isym 1, 4, 2, 3, 0).
enum class CSymmetry {
    None,          // every plane from C = 0 on (IES 0-360, LDT Isym 0)
    Rotational,    // one plane for all C (IES last angle 0, LDT Isym 1)
    AboutC0C180,   // C in [0, 180], I(360 - C) = I(C) (IES 0-180, LDT Isym 2)
    AboutC90C270,  // C in [90, 270], I(180 - C) = I(C) (IES 90-270, LDT Isym 3)
    Quadrants,     // C in [0, 90], mirrored about both planes (IES 0-90, LDT Isym 4)
};

// The table as a file holds it: the stored planes' C angles and the gamma angles in
// degrees, both increasing, and the candela of plane c at gamma g in
// candela[c * gammaDeg.size() + g], already multiplied by the file's factors.
struct PhotometricTable {
    std::vector<double> cDeg, gammaDeg;
    std::vector<double> candela;
    CSymmetry symmetry = CSymmetry::None;
};

// A direction of the luminaire's own frame: C about the gamma = 0 axis from the C = 0
// plane, gamma from that axis, both in radians.
struct PhotometricAngles {
    double c = 0, gamma = 0;
};

class IntensityDistribution {
public:
    // Expands the symmetry to C in [0, 2 pi]. Throws std::invalid_argument for a table
    // that is not increasing, out of range or of the wrong size (the readers check
    // first, with the file's line numbers).
    explicit IntensityDistribution(const PhotometricTable& table);

    // Candela towards (C, gamma); 0 at gammas outside the file's range.
    double intensity(PhotometricAngles a) const;
    // Candela towards a unit direction given in the luminaire's frame: x along C = 0,
    // y along C = 90, z along gamma = 0.
    double intensity(const Vec3& local) const;
    // Total flux in lm: the integral of the bilinear intensity over the sphere (exact
    // for that model, cell by cell).
    double flux() const { return flux_; }
    // Whether any light leaves at gamma > 90 degrees (flat openings then emit from
    // both faces).
    bool emitsBeyond90() const { return emitsBeyond90_; }

    // A direction of the luminaire's frame drawn in proportion to intensity, from a
    // piecewise-constant density over cells of at most kSampleCellDeg (the file's
    // own cells, split): within a cell the density is its mean intensity / flux.
    struct DirectionSample {
        Vec3 local;
        double pdf = 0;  // per unit solid angle
    };
    DirectionSample sample(Vec2 u) const;
    double pdf(const Vec3& local) const;
    static constexpr double kSampleCellDeg = 2.5;

    // The full table after expansion (C from 0 to 2 pi, radians), for tests and plots.
    const std::vector<double>& cAngles() const { return c_; }
    const std::vector<double>& gammaAngles() const { return gamma_; }

private:
    double at(size_t ic, size_t ig) const { return values_[ic * gamma_.size() + ig]; }
    // Integral of the bilinear intensity times sin(gamma) over [c0, c1] x [g0, g1]
    // inside the file cell (ic, ig).
    double cellMass(size_t ic, size_t ig, double c0, double c1, double g0, double g1) const;
    void buildSampling();

    std::vector<double> c_, gamma_, values_;
    double flux_ = 0;
    bool emitsBeyond90_ = false;
    Distribution2D sampling_;  // over (C, 1 - cos gamma): per unit solid angle
};

}  // namespace luxplan
