// The scrambled Sobol pairs (core/low_discrepancy.h): Owen scrambling is a
// permutation; the first 2^m points of a scrambled pair put one point in every
// elementary interval of area 2^-m (the (0,m,2)-net property survives scrambling
// and index shuffling); every point is uniform over seeds (chi-square); and
// different pairs of one sequence are independent.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include <luxplan/core/low_discrepancy.h>

namespace luxplan {
namespace {

// sobolPair leaves out the bit reversals that undo one another: it must give exactly
// the composition it stands for, and the paths' 1D numbers its first coordinate.
TEST(LowDiscrepancy, TheShortcutPairIsTheScrambledSobolPair) {
    for (uint32_t i : {0u, 1u, 5u, 255u, 1000u, 65537u, 0x89abcdefu, 0xffffffffu})
        for (uint32_t pair : {0u, 3u, 17u}) {
            const PairScramble s(0x5eed, pair);
            const uint32_t shuffled = owenScramble(i, s.shuffle);
            const Vec2 p = sobolPair(s, i);
            EXPECT_EQ(p.x, toUnit(owenScramble(sobol0(shuffled), s.x))) << i;
            EXPECT_EQ(p.y, toUnit(owenScramble(sobol1(shuffled), s.y))) << i;
            EXPECT_EQ(sobolPairX(s, shuffledIndex(s, reverseBits(i))), p.x) << i;
            EXPECT_EQ(sobol1Reversed(i), reverseBits(sobol1(i))) << i;
        }
}

TEST(LowDiscrepancy, OwenScrambleIsAPermutation) {
    // On the top 16 bits (the scramble keeps the order of the lower bits' influence):
    // 2^16 distinct inputs give 2^16 distinct outputs.
    std::set<uint32_t> seen;
    for (uint32_t i = 0; i < (1u << 16); ++i) seen.insert(owenScramble(i << 16, 0x1234567u));
    EXPECT_EQ(seen.size(), size_t(1) << 16);
    EXPECT_EQ(reverseBits(1u), 1u << 31);
    EXPECT_EQ(sobol1(1), 1u << 31);
    EXPECT_EQ(sobol1(2), 3u << 30);
    // The table against the bit loop that defines it.
    for (uint32_t i : {0u, 1u, 3u, 255u, 256u, 65537u, 0x89abcdefu, 0xffffffffu}) {
        uint32_t r = 0, x = i;
        for (uint32_t v = 1u << 31; x; x >>= 1, v ^= v >> 1)
            if (x & 1) r ^= v;
        EXPECT_EQ(sobol1(i), r) << i;
    }
}

TEST(LowDiscrepancy, EveryElementaryIntervalHoldsOnePoint) {
    for (uint64_t sequence : {1ull, 77ull, 123456789ull})
        for (uint32_t pair : {0u, 5u, 13u}) {
            const int m = 8;
            std::vector<Vec2> points;
            for (uint32_t i = 0; i < (1u << m); ++i) points.push_back(sobolPair(sequence, i, pair));
            for (int a = 0; a <= m; ++a) {
                const int nx = 1 << a, ny = 1 << (m - a);
                std::vector<int> count(size_t(nx * ny), 0);
                for (const Vec2& p : points) ++count[size_t(int(p.x * nx) * ny + int(p.y * ny))];
                for (int c : count) ASSERT_EQ(c, 1) << "sequence " << sequence << " pair " << pair << " intervals " << nx << "x" << ny;
            }
        }
}

// Pearson's chi-square of counts against a uniform expectation.
double chiSquare(const std::vector<int>& counts, double expected) {
    double x2 = 0;
    for (int c : counts) x2 += (c - expected) * (c - expected) / expected;
    return x2;
}

TEST(LowDiscrepancy, EachPointIsUniformOverSeeds) {
    // Point 5 of pair 3 over 64000 sequences on a 16 x 16 grid: chi-square with 255
    // degrees of freedom; its 99.9% quantile is about 330.
    const int n = 64000, cells = 16;
    std::vector<int> counts(cells * cells, 0);
    for (int s = 0; s < n; ++s) {
        Vec2 p = sobolPair(uint64_t(s), 5, 3);
        ASSERT_GE(p.x, 0);
        ASSERT_LT(p.x, 1);
        ++counts[size_t(int(p.x * cells) * cells + int(p.y * cells))];
    }
    EXPECT_LT(chiSquare(counts, double(n) / (cells * cells)), 330);
}

TEST(LowDiscrepancy, PairsOfOneSequenceAreIndependent) {
    // The x of pair 0 against the x of pair 1 for the first 4096 points: a 16 x 16
    // contingency table, uniform if the pairs' shuffles are independent.
    const int n = 4096, cells = 16;
    std::vector<int> counts(cells * cells, 0);
    for (uint32_t i = 0; i < uint32_t(n); ++i)
        ++counts[size_t(int(sobolPair(9, i, 0).x * cells) * cells + int(sobolPair(9, i, 1).x * cells))];
    EXPECT_LT(chiSquare(counts, double(n) / (cells * cells)), 330);
}

}  // namespace
}  // namespace luxplan
