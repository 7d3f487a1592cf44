// Deterministic random streams. Every stream is seeded from a hash of what it
// is for (seed, sampler, point, path), never from a thread id, so results do not
// depend on the thread count.
#pragma once

#include <cstdint>
#include <initializer_list>

namespace luxplan {

// SplitMix64 finalizer: a strong 64-bit mixing function.
constexpr uint64_t mixBits(uint64_t v) {
    v ^= v >> 30; v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27; v *= 0x94d049bb133111ebULL;
    v ^= v >> 31;
    return v;
}

// Order-dependent hash of a list of integers (seed, ids, indices).
constexpr uint64_t hashValues(std::initializer_list<uint64_t> values) {
    uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (uint64_t v : values) h = mixBits(h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
    return h;
}

// PCG32 (O'Neill 2014, https://www.pcg-random.org): small state, good statistics.
class Rng {
public:
    Rng() { setSequence(0, 0); }
    explicit Rng(uint64_t seed, uint64_t stream = 0) { setSequence(seed, stream); }

    void setSequence(uint64_t seed, uint64_t stream) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        nextU32();
        state_ += mixBits(seed);
        nextU32();
    }
    uint32_t nextU32() {
        uint64_t old = state_;
        state_ = old * 0x5851f42d4c957f2dULL + inc_;
        uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
    }
    // Uniform in [0, 1), 53 random bits from two draws.
    double uniform() {
        uint64_t hi = nextU32() >> 5, lo = nextU32() >> 6;
        return (double(hi) * 67108864.0 + double(lo)) * (1.0 / 9007199254740992.0);
    }
    // Uniform integer in [0, n), unbiased (Lemire's rejection).
    uint32_t uniformInt(uint32_t n) {
        uint32_t threshold = (~n + 1u) % n;
        for (;;) {
            uint32_t r = nextU32();
            if (r >= threshold) return r % n;
        }
    }

private:
    uint64_t state_ = 0, inc_ = 1;
};

}  // namespace luxplan
