// Piecewise-constant 1D and 2D distributions over bins with arbitrary edges, for
// importance sampling tabulated functions (environment maps, sun disks by weight).
// Sampling follows pbrt-v4's PiecewiseConstant1D/2D (https://pbr-book.org/4ed/Monte_Carlo_Integration);
// callers pass the uniform random numbers `u` in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <luxplan/core/math.h>

namespace luxplan {

// Density proportional to a non-negative step function f over [edges[0], edges[n]]:
// f(x) = values[i] for x in [edges[i], edges[i+1]). If every value is zero the
// distribution is uniform over the domain (and pdf() says so), so sampling never fails.
class Distribution1D {
public:
    Distribution1D() = default;
    // n bins of equal width on [0, 1].
    explicit Distribution1D(std::span<const double> values);
    // n bins with the given n + 1 increasing edges.
    Distribution1D(std::span<const double> values, std::span<const double> edges);

    size_t size() const { return values_.size(); }
    double integral() const { return integral_; }  // sum values[i] * width[i] (0 if all zero)
    bool allZero() const { return integral_ == 0; }
    double lower() const { return edges_.front(); }
    double upper() const { return edges_.back(); }
    double value(size_t i) const { return values_[i]; }
    double edge(size_t i) const { return edges_[i]; }

    // Continuous sample x with density pdf (per unit x); bin receives the bin index.
    double sampleContinuous(double u, double* pdf = nullptr, size_t* bin = nullptr) const;
    // Bin i with probability pmf(i) = values[i] * width[i] / integral; uRemapped is u
    // rescaled to [0, 1) within the chosen bin (reusable as a fresh uniform number).
    size_t sampleDiscrete(double u, double* pmf = nullptr, double* uRemapped = nullptr) const;
    // Density at x per unit x (0 outside the domain), probability of bin i, density of bin i.
    double pdf(double x) const;
    double pmf(size_t i) const { return cdf_[i + 1] - cdf_[i]; }
    double binPdf(size_t i) const { return pmf(i) / (edges_[i + 1] - edges_[i]); }
    // Index of the bin holding x (x clamped to the domain).
    size_t binOf(double x) const;
    // Cumulative distribution at x: the u for which sampleContinuous(u) == x.
    double cdf(double x) const;

private:
    std::vector<double> values_, edges_, cdf_;
    double integral_ = 0;
};

// Density proportional to a non-negative step function over a grid of nx * ny cells
// (values row-major, row iy spans [yEdges[iy], yEdges[iy+1]]): y from the marginal,
// then x from the row's conditional. Densities are per unit area in (x, y).
class Distribution2D {
public:
    Distribution2D() = default;
    Distribution2D(std::span<const double> values, std::span<const double> xEdges, std::span<const double> yEdges);

    struct Sample {
        Vec2 p;          // (x, y)
        double pdf = 0;  // per unit area in (x, y)
        size_t ix = 0, iy = 0;
    };
    Sample sample(Vec2 u) const;
    double pdf(Vec2 p) const;
    double cellPdf(size_t ix, size_t iy) const;
    double integral() const { return marginal_.integral(); }
    bool allZero() const { return marginal_.allZero(); }
    size_t nx() const { return conditional_.empty() ? 0 : conditional_.front().size(); }
    size_t ny() const { return rowOf_.size(); }

private:
    const Distribution1D& row(size_t iy) const { return conditional_[rowOf_[iy]]; }

    // Rows equal to the row before them share its distribution (a sky map's ground
    // half: one row's cdf in the cache instead of 128 of them, the same numbers).
    std::vector<Distribution1D> conditional_;
    std::vector<uint32_t> rowOf_;  // per row, its distribution in conditional_
    Distribution1D marginal_;
};

}  // namespace luxplan
