// The GGX coat albedo table against its reference quadrature, an analytic value, and
// its cosine-weighted average; also holds the (disabled) generator of the table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <luxplan/core/rng.h>
#include <luxplan/materials/ggx_albedo.h>

namespace luxplan {
namespace {

// The quadrature's own accuracy, and that of the generated table's entries: the
// generator runs it at kGenerationTolerance and prints 8 decimals.
constexpr double kGenerationTolerance = 1e-6;
constexpr double kStoredEntryTolerance = 2 * kGenerationTolerance + 1e-8;

TEST(GgxAlbedoQuadrature, MatchesClosedFormAtAlphaOneNormalIncidence) {
    // alpha = 1: D = 1/pi, G2 = G1(wi) at normal incidence, and the F = 1 albedo is
    // int_0^{pi/4} 2 cos(2t) tan(t) dt = 1 - ln 2.
    GgxAlbedo e = ggxAlbedoQuadrature(1.0, 1.0, 1e-9);
    EXPECT_NEAR(e.scale + e.bias, 1 - std::log(2.0), 1e-8);
}

TEST(GgxAlbedoQuadrature, SmoothCoatReflectsSchlickFresnel) {
    // As alpha -> 0, masking vanishes and h -> n: E(mu) -> F(mu) = f0 + (1 - f0)(1 - mu)^5.
    for (double mu : {1.0, 0.7, 0.4}) {
        GgxAlbedo e = ggxAlbedoQuadrature(mu, kMinGgxAlpha, 1e-9);
        double w = std::pow(1 - mu, 5);
        // O(alpha^2) corrections from masking and from the spread of h.
        double tol = 10 * kMinGgxAlpha * kMinGgxAlpha + 1e-8;
        EXPECT_NEAR(e.scale, 1 - w, tol) << "mu " << mu;
        EXPECT_NEAR(e.bias, w, tol) << "mu " << mu;
    }
}

TEST(GgxAlbedoTable, StoredEntriesMatchQuadrature) {
    Rng rng(11);
    for (int k = 0; k < 24; ++k) {
        int row = int(rng.uniformInt(kGgxAlbedoAlphaCount)), col = int(rng.uniformInt(kGgxAlbedoCosCount));
        if (k == 0) row = 0, col = 0;
        if (k == 1) row = kGgxAlbedoAlphaCount - 1, col = kGgxAlbedoCosCount - 1;
        double mu = ggxAlbedoTableCos(col), alpha = ggxAlbedoTableAlpha(row);
        GgxAlbedo ref = ggxAlbedoQuadrature(mu, alpha, kGenerationTolerance);
        GgxAlbedo tab = ggxAlbedo(mu, alpha);
        EXPECT_NEAR(tab.scale, ref.scale, kStoredEntryTolerance) << "row " << row << " col " << col;
        EXPECT_NEAR(tab.bias, ref.bias, kStoredEntryTolerance) << "row " << row << " col " << col;
    }
}

TEST(GgxAlbedoTable, InterpolationErrorWithinDocumentedBound) {
    // Off-grid points, half of them log-distributed towards grazing angles and small alpha
    // where E varies fastest. Both terms at f0 = 0 and f0 = 1 are checked.
    Rng rng(12);
    double worst = 0;
    for (int k = 0; k < 120; ++k) {
        double mu = k % 2 ? rng.uniform() : std::pow(10.0, -4 * rng.uniform());
        double alpha = k % 3 ? kMinGgxAlpha * std::pow(1 / kMinGgxAlpha, rng.uniform())
                             : kMinGgxAlpha + (1 - kMinGgxAlpha) * rng.uniform();
        GgxAlbedo ref = ggxAlbedoQuadrature(mu, alpha, kGenerationTolerance);
        GgxAlbedo tab = ggxAlbedo(mu, alpha);
        for (double f0 : {0.0, 1.0}) {
            double err = std::abs(tab.with(f0) - ref.with(f0));
            worst = std::max(worst, err);
            EXPECT_LE(err, kGgxAlbedoTableError) << "mu " << mu << " alpha " << alpha << " f0 " << f0;
        }
    }
    std::printf("worst table error %.2e (bound %.1e)\n", worst, kGgxAlbedoTableError);
}

TEST(GgxAlbedoTable, AlbedoIsAFraction) {
    for (int row = 0; row < kGgxAlbedoAlphaCount; ++row)
        for (int col = 0; col < kGgxAlbedoCosCount; ++col) {
            GgxAlbedo e = ggxAlbedo(ggxAlbedoTableCos(col), ggxAlbedoTableAlpha(row));
            ASSERT_GE(e.scale, 0);
            ASSERT_GE(e.bias, 0);
            ASSERT_LE(e.scale + e.bias, 1 + kStoredEntryTolerance) << "row " << row << " col " << col;
        }
}

TEST(GgxAlbedoTable, AverageIsTheCosineWeightedIntegralOfTheLookup) {
    for (double alpha : {kMinGgxAlpha, 0.0123, 0.1, 0.37, 0.8, 1.0}) {
        GgxAlbedoRow row = ggxAlbedoRow(alpha);
        // Midpoint rule in the table's own dense-at-grazing coordinate would be ideal; a fine
        // midpoint rule in mu^2 (d(mu^2) = 2 mu dmu) is accurate to ~1e-7 here.
        const int n = 200000;
        double scale = 0, bias = 0;
        for (int i = 0; i < n; ++i) {
            double mu = std::sqrt((i + 0.5) / n);
            GgxAlbedo e = ggxAlbedo(mu, row);
            scale += e.scale;
            bias += e.bias;
        }
        GgxAlbedo avg = ggxAverageAlbedo(row);
        EXPECT_NEAR(avg.scale, scale / n, 1e-6) << "alpha " << alpha;
        EXPECT_NEAR(avg.bias, bias / n, 1e-6) << "alpha " << alpha;
    }
}

TEST(GgxAlbedoTable, GridEndsAtTheDomainEnds) {
    EXPECT_EQ(ggxAlbedoTableCos(0), 0.0);
    EXPECT_EQ(ggxAlbedoTableCos(kGgxAlbedoCosCount - 1), 1.0);
    EXPECT_NEAR(ggxAlbedoTableAlpha(0), kMinGgxAlpha, 1e-15);
    EXPECT_EQ(ggxAlbedoTableAlpha(kGgxAlbedoAlphaCount - 1), 1.0);
    for (int i = 1; i < kGgxAlbedoCosCount; ++i) EXPECT_LT(ggxAlbedoTableCos(i - 1), ggxAlbedoTableCos(i));
    for (int j = 1; j < kGgxAlbedoAlphaCount; ++j) EXPECT_LT(ggxAlbedoTableAlpha(j - 1), ggxAlbedoTableAlpha(j));
}

// Writes src/luxplan/materials/ggx_albedo_table.inc (or $LUXPLAN_GGX_TABLE_OUT). Run with
//   test_materials --gtest_also_run_disabled_tests --gtest_filter='*Regenerate*'
// after changing the model or the grid, then rebuild (about a minute, single-threaded).
TEST(GgxAlbedoTable, DISABLED_Regenerate) {
    const char* env = std::getenv("LUXPLAN_GGX_TABLE_OUT");
    std::string path = env ? env : std::string(LUXPLAN_SOURCE_DIR) + "/src/luxplan/materials/ggx_albedo_table.inc";
    std::ofstream out(path);
    ASSERT_TRUE(out) << path;
    out << "// Generated by tests/materials/ggx_albedo_test.cpp (GgxAlbedoTable.DISABLED_Regenerate); do not edit.\n"
        << "// {scale, bias} = ggxAlbedoQuadrature(ggxAlbedoTableCos(i), ggxAlbedoTableAlpha(j), 1e-6) at [j][i].\n"
        << "constexpr double kGgxAlbedoTable[kGgxAlbedoAlphaCount][kGgxAlbedoCosCount][2] = {\n";
    char buf[64];
    for (int j = 0; j < kGgxAlbedoAlphaCount; ++j) {
        double alpha = ggxAlbedoTableAlpha(j);
        out << "    {  // alpha " << alpha << "\n";
        for (int i = 0; i < kGgxAlbedoCosCount; ++i) {
            GgxAlbedo e = ggxAlbedoQuadrature(ggxAlbedoTableCos(i), alpha, kGenerationTolerance);
            std::snprintf(buf, sizeof buf, "{%.8f, %.8f},", e.scale, e.bias);
            out << (i % 4 == 0 ? "        " : " ") << buf << (i % 4 == 3 || i + 1 == kGgxAlbedoCosCount ? "\n" : "");
        }
        out << "    },\n";
    }
    out << "};\n";
}

}  // namespace
}  // namespace luxplan
