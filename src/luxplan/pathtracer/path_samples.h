// The random numbers of one path, named by what they are for. With a sequence (the
// default for light samplers, MeasureOptions::lowDiscrepancy), the paths of one
// sampler point in one fold are consecutive points of a padded, Owen-scrambled Sobol
// sequence (core/low_discrepancy.h): at each of the first kDepths vertices every use
// (the emitter choice, the point on it, the sun, the sky, the sunlit patch, the next
// direction, the BSDF lobe, roulette) has a dimension pair of its own, so that across the paths each is
// stratified. Everything else (later vertices, glass coins), and every number when no
// sequence is given, comes from the path's PCG stream. Each path's numbers are
// uniform whatever the layout: estimates stay unbiased.
#pragma once

#include <array>
#include <cstdint>

#include <luxplan/core/low_discrepancy.h>
#include <luxplan/core/rng.h>

namespace luxplan {

class PathSamples {
public:
    enum Slot : uint32_t {
        EmitterChoice, EmitterPoint, SunDisk, SunPoint, SkyPoint, PatchSunDisk, PatchSunPoint, PatchEntry,
        Lobe, Direction, Roulette, kSlots
    };
    static constexpr int kDepths = 2;

    // One sequence's scrambles, shared by the paths of a sampler point.
    struct Sequence {
        std::array<PairScramble, kDepths * kSlots> pairs;
        explicit Sequence(uint64_t key) {
            for (uint32_t p = 0; p < pairs.size(); ++p) pairs[p] = PairScramble(key, p);
        }
    };

    // Pseudo-random only.
    explicit PathSamples(Rng& rng) : rng_(rng) {}
    // Point `index` of `sequence` for the first vertices.
    PathSamples(Rng& rng, const Sequence& sequence, uint32_t index)
        : rng_(rng), sequence_(&sequence), reversedIndex_(reverseBits(index)) {}

    void setDepth(int depth) { depth_ = depth; }
    double get1D(Slot slot) {
        if (!fromSequence()) return rng_.uniform();
        const PairScramble& s = sequence_->pairs[pair(slot)];
        return sobolPairX(s, shuffledIndex(s, reversedIndex_));
    }
    Vec2 get2D(Slot slot) {
        if (fromSequence()) return sobolPairReversed(sequence_->pairs[pair(slot)], reversedIndex_);
        double u = rng_.uniform();
        return {u, rng_.uniform()};
    }
    // For numbers outside the layout (glass coins, the light samples' roulette).
    Rng& rng() { return rng_; }

private:
    bool fromSequence() const { return sequence_ && depth_ < kDepths; }
    uint32_t pair(Slot slot) const { return uint32_t(depth_) * kSlots + slot; }

    Rng& rng_;
    const Sequence* sequence_ = nullptr;
    uint32_t reversedIndex_ = 0;  // the point's index, bits reversed (low_discrepancy.h)
    int depth_ = 0;
};

}  // namespace luxplan
