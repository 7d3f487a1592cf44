// The daylight a path tracer sees: a baked sky/ground environment map and a list of sun
// disks, with emitted radiance lookups and importance sampling (pdfs per unit solid angle,
// ready for multiple importance sampling). All directions are unit vectors in scene
// coordinates (z up), pointing away from the scene towards the sky.
//
// Units: radiance is photometric, in cd/m^2 (nits), returned as linear sRGB/Rec. 709
// triples whose luminance() (core/math.h) is the luminance; Lv() returns that luminance
// directly. Illuminances are in lux. Pdfs are per steradian.
#pragma once

#include <vector>

#include <luxplan/core/math.h>
#include <luxplan/core/parallel.h>
#include <luxplan/daylight/distribution.h>

namespace luxplan {

// Equirectangular map over the whole sphere in scene coordinates: pixel (ix, iy) covers
// phi = atan2(y, x) in [2 pi ix / W, 2 pi (ix + 1) / W) and zenith angle theta in
// [pi iy / H, pi (iy + 1) / H). H is even, so the horizon is the edge between rows H/2 - 1
// and H/2. Each pixel holds the average radiance over its solid angle; lookups are
// nearest-pixel (the map is piecewise constant, which makes its sampling exact).
class SkyMap {
public:
    SkyMap() = default;
    SkyMap(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    Vec3& at(int ix, int iy) { return pixels_[size_t(iy) * width_ + ix]; }
    const Vec3& at(int ix, int iy) const { return pixels_[size_t(iy) * width_ + ix]; }
    const std::vector<Vec3>& pixels() const { return pixels_; }

    // Pixel holding unit direction w. Row iy holds cos(theta) in (cosEdge(iy+1), cosEdge(iy)],
    // so a horizontal direction belongs to the ground row H/2 (as in the sampling distribution).
    void pixelOf(const Vec3& w, int& ix, int& iy) const;
    // Solid angle of any pixel in row iy (sr).
    double pixelSolidAngle(int iy) const;
    // Direction at fractional pixel coordinates (ix + fx, iy + fz), fz measured in cos(theta)
    // so that sub-samples are equal in solid angle.
    Vec3 direction(int ix, int iy, double fx, double fz) const;
    // Cosine of the zenith angle at the top edge of row iy (row iy spans [cosEdge(iy+1), cosEdge(iy)]).
    double cosEdge(int iy) const { return cosEdges_[size_t(iy)]; }

    // Adds weight * (average over each pixel of the radiance) for the rows [rowBegin, rowEnd),
    // with s x s sub-samples per pixel, equal in solid angle. `rowFunction(z)` returns a
    // callable g(w) giving the radiance for directions w with w.z == z (so work that depends
    // only on the zenith angle is done once per sub-row). Rows run in parallel; each pixel is
    // computed on its own, so the result does not depend on the thread count.
    template <class RowFunction>
    void accumulate(const RowFunction& rowFunction, double weight, int s, int rowBegin, int rowEnd);

private:
    int width_ = 0, height_ = 0;
    std::vector<Vec3> pixels_;
    std::vector<double> cosEdges_;  // H + 1 values, cos(pi iy / H)
    // A first guess of a direction's row from its cos(theta), in 4 H equal steps of z
    // (pixelOf then steps to the exact row): no acos per lookup.
    std::vector<int> rowGuess_;
};

// One sun disk of the time average: the sun at one time step, seen as a uniform disk of
// kSunAngularDiameterDeg. `luminance` is already multiplied by `weight` (the instant's share
// of the time average), so summing every disk's emission gives the average sun.
struct SunDisk {
    Vec3 direction;                  // centre, scene coordinates
    double altitudeDeg = 0, azimuthDeg = 0;  // apparent, azimuth clockwise from true north
    double weight = 1;               // share of the time average (1 / number of time steps)
    double normalIlluminanceLx = 0;  // of the instant, at normal incidence, before weighting
    double luminance = 0;            // weight * normalIlluminanceLx / (pi sin^2 half-angle), cd/m^2
    Vec3 color{1, 1, 1};             // linear sRGB with luminance 1
    Vec3 radiance() const { return color * luminance; }
};

// A sampled direction towards the sky/ground or a sun disk: Le is the radiance that
// Le()/sunLe() report for wi and pdf the density per steradian that skyPdf()/sunPdf() report.
// pdf == 0 marks a failed sample (skip it).
struct EnvironmentSample {
    Vec3 wi;
    Vec3 Le;
    double pdf = 0;
};

class DaylightEnvironment {
public:
    // Night: no sky, no sun, no ground light.
    DaylightEnvironment() = default;
    // `sky` holds the sky above the horizon (rows below are overwritten with the ground);
    // the ground is a diffuse plane of `groundReflectance` lit by the sky and sun disks on the
    // open horizontal plane: L_ground = rho E_h / pi, coloured by the light that falls on it.
    DaylightEnvironment(SkyMap sky, std::vector<SunDisk> suns, double groundReflectance);
    // ... with the ground a given radiance, whatever lights it: a basis of daylight
    // coefficients, where the ground is a patch of its own (annual/daylight_coefficients.h).
    DaylightEnvironment(SkyMap sky, std::vector<SunDisk> suns, const Vec3& groundRadiance);

