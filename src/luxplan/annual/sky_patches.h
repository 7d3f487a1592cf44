// The sky in patches, as daylight coefficients bin it: Reinhart's subdivision of
// Tregenza's 145 patches (Radiance's reinhart.cal), MF:m giving 7m bands of azimuth
// counts {30, 30, 24, 24, 18, 12, 6} x m from the horizon up and one polar cap, so
// MF:1 = 145 patches, MF:2 = 577, MF:4 = 2305; patch 0 is the ground below the horizon.
// Directions are in scene coordinates (z up); azimuth is measured clockwise from +y.
#pragma once

#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

class SkyPatches {
public:
    explicit SkyPatches(int subdivision = 1);

    int subdivision() const { return m_; }
    // Patches including the ground (patch 0).
    int count() const { return int(rowStart_.back()) + 1; }
    // The patch of unit direction w (0 below the horizon: w.z < 0).
    int patchOf(const Vec3& w) const;
    // A patch's solid angle (sr; the ground's: 2 pi).
    double solidAngle(int patch) const;
    // Its centre direction (the ground's: straight down).
    Vec3 centre(int patch) const;
    // n x n directions equal in solid angle over a sky patch (stratified in sin(altitude)
    // and azimuth, each at its cell's middle): a patch's mean of a function.
    std::vector<Vec3> directions(int patch, int n) const;
    // Its projected solid angle on a horizontal plane facing up (sr; the ground's: 0).
    double projectedSolidAngle(int patch) const;

private:
    struct Span {
        double sinLow, sinHigh, azimuthLow, azimuthHigh;  // radians
    };
    Span span(int patch) const;
    int m_;
    double bandRadians_;             // each band's altitude span, 90 deg / (7 m + 0.5)
    std::vector<int> rowStart_;      // first patch of each band, then the cap's
    std::vector<int> rowCount_;      // patches in each band, then the cap's 1
};

}  // namespace luxplan
