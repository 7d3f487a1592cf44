// Piecewise-constant distributions: construction, inversion-method sampling and pdfs.
#include <luxplan/daylight/distribution.h>

#include <algorithm>
#include <stdexcept>

namespace luxplan {
namespace {

std::vector<double> uniformEdges(size_t n) {
    std::vector<double> e(n + 1);
    for (size_t i = 0; i <= n; ++i) e[i] = double(i) / double(n);
    return e;
}

}  // namespace

Distribution1D::Distribution1D(std::span<const double> values) : Distribution1D(values, uniformEdges(values.size())) {}

Distribution1D::Distribution1D(std::span<const double> values, std::span<const double> edges)
    : values_(values.begin(), values.end()), edges_(edges.begin(), edges.end()) {
    if (values_.empty() || edges_.size() != values_.size() + 1)
        throw std::invalid_argument("Distribution1D: need n > 0 values and n + 1 edges");
    const size_t n = values_.size();
    cdf_.assign(n + 1, 0.0);
    for (size_t i = 0; i < n; ++i) {
        if (!(values_[i] >= 0) || !std::isfinite(values_[i]))
            throw std::invalid_argument("Distribution1D: values must be finite and non-negative");
        if (!(edges_[i + 1] > edges_[i])) throw std::invalid_argument("Distribution1D: edges must increase");
        cdf_[i + 1] = cdf_[i] + values_[i] * (edges_[i + 1] - edges_[i]);
    }
    integral_ = cdf_[n];
    if (integral_ > 0) {
        for (double& c : cdf_) c /= integral_;
    } else {
        // All zero: fall back to the uniform density over the domain.
        const double width = edges_[n] - edges_[0];
        for (size_t i = 1; i <= n; ++i) cdf_[i] = (edges_[i] - edges_[0]) / width;
    }
    cdf_[n] = 1.0;
}

double Distribution1D::sampleContinuous(double u, double* pdfOut, size_t* binOut) const {
    double t = 0;
    size_t i = sampleDiscrete(u, nullptr, &t);
    double x = edges_[i] + t * (edges_[i + 1] - edges_[i]);
    if (x >= edges_[i + 1]) x = std::nextafter(edges_[i + 1], edges_[i]);
    if (pdfOut) *pdfOut = binPdf(i);
    if (binOut) *binOut = i;
    return x;
}

size_t Distribution1D::sampleDiscrete(double u, double* pmfOut, double* uRemapped) const {
    u = std::clamp(u, 0.0, 1.0);
    // The index upper_bound finds: the number of cdf values <= u. For a few bins (a
    // period's sun disks, drawn at every path vertex) counted without branches, which a
    // random u would mispredict.
    size_t i = 0;
    if (cdf_.size() <= 32) {
        for (double c : cdf_) i += c <= u;
    } else {
        i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
    }
    i = std::clamp<size_t>(i, 1, values_.size()) - 1;
    // cdf[i] <= u < cdf[i+1] implies pmf(i) > 0, except at u = 1: step back to a non-empty bin.
    while (pmf(i) == 0 && i > 0) --i;
    double p = pmf(i);
    if (pmfOut) *pmfOut = p;
    if (uRemapped) *uRemapped = p > 0 ? std::clamp((u - cdf_[i]) / p, 0.0, std::nextafter(1.0, 0.0)) : 0.0;
    return i;
}

size_t Distribution1D::binOf(double x) const {
    size_t i = size_t(std::upper_bound(edges_.begin(), edges_.end(), x) - edges_.begin());
    return std::clamp<size_t>(i, 1, values_.size()) - 1;
}

double Distribution1D::pdf(double x) const {
    if (x < edges_.front() || x > edges_.back()) return 0;
    return binPdf(binOf(x));
}

double Distribution1D::cdf(double x) const {
    if (x <= edges_.front()) return 0;
    if (x >= edges_.back()) return 1;
    size_t i = binOf(x);
    return cdf_[i] + pmf(i) * (x - edges_[i]) / (edges_[i + 1] - edges_[i]);
}

Distribution2D::Distribution2D(std::span<const double> values, std::span<const double> xEdges,
                               std::span<const double> yEdges) {
    const size_t nx = xEdges.size() - 1, ny = yEdges.size() - 1;
    if (xEdges.size() < 2 || yEdges.size() < 2 || values.size() != nx * ny)
        throw std::invalid_argument("Distribution2D: values must have (xEdges-1)*(yEdges-1) entries");
    std::vector<double> rowIntegrals(ny);
    rowOf_.reserve(ny);
    for (size_t iy = 0; iy < ny; ++iy) {
        const std::span<const double> rowValues = values.subspan(iy * nx, nx);
        if (iy == 0 || !std::equal(rowValues.begin(), rowValues.end(), values.begin() + std::ptrdiff_t((iy - 1) * nx)))
            conditional_.emplace_back(rowValues, xEdges);
        rowOf_.push_back(uint32_t(conditional_.size() - 1));
        rowIntegrals[iy] = conditional_.back().integral();
    }
    marginal_ = Distribution1D(rowIntegrals, yEdges);
}

Distribution2D::Sample Distribution2D::sample(Vec2 u) const {
    Sample s;
    double pdfY = 0, pdfX = 0;
    s.p.y = marginal_.sampleContinuous(u.y, &pdfY, &s.iy);
    s.p.x = row(s.iy).sampleContinuous(u.x, &pdfX, &s.ix);
    s.pdf = pdfX * pdfY;
    return s;
}

double Distribution2D::cellPdf(size_t ix, size_t iy) const {
    return marginal_.binPdf(iy) * row(iy).binPdf(ix);
}

double Distribution2D::pdf(Vec2 p) const {
    if (p.y < marginal_.lower() || p.y > marginal_.upper()) return 0;
    const Distribution1D& conditional = row(marginal_.binOf(p.y));
    if (p.x < conditional.lower() || p.x > conditional.upper()) return 0;
    return cellPdf(conditional.binOf(p.x), marginal_.binOf(p.y));
}

}  // namespace luxplan
