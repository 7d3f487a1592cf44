#include <luxplan/annual/sky_patches.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace luxplan {
namespace {

constexpr int kTregenzaCounts[7] = {30, 30, 24, 24, 18, 12, 6};

double azimuthOf(const Vec3& w) {
    const double a = std::atan2(w.x, w.y);
    return a < 0 ? a + 2 * kPi : a;
}

}  // namespace

SkyPatches::SkyPatches(int subdivision) : m_(subdivision) {
    if (m_ < 1 || m_ > 16) throw std::invalid_argument("sky patches: subdivision " + std::to_string(m_) + " outside [1, 16]");
    bandRadians_ = radians(90.0 / (7 * m_ + 0.5));
    int next = 1;  // patch 0 is the ground
    for (int row = 0; row < 7 * m_; ++row) {
        rowStart_.push_back(next);
        rowCount_.push_back(kTregenzaCounts[row / m_] * m_);
        next += rowCount_.back();
    }
    rowStart_.push_back(next);  // the cap: rowStart_.back(), and count() - 1
    rowCount_.push_back(1);
}

int SkyPatches::patchOf(const Vec3& w) const {
    if (!(w.z >= 0)) return 0;
    const double altitude = std::asin(std::clamp(w.z, -1.0, 1.0));
    const int row = std::min(int(altitude / bandRadians_), 7 * m_);
    if (row >= 7 * m_) return rowStart_.back();
    const int n = rowCount_[size_t(row)];
    const int k = std::min(n - 1, int(azimuthOf(w) / (2 * kPi) * n));
    return rowStart_[size_t(row)] + k;
}

SkyPatches::Span SkyPatches::span(int patch) const {
    if (patch <= 0 || patch >= count()) throw std::out_of_range("sky patches: no sky patch " + std::to_string(patch));
    const int rows = 7 * m_;
    if (patch == rowStart_.back()) return {std::sin(rows * bandRadians_), 1.0, 0.0, 2 * kPi};
    const int row = int(std::upper_bound(rowStart_.begin(), rowStart_.begin() + rows, patch) - rowStart_.begin()) - 1;
    const int n = rowCount_[size_t(row)], k = patch - rowStart_[size_t(row)];
    return {std::sin(row * bandRadians_), std::sin((row + 1) * bandRadians_), 2 * kPi * k / n, 2 * kPi * (k + 1) / n};
}

double SkyPatches::solidAngle(int patch) const {
    if (patch == 0) return 2 * kPi;
    const Span s = span(patch);
    return (s.sinHigh - s.sinLow) * (s.azimuthHigh - s.azimuthLow);
}

double SkyPatches::projectedSolidAngle(int patch) const {
    if (patch == 0) return 0;
    const Span s = span(patch);
    return (s.sinHigh * s.sinHigh - s.sinLow * s.sinLow) / 2 * (s.azimuthHigh - s.azimuthLow);
}

Vec3 SkyPatches::centre(int patch) const {
    if (patch == 0) return {0, 0, -1};
    if (patch == rowStart_.back()) return {0, 0, 1};
    return directions(patch, 1).front();
}

std::vector<Vec3> SkyPatches::directions(int patch, int n) const {
    const Span s = span(patch);
    std::vector<Vec3> out;
    out.reserve(size_t(n) * size_t(n));
    for (int i = 0; i < n; ++i) {
        const double z = s.sinLow + (s.sinHigh - s.sinLow) * (i + 0.5) / n, r = std::sqrt(std::max(0.0, 1 - z * z));
        for (int j = 0; j < n; ++j) {
            const double a = s.azimuthLow + (s.azimuthHigh - s.azimuthLow) * (j + 0.5) / n;
            out.push_back({r * std::sin(a), r * std::cos(a), z});
        }
    }
    return out;
}

}  // namespace luxplan
