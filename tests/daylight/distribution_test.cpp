// Piecewise-constant 1D/2D distributions: chi-square of samples against pdfs, normalization,
// discrete pmfs, cdf inversion and the all-zero fallback.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/daylight/distribution.h>
#include "support/chi2.h"

namespace luxplan {
namespace {

TEST(Distribution1D, SamplesMatchPdfWithUnevenEdges) {
    const std::vector<double> values = {1.0, 0.0, 3.0, 0.5, 2.0};
    const std::vector<double> edges = {-1.0, -0.5, 0.0, 0.25, 1.5, 2.0};
    Distribution1D d(values, edges);
    EXPECT_DOUBLE_EQ(d.integral(), 1.0 * 0.5 + 0 + 3.0 * 0.25 + 0.5 * 1.25 + 2.0 * 0.5);
    // Bins for the test: 60 equal cells across the domain; expected = integral of the pdf.
    const int cells = 60, n = 200000;
    std::vector<double> observed(cells, 0), expected(cells, 0);
    Rng rng(11);
    for (int k = 0; k < n; ++k) {
        double pdf = 0;
        double x = d.sampleContinuous(rng.uniform(), &pdf);
        ASSERT_GE(x, -1.0);
        ASSERT_LT(x, 2.0);
        EXPECT_DOUBLE_EQ(pdf, d.pdf(x));
        ASSERT_GT(pdf, 0);
        observed[std::min(cells - 1, int((x + 1) / 3 * cells))] += 1;
    }
    for (int c = 0; c < cells; ++c) expected[c] = (d.cdf(-1 + 3.0 * (c + 1) / cells) - d.cdf(-1 + 3.0 * c / cells)) * n;
    auto r = test::chi2Test(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(Distribution1D, PdfIntegratesToOneAndCdfInvertsSampling) {
    const std::vector<double> values = {0.2, 5.0, 0.0, 1.0};
    const std::vector<double> edges = {0.0, 0.1, 0.2, 0.7, 1.0};
    Distribution1D d(values, edges);
    double sum = 0;
    const int m = 100000;
    for (int i = 0; i < m; ++i) sum += d.pdf((i + 0.5) / m) / m;
    EXPECT_NEAR(sum, 1.0, 1e-9);
    for (double u : {0.0, 0.01, 0.3, 0.5, 0.77, 0.999}) {
        double x = d.sampleContinuous(u);
        EXPECT_NEAR(d.cdf(x), u, 1e-12) << u;
    }
    // The empty bin (0.2, 0.7) is never sampled.
    Rng rng(3);
    for (int k = 0; k < 10000; ++k) {
        double x = d.sampleContinuous(rng.uniform());
        EXPECT_FALSE(x > 0.2 && x < 0.7) << x;
    }
}

TEST(Distribution1D, DiscreteSamplingFollowsPmf) {
    const std::vector<double> weights = {3, 0, 1, 6};
    Distribution1D d(weights);
    EXPECT_DOUBLE_EQ(d.pmf(0), 0.3);
    EXPECT_DOUBLE_EQ(d.pmf(1), 0.0);
    EXPECT_DOUBLE_EQ(d.pmf(3), 0.6);
    std::vector<double> observed(4, 0), expected(4, 0);
    Rng rng(5);
    const int n = 50000;
    for (int k = 0; k < n; ++k) {
        double pmf = 0, remapped = -1;
        size_t i = d.sampleDiscrete(rng.uniform(), &pmf, &remapped);
        EXPECT_EQ(pmf, d.pmf(i));
        EXPECT_GE(remapped, 0.0);
        EXPECT_LT(remapped, 1.0);
        observed[i] += 1;
    }
    for (int i = 0; i < 4; ++i) expected[i] = d.pmf(i) * n;
    EXPECT_EQ(observed[1], 0);
    auto r = test::chi2Test(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << r.table;
    // u = 1 (clamped) still returns a bin with mass.
    EXPECT_EQ(d.sampleDiscrete(1.0), 3u);
}

// sampleDiscrete counts a few bins and searches many: both must find the bin
// std::upper_bound finds over the whole cdf, at random, on the bins' edges and beside
// them, on the cdf's own values, and through runs of empty bins (an environment map's
// dark pixels).
TEST(Distribution1D, EveryWayOfSearchingFindsTheBinUpperBoundFinds) {
    Rng rng(41);
    for (const size_t n : {size_t(5), size_t(31), size_t(32), size_t(33), size_t(256), size_t(1000)}) {
        std::vector<double> values(n);
        for (size_t i = 0; i < n; ++i) values[i] = (i / 7) % 3 == 0 ? 0.0 : rng.uniform() * rng.uniform();
        values[n / 2] = 50;  // one bright bin spans many buckets
        // The cdf as the class builds it: the same sums and the same division.
        std::vector<double> cdf(n + 1, 0.0);
        for (size_t i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + values[i] * (double(i + 1) / double(n) - double(i) / double(n));
        const double total = cdf[n];
        for (double& c : cdf) c /= total;
        cdf[n] = 1.0;
        const Distribution1D d(values);
        std::vector<double> us = {0.0, 1.0};
        for (size_t k = 0; k <= n; ++k) {
            const double edge = double(k) / double(n);
            us.insert(us.end(), {edge, std::nextafter(edge, 0.0), std::nextafter(edge, 2.0)});
        }
        for (double c : cdf) us.insert(us.end(), {c, std::nextafter(c, 0.0), std::nextafter(c, 2.0)});
        for (int k = 0; k < 20000; ++k) us.push_back(rng.uniform());
        for (double u : us) {
            u = std::clamp(u, 0.0, 1.0);
            size_t expected = std::clamp<size_t>(size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin()), 1, n) - 1;
            while (cdf[expected + 1] - cdf[expected] == 0 && expected > 0) --expected;
            ASSERT_EQ(d.sampleDiscrete(u), expected) << n << " bins, u = " << u;
        }
    }
}

TEST(Distribution1D, AllZeroFallsBackToUniform) {
    const std::vector<double> values = {0, 0, 0, 0};
    Distribution1D d(values);
    EXPECT_TRUE(d.allZero());
    double pdf = 0;
    double x = d.sampleContinuous(0.6, &pdf);
    EXPECT_NEAR(x, 0.6, 1e-12);
    EXPECT_DOUBLE_EQ(pdf, 1.0);
    EXPECT_DOUBLE_EQ(d.pdf(0.1), 1.0);
}

TEST(Distribution1D, RejectsBadInput) {
    const std::vector<double> negative = {1, -1};
    EXPECT_THROW(Distribution1D{negative}, std::invalid_argument);
    const std::vector<double> values = {1, 1};
    const std::vector<double> edges = {0, 1, 1};
    EXPECT_THROW(Distribution1D(values, edges), std::invalid_argument);
}

TEST(Distribution2D, SamplesMatchCellPdfs) {
    const int nx = 7, ny = 5;
    std::vector<double> values(nx * ny);
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) values[iy * nx + ix] = (ix == 3 && iy == 2) ? 0.0 : 1.0 + ix * iy % 5;
    const std::vector<double> xe = {0, 1, 1.5, 2, 4, 4.5, 6, 7};
    const std::vector<double> ye = {-1, -0.2, 0, 0.1, 0.9, 1};
    Distribution2D d(values, xe, ye);
    std::vector<double> observed(nx * ny, 0), expected(nx * ny, 0);
    Rng rng(9);
    const int n = 200000;
    for (int k = 0; k < n; ++k) {
        auto s = d.sample({rng.uniform(), rng.uniform()});
        ASSERT_GT(s.pdf, 0);
        EXPECT_DOUBLE_EQ(s.pdf, d.pdf(s.p));
        EXPECT_GE(s.p.x, xe[s.ix]);
        EXPECT_LT(s.p.x, xe[s.ix + 1]);
        EXPECT_GE(s.p.y, ye[s.iy]);
        EXPECT_LT(s.p.y, ye[s.iy + 1]);
        observed[s.iy * nx + s.ix] += 1;
    }
    double total = 0;
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) {
            double area = (xe[ix + 1] - xe[ix]) * (ye[iy + 1] - ye[iy]);
            expected[iy * nx + ix] = d.cellPdf(ix, iy) * area * n;
            total += d.cellPdf(ix, iy) * area;
            EXPECT_NEAR(d.cellPdf(ix, iy), values[iy * nx + ix] / d.integral(), 1e-12);
        }
    EXPECT_NEAR(total, 1.0, 1e-12);
    EXPECT_EQ(observed[2 * nx + 3], 0);
    auto r = test::chi2Test(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

// Rows equal to the row before them (a sky map's ground half) share one distribution:
// every sample, pdf and cell pdf is bit for bit what a distribution of its own per row
// gives (the marginal and a Distribution1D of the chosen row, built afresh).
TEST(Distribution2D, RowsThatRepeatSampleAsTheirOwnWould) {
    const int nx = 9, ny = 8;
    std::vector<double> values(nx * ny);
    for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) values[iy * nx + ix] = iy < 3 ? 1.0 + (ix * (iy + 2)) % 7 : iy < 7 ? 0.75 : 2.0;
    std::vector<double> xe(nx + 1), ye(ny + 1);
    for (int ix = 0; ix <= nx; ++ix) xe[ix] = 0.3 * ix + 0.01 * ix * ix;
    for (int iy = 0; iy <= ny; ++iy) ye[iy] = -1 + 0.25 * iy;
    const Distribution2D d(values, xe, ye);
    ASSERT_EQ(d.ny(), size_t(ny));
    std::vector<double> rowIntegrals;
    std::vector<Distribution1D> rows;
    for (int iy = 0; iy < ny; ++iy) {
        rows.emplace_back(std::span<const double>(values).subspan(size_t(iy) * nx, nx), xe);
        rowIntegrals.push_back(rows.back().integral());
    }
    const Distribution1D marginal(rowIntegrals, ye);
    Rng rng(4);
    for (int k = 0; k < 20000; ++k) {
        const Vec2 u{rng.uniform(), rng.uniform()};
        const auto s = d.sample(u);
        double pdfY = 0, pdfX = 0;
        size_t iy = 0, ix = 0;
        const double y = marginal.sampleContinuous(u.y, &pdfY, &iy);
        const double x = rows[iy].sampleContinuous(u.x, &pdfX, &ix);
        ASSERT_EQ(s.iy, iy);
        ASSERT_EQ(s.ix, ix);
        ASSERT_EQ(s.p.x, x);
        ASSERT_EQ(s.p.y, y);
        ASSERT_EQ(s.pdf, pdfX * pdfY);
        ASSERT_EQ(d.cellPdf(ix, iy), marginal.binPdf(iy) * rows[iy].binPdf(ix));
        ASSERT_EQ(d.pdf(s.p), s.pdf);
    }
}

}  // namespace
}  // namespace luxplan
