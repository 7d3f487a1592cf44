// Low-discrepancy points for path sampling: the first two dimensions of the Sobol
// sequence (a (0,2)-sequence in base 2: every 2^m consecutive points from index 0
// put one point in each of 2^m equal rectangles of any shape), randomized by
// hash-based Owen scrambling (Burley 2020, "Practical Hash-based Owen Scrambling",
// after Laine and Karras 2011), which keeps that stratification and makes every point
// uniform on its own: estimates stay unbiased. Higher dimensions are "padded": each
// pair of dimensions gets its own shuffle of the point index and its own scramble
// (pbrt-v4's PaddedSobolSampler does the same), so pairs are independent of each
// other and each is well stratified.
#pragma once

#include <cstdint>

#include <luxplan/core/math.h>
#include <luxplan/core/rng.h>

namespace luxplan {

constexpr uint32_t reverseBits(uint32_t x) {
    x = ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
    x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
    x = ((x & 0x00ff00ffu) << 8) | ((x >> 8) & 0x00ff00ffu);
    return (x << 16) | (x >> 16);
}

// Laine-Karras's mixing, on a value with its bits reversed: each step only mixes lower
// bits into higher ones (reversed order).
constexpr uint32_t laineKarras(uint32_t reversed, uint32_t seed) {
    uint32_t x = reversed + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// A random permutation of [0, 2^32) that is a nested uniform scramble in base 2: bit k
// of the result is bit k of the input flipped by a hash of the bits above it.
constexpr uint32_t owenScramble(uint32_t x, uint32_t seed) { return reverseBits(laineKarras(reverseBits(x), seed)); }

// Sobol dimensions 0 (van der Corput) and 1, as 32-bit fractions.
constexpr uint32_t sobol0(uint32_t i) { return reverseBits(i); }
// Dimension 1: bit k of the index adds direction number v_k (v_0 = 2^31,
// v_{k+1} = v_k ^ (v_k >> 1)), by bytes from a table.
// `reversed` holds the same with each direction number's bits reversed, so that
// reverseBits(sobol1(i)) == sobol1Reversed(i) (reversal is linear over XOR).
struct Sobol1Table {
    uint32_t bytes[4][256] = {}, reversed[4][256] = {};
    constexpr Sobol1Table() {
        uint32_t v[32] = {};
        v[0] = 1u << 31;
        for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
        for (int b = 0; b < 4; ++b)
            for (uint32_t x = 0; x < 256; ++x)
                for (int j = 0; j < 8; ++j)
                    if (x & (1u << j)) {
                        bytes[b][x] ^= v[8 * b + j];
                        reversed[b][x] ^= reverseBits(v[8 * b + j]);
                    }
    }
};
inline constexpr Sobol1Table kSobol1;
constexpr uint32_t sobol1(uint32_t i) {
    return kSobol1.bytes[0][i & 255] ^ kSobol1.bytes[1][(i >> 8) & 255] ^ kSobol1.bytes[2][(i >> 16) & 255] ^
           kSobol1.bytes[3][i >> 24];
}
constexpr uint32_t sobol1Reversed(uint32_t i) {
    return kSobol1.reversed[0][i & 255] ^ kSobol1.reversed[1][(i >> 8) & 255] ^ kSobol1.reversed[2][(i >> 16) & 255] ^
           kSobol1.reversed[3][i >> 24];
}

// 32-bit fraction to [0, 1).
constexpr double toUnit(uint32_t x) { return double(x) * (1.0 / 4294967296.0); }

// The scramble of one dimension pair of one sequence: an index shuffle and a scramble
// per coordinate, from a hash of (sequence, pair). Computed once per sampler point.
struct PairScramble {
    uint32_t shuffle = 0, x = 0, y = 0;
    PairScramble() = default;
    PairScramble(uint64_t sequence, uint32_t pair) {
        const uint64_t h = hashValues({sequence, pair});
        shuffle = uint32_t(h), x = uint32_t(h >> 32), y = uint32_t(mixBits(h) >> 32);
    }
};

// Point `index` of a scrambled pair: owenScramble(sobol0(shuffled), s.x) and
// owenScramble(sobol1(shuffled), s.y) for shuffled = owenScramble(index, s.shuffle),
// without the bit reversals that undo one another. A path's pairs share one index,
// so it comes reversed (reverseBits(index)).
inline uint32_t shuffledIndex(const PairScramble& s, uint32_t reversedIndex) {
    return reverseBits(laineKarras(reversedIndex, s.shuffle));
}
inline double sobolPairX(const PairScramble& s, uint32_t shuffled) { return toUnit(reverseBits(laineKarras(shuffled, s.x))); }
inline Vec2 sobolPairReversed(const PairScramble& s, uint32_t reversedIndex) {
    const uint32_t shuffled = shuffledIndex(s, reversedIndex);
    return {sobolPairX(s, shuffled), toUnit(reverseBits(laineKarras(sobol1Reversed(shuffled), s.y)))};
}
inline Vec2 sobolPair(const PairScramble& s, uint32_t index) { return sobolPairReversed(s, reverseBits(index)); }

// Point `index` of the padded, scrambled sequence `sequence`, in dimension pair `pair`.
inline Vec2 sobolPair(uint64_t sequence, uint32_t index, uint32_t pair) { return sobolPair(PairScramble(sequence, pair), index); }

}  // namespace luxplan
