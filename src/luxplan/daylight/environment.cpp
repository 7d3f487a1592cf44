// SkyMap geometry and DaylightEnvironment: ground, illuminance integrals, lookups, sampling.
#include <luxplan/daylight/environment.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <luxplan/core/sin_cos.h>
#include <luxplan/core/warp.h>
#include <luxplan/daylight/preetham.h>

namespace luxplan {
namespace {

// Directions within this much (in cosine) outside a disk's rim still count as inside it, so
// that cone samples land in their own disk despite rounding; it widens the 1.1e-5 of
// (1 - cos half-angle) by 1e-7 relative.
constexpr double kDiskRimTolerance = 1e-12;

}  // namespace

SkyMap::SkyMap(int width, int height) : width_(width), height_(height) {
    if (width < 1 || height < 2 || height % 2 != 0)
        throw std::invalid_argument("SkyMap: width must be >= 1 and height even and >= 2");
    pixels_.assign(size_t(width) * size_t(height), Vec3{});
    cosEdges_.resize(size_t(height) + 1);
    // Exactly symmetric edges, with the horizon at exactly 0.
    for (int i = 0; i <= height / 2; ++i) {
        double c = i == height / 2 ? 0.0 : std::cos(kPi * i / height);
        cosEdges_[size_t(i)] = c;
        cosEdges_[size_t(height - i)] = -c;
    }
    const int steps = 4 * height;
    rowGuess_.resize(size_t(steps) + 1);
    for (int b = 0; b <= steps; ++b) {
        const double z = -1 + 2.0 * b / steps;
        int iy = 0;
        while (iy < height - 1 && z <= cosEdges_[size_t(iy) + 1]) ++iy;
        rowGuess_[size_t(b)] = iy;
    }
}

void SkyMap::pixelOf(const Vec3& w, int& ix, int& iy) const {
    const double z = std::clamp(w.z, -1.0, 1.0);
    iy = rowGuess_[size_t(std::clamp(int((z + 1) * (2 * height_)), 0, 4 * height_))];
    while (iy > 0 && z > cosEdges_[size_t(iy)]) --iy;
    while (iy < height_ - 1 && z <= cosEdges_[size_t(iy) + 1]) ++iy;
    double phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    ix = std::clamp(int(phi / (2 * kPi) * width_), 0, width_ - 1);
}

double SkyMap::pixelSolidAngle(int iy) const {
    return (2 * kPi / width_) * (cosEdges_[size_t(iy)] - cosEdges_[size_t(iy) + 1]);
}

Vec3 SkyMap::direction(int ix, int iy, double fx, double fz) const {
    const double phi = 2 * kPi * (ix + fx) / width_;
    const double z = cosEdges_[size_t(iy)] + fz * (cosEdges_[size_t(iy) + 1] - cosEdges_[size_t(iy)]);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const SinCos t = sinCos(phi);
    return {r * t.cos, r * t.sin, z};
}

DaylightEnvironment::DaylightEnvironment(SkyMap sky, std::vector<SunDisk> suns, double groundReflectance)
    : DaylightEnvironment(std::move(sky), std::move(suns), groundReflectance, nullptr) {}

DaylightEnvironment::DaylightEnvironment(SkyMap sky, std::vector<SunDisk> suns, const Vec3& groundRadiance)
    : DaylightEnvironment(std::move(sky), std::move(suns), 0.0, &groundRadiance) {}

DaylightEnvironment::DaylightEnvironment(SkyMap sky, std::vector<SunDisk> suns, double groundReflectance,
                                         const Vec3* groundRadiance)
    : map_(std::move(sky)), suns_(std::move(suns)), groundReflectance_(groundReflectance) {
    const int w = map_.width(), h = map_.height();
    if (w == 0) throw std::invalid_argument("DaylightEnvironment: empty sky map");
    const double dPhi = 2 * kPi / w;

    // Horizontal illuminance of the sky: each pixel's cosine-weighted solid angle is
    // dPhi * (z0^2 - z1^2) / 2 exactly.
    Vec3 skyE;
    for (int iy = 0; iy < h / 2; ++iy) {
        const double z0 = map_.cosEdge(iy), z1 = map_.cosEdge(iy + 1);
        const double projected = dPhi * (z0 * z0 - z1 * z1) / 2;
        Vec3 row;
        for (int ix = 0; ix < w; ++ix) row += map_.at(ix, iy);
        skyE += row * projected;
    }
    // Sun disks: integral of a uniform cone of radiance L over a plane is L pi sin^2(a) cos(altitude).
    Vec3 sunE;
    for (const SunDisk& s : suns_) sunE += s.radiance() * (kSunDiskProjectedSolidAngle * std::max(0.0, s.direction.z));
    skyHorizontal_ = luminance(skyE);
    sunHorizontal_ = luminance(sunE);

    // Ground: diffuse reflection of the light on the open horizontal plane.
    ground_ = groundRadiance ? *groundRadiance : (skyE + sunE) * (groundReflectance_ * kInvPi);
    for (int iy = h / 2; iy < h; ++iy)
        for (int ix = 0; ix < w; ++ix) map_.at(ix, iy) = ground_;
    radiancePositive_ = maxComponent(ground_) > 0;
    for (const Vec3& pixel : map_.pixels()) radiancePositive_ = radiancePositive_ && maxComponent(pixel) > 0;

    // Sampling in (phi, -cos theta), where area equals solid angle, proportional to luminance.
    std::vector<double> values(size_t(w) * h), xEdges(size_t(w) + 1), yEdges(size_t(h) + 1);
    for (int ix = 0; ix <= w; ++ix) xEdges[size_t(ix)] = dPhi * ix;
    for (int iy = 0; iy <= h; ++iy) yEdges[size_t(iy)] = -map_.cosEdge(iy);
    skyIntegral_ = 0;
    for (int iy = 0; iy < h; ++iy)
        for (int ix = 0; ix < w; ++ix) {
            double lv = std::max(0.0, luminance(map_.at(ix, iy)));
            values[size_t(iy) * w + ix] = lv;
            skyIntegral_ += lv * map_.pixelSolidAngle(iy);
        }
    skyDistribution_ = Distribution2D(values, xEdges, yEdges);

    if (!suns_.empty()) {
        std::vector<double> weights;
        for (const SunDisk& s : suns_) weights.push_back(std::max(0.0, s.luminance));
        sunDistribution_ = Distribution1D(weights);
        for (const SunDisk& s : suns_) sunFrames_.push_back(Frame::fromNormal(s.direction));
        sunIntegral_ = sunDistribution_.integral() * double(suns_.size()) * kSunSolidAngle;
        indexSunDisks();
    }
}

namespace {

constexpr int kThetaCells = 180, kPhiCells = 360;  // 1-degree cells
constexpr double kCell = kPi / kThetaCells;  // radians, both ways

int thetaCell(double theta) { return std::clamp(int(theta / kCell), 0, kThetaCells - 1); }
int phiCell(double phi) { return std::clamp(int((phi + kPi) / kCell), 0, kPhiCells - 1); }

}  // namespace

void DaylightEnvironment::indexSunDisks() {
    // Each disk goes into every cell its cone (widened a little for the rim
    // tolerance and rounding) may reach.
    const double reach = kSunHalfAngle * 1.01 + 1e-6;
    Vec3 sum;
    for (const SunDisk& s : suns_) sum += s.direction;
    sunConeCos_ = -2;  // every direction
    if (length(sum) > 1e-9) {
        sunConeAxis_ = normalize(sum);
        double widest = 0;
        for (const SunDisk& s : suns_) widest = std::max(widest, std::acos(std::clamp(dot(s.direction, sunConeAxis_), -1.0, 1.0)));
        // Wider by the disk, its rim tolerance and rounding.
        if (widest + 2 * reach < kPi / 2) sunConeCos_ = std::cos(widest + 2 * reach), sunConeSin_ = std::sin(widest + 2 * reach);
    }
    // Apart by more than two of the widened disks (checked pair by pair up to a few
    // thousand disks; beyond that, many steps overlap anyway).
    sunDisksApart_ = suns_.size() <= 4096;
    const double apartCos = std::cos(2 * reach);
    for (size_t i = 0; i < suns_.size() && sunDisksApart_; ++i)
        for (size_t j = i + 1; j < suns_.size(); ++j)
            if (dot(suns_[i].direction, suns_[j].direction) >= apartCos) {
                sunDisksApart_ = false;
                break;
            }
    std::vector<std::vector<uint32_t>> cells(size_t(kThetaCells) * kPhiCells);
    for (size_t k = 0; k < suns_.size(); ++k) {
        const Vec3& d = suns_[k].direction;
        const double theta = std::acos(std::clamp(d.z, -1.0, 1.0)), phi = std::atan2(d.y, d.x);
        const double lo = theta - reach, hi = theta + reach;
        const int t0 = thetaCell(std::max(0.0, lo)), t1 = thetaCell(std::min(kPi, hi));
        int halfSpan = kPhiCells;  // near a pole: every phi
        if (lo > 0 && hi < kPi) {
            double s = std::sin(reach) / std::min(std::sin(lo), std::sin(hi));
            if (s < 1) halfSpan = int(std::asin(s) / kCell) + 2;
        }
        const int p = phiCell(phi);
        for (int t = t0; t <= t1; ++t) {
            if (2 * halfSpan + 1 >= kPhiCells) {
                for (int q = 0; q < kPhiCells; ++q) cells[size_t(t) * kPhiCells + q].push_back(uint32_t(k));
            } else {
                for (int q = p - halfSpan; q <= p + halfSpan; ++q)
                    cells[size_t(t) * kPhiCells + size_t((q + kPhiCells) % kPhiCells)].push_back(uint32_t(k));
            }
        }
    }
    sunCellStart_.assign(1, 0);
    sunCellDisks_.clear();
    for (const auto& c : cells) {
        sunCellDisks_.insert(sunCellDisks_.end(), c.begin(), c.end());
        sunCellStart_.push_back(uint32_t(sunCellDisks_.size()));
    }
}

template <class F>
void DaylightEnvironment::forEachSunDiskAt(const Vec3& w, F&& f) const {
    if (sunCellStart_.empty() || dot(w, sunConeAxis_) < sunConeCos_) return;
    const double theta = std::acos(std::clamp(w.z, -1.0, 1.0)), phi = std::atan2(w.y, w.x);
    const size_t c = size_t(thetaCell(theta)) * kPhiCells + size_t(phiCell(phi));
    for (uint32_t i = sunCellStart_[c]; i < sunCellStart_[c + 1]; ++i) {
        const uint32_t k = sunCellDisks_[i];
        if (dot(w, suns_[k].direction) >= kSunCosHalfAngle - kDiskRimTolerance) f(k);
    }
}

Vec3 DaylightEnvironment::Le(const Vec3& w) const {
    if (map_.width() == 0) return {};
    // The rows from the horizon down all hold the ground (pixelOf puts z <= 0 there):
    // no pixel to find, no cache line to miss.
    if (w.z <= 0) return ground_;
    int ix, iy;
    map_.pixelOf(w, ix, iy);
    return map_.at(ix, iy);
}

double DaylightEnvironment::skyPdf(const Vec3& w) const {
    if (map_.width() == 0) return 0;
    int ix, iy;
    map_.pixelOf(w, ix, iy);
    return skyDistribution_.cellPdf(size_t(ix), size_t(iy));
}

EnvironmentSample DaylightEnvironment::sampleSky(Vec2 u) const {
    EnvironmentSample s;
    if (map_.width() == 0) return s;
    Distribution2D::Sample d = skyDistribution_.sample(u);
    const double phi = d.p.x, z = std::clamp(-d.p.y, -1.0, 1.0);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const SinCos t = sinCos(phi);
    s.wi = {r * t.cos, r * t.sin, z};
    // Evaluate through the same pixel lookup as Le()/skyPdf() so that all three agree.
    int ix, iy;
    map_.pixelOf(s.wi, ix, iy);
    s.pdf = skyDistribution_.cellPdf(size_t(ix), size_t(iy));
    s.Le = s.wi.z <= 0 ? ground_ : map_.at(ix, iy);  // as Le(): the ground's rows hold ground_
    return s;
}

Vec3 DaylightEnvironment::sunLe(const Vec3& w) const {
    Vec3 sum;
    forEachSunDiskAt(w, [&](uint32_t k) { sum += suns_[k].radiance(); });
    return sum;
}

double DaylightEnvironment::sunPdf(const Vec3& w) const {
    if (suns_.empty()) return 0;
    double pmfSum = 0;
    forEachSunDiskAt(w, [&](uint32_t k) { pmfSum += sunDistribution_.pmf(k); });
    return pmfSum / kSunSolidAngle;
}

void DaylightEnvironment::sunAt(const Vec3& w, Vec3& Le, double& pdf) const {
    Le = Vec3();
    double pmfSum = 0;
    forEachSunDiskAt(w, [&](uint32_t k) {
        Le += suns_[k].radiance();
        pmfSum += sunDistribution_.pmf(k);
    });
    pdf = pmfSum / kSunSolidAngle;
}

size_t DaylightEnvironment::sunDiskOf(double uDisk) const { return suns_.empty() ? 0 : sunDistribution_.sampleDiscrete(uDisk); }

EnvironmentSample DaylightEnvironment::sampleSunDisk(size_t k, Vec2 u) const {
    EnvironmentSample s;
    if (suns_.empty()) return s;
    s.wi = normalize(sunFrames_[k].toWorld(sampleUniformCone(u, kSunCosHalfAngle)));
    if (sunDisksApart_) {
        // What sunAt would sum: disk k alone (the same rim test).
        if (dot(s.wi, suns_[k].direction) >= kSunCosHalfAngle - kDiskRimTolerance) {
            s.Le = suns_[k].radiance();
            s.pdf = sunDistribution_.pmf(k) / kSunSolidAngle;
        }
        return s;
    }
    sunAt(s.wi, s.Le, s.pdf);
    return s;
}

double DaylightEnvironment::illuminance(const Vec3& n, bool withGround, bool withSun) const {
    double e = 0;
    if (map_.width() > 0) {
        const int sub = 4, rows = withGround ? map_.height() : map_.height() / 2;
        for (int iy = 0; iy < rows; ++iy) {
            const double cellWeight = map_.pixelSolidAngle(iy) / (sub * sub);
            for (int ix = 0; ix < map_.width(); ++ix) {
                const double lv = luminance(map_.at(ix, iy));
                if (lv == 0) continue;
                double cosSum = 0;
                for (int a = 0; a < sub; ++a)
                    for (int b = 0; b < sub; ++b)
                        cosSum += std::max(0.0, dot(n, map_.direction(ix, iy, (a + 0.5) / sub, (b + 0.5) / sub)));
                e += lv * cosSum * cellWeight;
            }
        }
    }
    if (withSun)
        for (const SunDisk& s : suns_)
            e += s.luminance * kSunDiskProjectedSolidAngle * std::max(0.0, dot(n, s.direction));
    return e;
}

}  // namespace luxplan