    // ---- Sky and ground (everything except the sun disks) ----
    Vec3 Le(const Vec3& w) const;
    double Lv(const Vec3& w) const { return luminance(Le(w)); }
    // Importance sampling proportional to luminance over the sphere (sky and ground).
    EnvironmentSample sampleSky(Vec2 u) const;
    double skyPdf(const Vec3& w) const;
    bool hasSky() const { return !skyDistribution_.allZero(); }
    // Whether Le(w) has a positive component for every direction (every pixel of the
    // map and the ground): a light sample of the sky may then trace its shadow ray
    // before it looks its radiance up.
    bool radiancePositive() const { return radiancePositive_; }
    // Integral of luminance over the whole sphere (sky + ground), cd sr / m^2.
    double skyIntegral() const { return skyIntegral_; }

    // ---- Sun disks ----
    bool hasSun() const { return !suns_.empty(); }
    const std::vector<SunDisk>& sunDisks() const { return suns_; }
    // Sum of the radiance of the disks that contain w (0 outside every disk).
    Vec3 sunLe(const Vec3& w) const;
    double sunLv(const Vec3& w) const { return luminance(sunLe(w)); }
    // Picks a disk with probability proportional to its luminance (uDisk), then a direction
    // uniformly in its cone (u). pdf is the mixture density over all disks containing wi.
    EnvironmentSample sampleSun(double uDisk, Vec2 u) const { return sampleSunDisk(sunDiskOf(uDisk), u); }
    // sampleSun's two steps: the disk uDisk chooses, then a direction in it (u).
    size_t sunDiskOf(double uDisk) const;
    // The probability with which sunDiskOf chooses disk k.
    double sunDiskProbability(size_t k) const { return sunDistribution_.pmf(k); }
    EnvironmentSample sampleSunDisk(size_t k, Vec2 u) const;
    double sunPdf(const Vec3& w) const;
    // sunLe(w) and sunPdf(w) from one lookup.
    void sunAt(const Vec3& w, Vec3& Le, double& pdf) const;
    // Sum of disk luminance x disk solid angle (cd sr / m^2).
    double sunIntegral() const { return sunIntegral_; }
    // A cone holding every disk and its rim (cos <= 0 when no cone narrower than a
    // hemisphere does): sampleSun's directions all lie in it.
    const Vec3& sunConeAxis() const { return sunConeAxis_; }
    double sunConeCos() const { return sunConeCos_; }
    // Whether every sampleSun direction w has dot(w, n) <= 0 (n unit): a surface of
    // normal n that only reflects gets nothing from a sun sample.
    bool sunBehind(const Vec3& n) const {
        return sunConeCos_ > 0 && dot(n, sunConeAxis_) < -(sunConeSin_ + 1e-9);
    }

