// The random numbers of one path, named by what they are for. With a sequence (the
// default for light samplers, MeasureOptions::lowDiscrepancy), the paths of one
// sampler point in one fold are consecutive points of a padded, Owen-scrambled Sobol
// sequence (core/low_discrepancy.h): at each of the first kDepths vertices every use
// (the emitter choice, the point on it, the sun, the sky, the next direction, the BSDF
// lobe, roulette) has a dimension pair of its own, so that across the paths each is
// stratified. Everything else (later vertices, glass coins), and every number when no
// sequence is given, comes from the path's PCG stream. Each path's numbers are
// uniform whatever the layout: estimates stay unbiased.
#pragma once

#include <cstdint>

#include <luxplan/core/low_discrepancy.h>
#include <luxplan/core/rng.h>

namespace luxplan {

class PathSamples {
public:
    enum Slot : uint32_t { EmitterChoice, EmitterPoint, SunDisk, SunPoint, SkyPoint, Lobe, Direction, Roulette, kSlots };
    static constexpr int kDepths = 2;

    // Pseudo-random only.
    explicit PathSamples(Rng& rng) : rng_(rng) {}
    // Point `index` of sequence `sequence` for the first vertices.
    PathSamples(Rng& rng, uint64_t sequence, uint32_t index) : rng_(rng), sequence_(sequence), index_(index), qmc_(true) {}

    void setDepth(int depth) { depth_ = depth; }
    double get1D(Slot slot) { return fromSequence() ? sobolPair(sequence_, index_, pair(slot)).x : rng_.uniform(); }
    Vec2 get2D(Slot slot) {
        if (fromSequence()) return sobolPair(sequence_, index_, pair(slot));
        double u = rng_.uniform();
        return {u, rng_.uniform()};
    }
    // For numbers outside the layout (glass coins).
    Rng& rng() { return rng_; }

private:
    bool fromSequence() const { return qmc_ && depth_ < kDepths; }
    uint32_t pair(Slot slot) const { return uint32_t(depth_) * kSlots + slot; }

    Rng& rng_;
    uint64_t sequence_ = 0;
    uint32_t index_ = 0;
    bool qmc_ = false;
    int depth_ = 0;
};

}  // namespace luxplan
