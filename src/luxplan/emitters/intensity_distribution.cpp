#include <luxplan/emitters/intensity_distribution.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <luxplan/core/sin_cos.h>

namespace luxplan {
namespace {

constexpr double kAngleEpsDeg = 1e-6;  // planes closer than this are one plane

// The C range a symmetry stores, in degrees.
std::pair<double, double> storedRange(CSymmetry s) {
    switch (s) {
        case CSymmetry::None: return {0, 360};
        case CSymmetry::Rotational: return {0, 360};
        case CSymmetry::AboutC0C180: return {0, 180};
        case CSymmetry::AboutC90C270: return {90, 270};
        case CSymmetry::Quadrants: return {0, 90};
    }
    return {0, 360};
}

// Where plane c (degrees) also stands by the symmetry, itself included.
std::vector<double> images(CSymmetry s, double c) {
    switch (s) {
        case CSymmetry::None: return {c};
        case CSymmetry::Rotational: return {0};
        case CSymmetry::AboutC0C180: return {c, 360 - c};
        case CSymmetry::AboutC90C270: return {c, 180 - c};
        case CSymmetry::Quadrants: return {c, 180 - c, 180 + c, 360 - c};
    }
    return {c};
}

double wrapDeg(double c) {
    c = std::fmod(c, 360.0);
    if (c < 0) c += 360;
    return c >= 360 - kAngleEpsDeg ? 0 : c;
}

// Index i of the interval [v[i], v[i+1]] holding x (v increasing, x inside).
size_t intervalOf(const std::vector<double>& v, double x) {
    size_t i = size_t(std::upper_bound(v.begin(), v.end(), x) - v.begin());
    return std::min(i == 0 ? 0 : i - 1, v.size() - 2);
}

// Integral over [a, b] of (A + B g) sin g dg.
double linearTimesSin(double A, double B, double a, double b) {
    auto F = [&](double g) { return -A * std::cos(g) + B * (std::sin(g) - g * std::cos(g)); };
    return F(b) - F(a);
}

}  // namespace

IntensityDistribution::IntensityDistribution(const PhotometricTable& t) {
    const size_t nc = t.cDeg.size(), ng = t.gammaDeg.size();
    if (nc == 0 || ng < 2 || t.candela.size() != nc * ng)
        throw std::invalid_argument("photometric table: needs one C plane, two gamma angles and nc * ngamma values");
    for (size_t i = 0; i < ng; ++i)
        if (t.gammaDeg[i] < 0 || t.gammaDeg[i] > 180 || (i > 0 && !(t.gammaDeg[i] > t.gammaDeg[i - 1])))
            throw std::invalid_argument("photometric table: gamma angles must increase within [0, 180]");
    auto [lo, hi] = storedRange(t.symmetry);
    for (size_t i = 0; i < nc; ++i)
        if (t.cDeg[i] < lo - kAngleEpsDeg || t.cDeg[i] > hi + kAngleEpsDeg || (i > 0 && !(t.cDeg[i] > t.cDeg[i - 1])))
            throw std::invalid_argument("photometric table: C angles must increase within the symmetry's range");
    for (double v : t.candela)
        if (!(v >= 0) || !std::isfinite(v)) throw std::invalid_argument("photometric table: candela must be finite and >= 0");

    // Every stored plane and its mirror images, sorted by C in [0, 360); the first
    // copy of a plane wins (a file's C = 360 repeats its C = 0).
    const size_t used = t.symmetry == CSymmetry::Rotational ? 1 : nc;
    std::vector<std::pair<double, size_t>> planes;
    for (size_t i = 0; i < used; ++i)
        for (double c : images(t.symmetry, t.cDeg[i])) planes.push_back({wrapDeg(c), i});
    std::stable_sort(planes.begin(), planes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<double, std::vector<double>>> columns;
    for (const auto& [c, i] : planes) {
        if (!columns.empty() && c - columns.back().first < kAngleEpsDeg) continue;
        columns.push_back({c, std::vector<double>(t.candela.begin() + long(i * ng), t.candela.begin() + long((i + 1) * ng))});
    }
    // Close the circle: a plane at C = 0 (interpolated across the wrap when the
    // file has none there; inserting a point on a linear piece changes nothing) and
    // its copy at C = 360.
    if (columns.front().first > kAngleEpsDeg) {
        const auto& first = columns.front();
        const auto& last = columns.back();
        double span = first.first + 360 - last.first, w = (360 - last.first) / span;
        std::vector<double> at0(ng);
        for (size_t g = 0; g < ng; ++g) at0[g] = last.second[g] + w * (first.second[g] - last.second[g]);
        columns.insert(columns.begin(), {0.0, at0});
    }
    columns.push_back({360.0, columns.front().second});

    for (const auto& [c, values] : columns) {
        c_.push_back(c * kPi / 180);
        values_.insert(values_.end(), values.begin(), values.end());
    }
    for (double g : t.gammaDeg) gamma_.push_back(g * kPi / 180);
    for (size_t ic = 0; ic + 1 < c_.size(); ++ic)
        for (size_t ig = 0; ig + 1 < gamma_.size(); ++ig) flux_ += cellMass(ic, ig, c_[ic], c_[ic + 1], gamma_[ig], gamma_[ig + 1]);
    // Light reaches gamma > 90 from a value there, or from one whose interval
    // reaches past 90 (interpolation carries it over).
    const double right = kPi / 2 + 1e-9;
    for (size_t ig = 0; ig < gamma_.size(); ++ig) {
        bool reaches = gamma_[ig] > right || (ig + 1 < gamma_.size() && gamma_[ig + 1] > right);
        for (size_t ic = 0; ic < c_.size() && reaches; ++ic) emitsBeyond90_ = emitsBeyond90_ || at(ic, ig) > 0;
    }
    buildSampling();
}

double IntensityDistribution::intensity(PhotometricAngles a) const {
    if (a.gamma < gamma_.front() - 1e-12 || a.gamma > gamma_.back() + 1e-12) return 0;
    double c = std::fmod(a.c, 2 * kPi);
    if (c < 0) c += 2 * kPi;
    double g = std::clamp(a.gamma, gamma_.front(), gamma_.back());
    size_t ic = intervalOf(c_, c), ig = intervalOf(gamma_, g);
    double tc = std::clamp((c - c_[ic]) / (c_[ic + 1] - c_[ic]), 0.0, 1.0);
    double tg = std::clamp((g - gamma_[ig]) / (gamma_[ig + 1] - gamma_[ig]), 0.0, 1.0);
    return (1 - tc) * ((1 - tg) * at(ic, ig) + tg * at(ic, ig + 1)) + tc * ((1 - tg) * at(ic + 1, ig) + tg * at(ic + 1, ig + 1));
}

double IntensityDistribution::intensity(const Vec3& local) const {
    double gamma = std::acos(std::clamp(local.z, -1.0, 1.0));
    double c = std::atan2(local.y, local.x);
    return intensity(PhotometricAngles{c, gamma});
}

double IntensityDistribution::cellMass(size_t ic, size_t ig, double c0, double c1, double g0, double g1) const {
    // Bilinear: linear in C between two columns, each linear in gamma; the C average
    // over [c0, c1] is the column blend at the interval's middle.
    double dc = c_[ic + 1] - c_[ic], dg = gamma_[ig + 1] - gamma_[ig];
    double t = ((c0 + c1) / 2 - c_[ic]) / dc;
    auto column = [&](size_t k) {
        double B = (at(k, ig + 1) - at(k, ig)) / dg, A = at(k, ig) - B * gamma_[ig];
        return linearTimesSin(A, B, g0, g1);
    };
    return (c1 - c0) * ((1 - t) * column(ic) + t * column(ic + 1));
}

void IntensityDistribution::buildSampling() {
    // A distribution constant in C (rotational) needs no cells across C.
    bool constantInC = true;
    for (size_t ic = 1; ic < c_.size() && constantInC; ++ic)
        for (size_t ig = 0; ig < gamma_.size(); ++ig)
            if (at(ic, ig) != at(0, ig)) constantInC = false;
    const double maxCell = kSampleCellDeg * kPi / 180;
    // Sub-cell edges in C and gamma, with the file cell each sub-cell lies in.
    std::vector<double> cEdges{0}, gEdges{gamma_.front()};
    std::vector<size_t> cCell, gCell;
    for (size_t ic = 0; ic + 1 < c_.size(); ++ic) {
        int n = constantInC ? 1 : std::max(1, int(std::ceil((c_[ic + 1] - c_[ic]) / maxCell - 1e-9)));
        for (int k = 1; k <= n; ++k) cEdges.push_back(k == n ? c_[ic + 1] : c_[ic] + (c_[ic + 1] - c_[ic]) * k / n), cCell.push_back(ic);
    }
    for (size_t ig = 0; ig + 1 < gamma_.size(); ++ig) {
        int n = std::max(1, int(std::ceil((gamma_[ig + 1] - gamma_[ig]) / maxCell - 1e-9)));
        for (int k = 1; k <= n; ++k)
            gEdges.push_back(k == n ? gamma_[ig + 1] : gamma_[ig] + (gamma_[ig + 1] - gamma_[ig]) * k / n), gCell.push_back(ig);
    }
    // Density per unit (C, 1 - cos gamma), which is per unit solid angle: each
    // sub-cell's mean intensity.
    const size_t nx = cCell.size(), ny = gCell.size();
    std::vector<double> values(nx * ny), yEdges(ny + 1);
    for (size_t j = 0; j <= ny; ++j) yEdges[j] = 1 - std::cos(gEdges[j]);
    for (size_t j = 0; j < ny; ++j)
        for (size_t i = 0; i < nx; ++i) {
            double mass = cellMass(cCell[i], gCell[j], cEdges[i], cEdges[i + 1], gEdges[j], gEdges[j + 1]);
            double omega = (cEdges[i + 1] - cEdges[i]) * (yEdges[j + 1] - yEdges[j]);
            values[j * nx + i] = omega > 0 ? std::max(0.0, mass) / omega : 0;
        }
    sampling_ = Distribution2D(values, cEdges, yEdges);
}

IntensityDistribution::DirectionSample IntensityDistribution::sample(Vec2 u) const {
    auto s = sampling_.sample(u);
    double cosG = std::clamp(1 - s.p.y, -1.0, 1.0), sinG = std::sqrt(std::max(0.0, 1 - cosG * cosG));
    const SinCos t = sinCos(s.p.x);
    return {Vec3(sinG * t.cos, sinG * t.sin, cosG), s.pdf};
}

double IntensityDistribution::pdf(const Vec3& local) const {
    double c = std::atan2(local.y, local.x);
    if (c < 0) c += 2 * kPi;
    return sampling_.pdf({c, 1 - std::clamp(local.z, -1.0, 1.0)});
}

}  // namespace luxplan