    // ---- Illuminance (lx) ----
    double groundReflectance() const { return groundReflectance_; }
    double groundLuminance() const { return luminance(ground_); }
    // On the open horizontal plane facing up: sky map above the horizon (exact for the
    // piecewise-constant map), sun disks (weight x E_n x sin altitude), and their sum.
    double skyHorizontalIlluminance() const { return skyHorizontal_; }
    double sunHorizontalIlluminance() const { return sunHorizontal_; }
    double totalHorizontalIlluminance() const { return skyHorizontal_ + sunHorizontal_; }
    // On an unobstructed plane with unit normal n, by quadrature over the map (4 x 4
    // sub-samples per pixel) plus the sun disks; `withGround` false drops the lower hemisphere.
    double illuminance(const Vec3& n, bool withGround = true, bool withSun = true) const;

    const SkyMap& skyMap() const { return map_; }

private:
    SkyMap map_;
    std::vector<SunDisk> suns_;
    std::vector<Frame> sunFrames_;  // around each disk's centre, for its samples
    double groundReflectance_ = 0;
    Vec3 ground_;
    bool radiancePositive_ = false;
    Distribution2D skyDistribution_;  // over (phi, -cos theta): area there = solid angle
    Distribution1D sunDistribution_;
    // The disks by direction, so sunLe and sunPdf cost O(1) however many time steps
    // there are: a grid of 1-degree cells over (theta, phi), each listing the disks
    // that may reach into it (compressed rows: disks of cell c are
    // sunCellDisks_[sunCellStart_[c] .. sunCellStart_[c + 1])).
    std::vector<uint32_t> sunCellStart_, sunCellDisks_;
    // A cone around every disk (a morning's suns span a few tens of degrees): a
    // direction outside it sees no sun, found with one dot product.
    Vec3 sunConeAxis_;
    double sunConeCos_ = 1, sunConeSin_ = 0;
    // No two disks reach each other (steps apart by more than a disk): a direction drawn
    // in one disk lies in it alone, so sampleSun needs no lookup.
    bool sunDisksApart_ = false;
    DaylightEnvironment(SkyMap sky, std::vector<SunDisk> suns, double groundReflectance, const Vec3* groundRadiance);
    void indexSunDisks();
    template <class F> void forEachSunDiskAt(const Vec3& w, F&& f) const;
    double skyIntegral_ = 0, sunIntegral_ = 0, skyHorizontal_ = 0, sunHorizontal_ = 0;
};

// ---- template implementation ----

template <class RowFunction>
void SkyMap::accumulate(const RowFunction& rowFunction, double weight, int s, int rowBegin, int rowEnd) {
    const double inv = 1.0 / s, norm = weight / (double(s) * s);
    // cos/sin of every sub-sample column, shared by all rows.
    std::vector<Vec2> columns(size_t(width_) * size_t(s));
    for (int ix = 0; ix < width_; ++ix)
        for (int a = 0; a < s; ++a) {
            const double phi = 2 * kPi * (ix + (a + 0.5) * inv) / width_;
            columns[size_t(ix) * s + a] = {std::cos(phi), std::sin(phi)};
        }
    parallelFor(size_t(std::max(0, rowEnd - rowBegin)), [&](size_t row) {
        const int iy = rowBegin + int(row);
        std::vector<Vec3> sums(static_cast<size_t>(width_));
        for (int b = 0; b < s; ++b) {
            const double z = direction(0, iy, 0, (b + 0.5) * inv).z;
            const double r = std::sqrt(std::max(0.0, 1 - z * z));
            const auto g = rowFunction(z);
            for (int ix = 0; ix < width_; ++ix)
                for (int a = 0; a < s; ++a) {
                    const Vec2 c = columns[size_t(ix) * s + a];
                    sums[size_t(ix)] += g(Vec3(r * c.x, r * c.y, z));
                }
        }
        for (int ix = 0; ix < width_; ++ix) at(ix, iy) += sums[size_t(ix)] * norm;
    });
}

}  // namespace luxplan
