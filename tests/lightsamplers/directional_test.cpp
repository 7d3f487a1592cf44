// The directional sampler against truth: a sun or a lamp in view read at their
// stratum's luminance (light sampling at the eye), a uniform sky at its luminance in
// every stratum, and a brightest-stratum value that does not read high with few paths
// (cross-fitted choice), with an error that covers it.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;
using test::kZ;

// The plane-area of one of strata x strata cells at unit distance.
double cellArea(double fovDeg, int strata) {
    double side = 2 * std::tan(radians(fovDeg) / 2) / strata;
    return side * side;
}

// A black room with a wide south opening and the sun at 30 deg altitude due south,
// alone in a black sky.
SceneBuilder sunRoom(double normalLx) {
    SceneBuilder b;
    b.material("black", test::diffuse(0)).sunAndUniformSky({30, 180, normalLx}, 0).room({0, 0, 0}, {6, 6, 3}, "black", "black", "black");
    b.window(Wall::South, 1, 4, 0.3, 2.5);
    return b;
}

TEST(Directional, SunInViewReadsItsStratumLuminance) {
    const double En = 60000, fov = 20;
    const int strata = 5;  // odd: the sun sits in the middle of the centre stratum
    const Vec3 toSun = normalize(Vec3(0, -std::cos(radians(30)), std::sin(radians(30))));
    SceneLab lab(sunRoom(En).sampler("sun", directionalSampler({3, 2, 0.8}, toSun, kZ, fov, strata), 0, 100).build());
    ASSERT_TRUE(lab.daylight && lab.daylight->hasSun());
    const Vec3 sun = lab.daylight->sunDisks()[0].direction;
    ASSERT_GT(dot(sun, toSun), std::cos(radians(0.1)));
    SamplerResult r = lab.measure(1000).samplers[0];
    // The disk lies inside one cell on the axis (cos = 1): its mean over the cell's
    // plane area is E_n / A_cell.
    const double expected = En / cellArea(fov, strata);
    const int centre = (strata / 2) * strata + strata / 2;
    EXPECT_NEAR(r.points[size_t(centre)], expected, 4 * r.pointErrors[size_t(centre)] + 0.01 * expected);
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 0.01 * expected);
    for (int i = 0; i < strata * strata; ++i) {
        if (i == centre) continue;
        EXPECT_EQ(r.points[size_t(i)], 0.0) << "stratum " << i;
    }
    // Light sampling finds the sun on every path: even 16 paths read it closely.
    EXPECT_NEAR(lab.measure(16, 5).samplers[0].value, expected, 0.03 * expected);
}

TEST(Directional, LampInViewReadsItsStratumLuminance) {
    // A 1000 lm sphere of radius 2 cm, 2 m ahead on the axis of a black void: intensity
    // 1000 / 4 pi cd, so the centre cell's mean is I / (d^2 A_cell).
    const double flux = 1000, d = 2, fov = 30;
    const int strata = 3;
    SceneLab lab(SceneBuilder()
                     .emitter("bulb", sphereEmitter({0, d, 0}, 0.02), flux)
                     .sampler("lamp", directionalSampler({0, 0, 0}, {0, 1, 0}, kZ, fov, strata), 0, 100)
                     .build());
    SamplerResult r = lab.measure(1000).samplers[0];
    const double expected = flux / (4 * kPi) / (d * d) / cellArea(fov, strata);
    EXPECT_NEAR(r.points[4], expected, 4 * r.pointErrors[4] + 0.01 * expected);
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 0.01 * expected);
}

// Adaptive measurement drops the strata that cannot hold the max (successive
// elimination): the dark ones stop at the first look, the lamp's runs on, and
// the value is still the lamp's stratum luminance.
TEST(Directional, AdaptiveMeasurementDropsStrataThatCannotHoldTheMax) {
    const double flux = 1000, d = 2, fov = 30;
    const int strata = 3;
    const double expected = flux / (4 * kPi) / (d * d) / cellArea(fov, strata);
    SceneLab lab(SceneBuilder()
                     .emitter("bulb", sphereEmitter({0, d, 0}, 0.02), flux)
                     .sampler("lamp", directionalSampler({0, 0, 0}, {0, 1, 0}, kZ, fov, strata), expected, kInf, 0.1 * expected)
                     .build());
    MeasureOptions o;
    o.pathsPerPoint = 1000, o.adaptive = true;
    MeasureResult m = measureSamplers(*lab.tracer, o);
    const SamplerResult& r = m.samplers[0];
    const int firstLook = o.minPaths;  // a whole number of rounds
    ASSERT_EQ(firstLook % o.batchPaths, 0);
    // The lamp's stratum sits on its band's edge, within the 1% that the sphere's size
    // puts between its luminance and I / (d^2 A): it runs on for many rounds (where it
    // stops depends on the paths' numbers), the eight dark ones stop at the first look.
    EXPECT_GE(r.pathsPerPoint, 4 * firstLook);
    EXPECT_EQ(m.paths, uint64_t(r.pathsPerPoint + 8 * firstLook));
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 0.01 * expected);
}

// Four strata's estimates, each fold holding the same two paths of its stratum.
ItemEstimates fourStrata(const double (&paths)[4][2]) {
    ItemEstimates e(4, 1);
    for (int i = 0; i < 4; ++i)
        for (int g = 0; g < ItemEstimates::kFolds; ++g)
            for (double v : paths[i]) e.cell(i, 0, g).add(v);
    return e;
}

// Which strata a look leaves with paths to trace: those that may hold the max
// (successive elimination) and, where the band starts at 0, may decide which side of
// its top the max is on; the others below the top pause (they catch up before the max
// settles below it).
TEST(Directional, AdaptiveMeasurementDropsStrataThatCannotLiftTheMaxAboveTheBand) {
    auto placed = directionalSampler({0, 0, 0}, {0, 1, 0}, kZ, 60, 2)->place(Transform());
    ASSERT_EQ(placed->items(), 4);
    // Two paths a fold: a noisy bright stratum (150, its upper end far above 100), two
    // precise ones near 80 and a dark one.
    const ItemEstimates e = fourStrata({{0, 300}, {75, 85}, {10, 12}, {70, 90}});
    const double z = 3;
    auto upper = [&](int i) { return e.of(i).value + z * e.of(i).standardError; };
    ASSERT_GT(upper(0), 100);
    ASSERT_LT(upper(1), 100);
    ASSERT_LT(upper(3), 100);
    const std::vector<char> band = placed->stillNeeded(e, z, 0, 100);
    EXPECT_EQ(band, (std::vector<char>{kMorePaths, kPaused, kNoMorePaths, kPaused}));
    // Every upper end below the top (a [0, 1000] band), a band that starts above 0, or
    // none: successive elimination alone, which drops only the dark stratum.
    for (auto [lo, hi] : {std::pair{0.0, 1000.0}, std::pair{50.0, 100.0}, std::pair{-kInf, kInf}})
        EXPECT_EQ(placed->stillNeeded(e, z, lo, hi), (std::vector<char>{1, 1, 0, 1})) << lo << " " << hi;
}

// Above the top, the best stratum alone is traced on; the others, which may still hold
// the max, pause. Three near-equal bright strata (150, two paths a fold) and a dark one.
TEST(Directional, AboveTheTopOnlyTheBestStratumIsTracedOn) {
    auto placed = directionalSampler({0, 0, 0}, {0, 1, 0}, kZ, 60, 2)->place(Transform());
    const ItemEstimates e = fourStrata({{0, 300}, {50, 250}, {100, 200}, {10, 12}});
    const double z = 3;
    auto count = [](const std::vector<char>& need, char kind) { return std::count(need.begin(), need.end(), kind); };
    const std::vector<char> focus = placed->stillNeeded(e, z, 0, 100);
    EXPECT_EQ(count(focus, kMorePaths), 1);
    EXPECT_EQ(count(focus, kPaused), 2);
    EXPECT_EQ(focus[3], kNoMorePaths);
    // A top above every mean, or a band that starts above 0: successive elimination alone.
    EXPECT_EQ(placed->stillNeeded(e, z, 0, 160), (std::vector<char>{1, 1, 1, 0}));
    EXPECT_EQ(placed->stillNeeded(e, z, 50, 100), (std::vector<char>{1, 1, 1, 0}));
}

// The max is at least every stratum's own lower end: the brightest stratum's bounds it
// from below, and the other strata's upper ends from above.
TEST(Directional, EveryStratumBoundsTheMaxFromBelow) {
    auto placed = directionalSampler({0, 0, 0}, {0, 1, 0}, kZ, 60, 2)->place(Transform());
    const ItemEstimates e = fourStrata({{140, 160}, {0, 300}, {10, 12}, {70, 90}});
    const double z = 3;
    double lowest = -kInf, highest = -kInf;
    for (int i = 0; i < 4; ++i) {
        lowest = std::max(lowest, e.of(i).value - z * e.of(i).standardError);
        highest = std::max(highest, e.of(i).value + z * e.of(i).standardError);
    }
    EXPECT_EQ(placed->lowerEnd(e, z), lowest);
    EXPECT_EQ(placed->upperEnd(e, z), highest);
    EXPECT_EQ(lowest, e.of(0).value - z * e.of(0).standardError);  // the precise bright one, not the noisy one
    EXPECT_GT(lowest, 100);
}

TEST(Directional, UniformSkyThroughAnOpeningReadsItsLuminanceInEveryStratum) {
    const double L = 3000;
    SceneLab lab(SceneBuilder()
                     .material("grey", test::diffuse(0.5))
                     .uniformSky(L)
                     .room({0, 0, 0}, {6, 6, 3}, "grey", "grey", "grey")
                     .window(Wall::South, 0.5, 5, 0.2, 2.7)
                     .sampler("sky", directionalSampler({3, 1, 1.5}, {0, -1, 0.5}, kZ, 30, 4), 0, 100)
                     .build());
    SamplerResult r = lab.measure(64).samplers[0];
    for (size_t i = 0; i < r.points.size(); ++i)
        EXPECT_NEAR(r.points[i], L, 4 * r.pointErrors[i] + 1e-3 * L) << "stratum " << i;
    EXPECT_NEAR(r.value, L, 4 * r.standardError + 1e-3 * L);
    EXPECT_NEAR(lab.measure(16, 3).samplers[0].value, L, 0.01 * L);
}

// A wall lit by a window under an overcast sky, seen through 8 x 8 strata of
// near-equal luminance.
Scene litWall() {
    return SceneBuilder()
        .material("wall", test::diffuse(0.6))
        .material("floor", test::diffuse(0.3))
        .overcastSky(10000)
        .room({0, 0, 0}, {5, 5, 3}, "floor", "wall", "wall")
        .window(Wall::South, 0.5, 1.5, 0.9, 1.4)
        .sampler("wall", directionalSampler({2.5, 2.5, 1.2}, {1, 0, 0}, kZ, 60, 8), 0, 100)
        .build();
}

// A wall lit by a window, strata of near-equal luminance: the plain max over 8 x 8
// noisy strata read 19% high at 32 paths here. The cross-fitted value must not read
// high on average, and its error must cover its spread over seeds.
TEST(Directional, FewPathsDoNotReadHighOnALitWall) {
    const SceneLab lab(litWall());
    const SamplerResult converged = lab.measure(2000).samplers[0];
    const int seeds = 12;
    double sum = 0, sumSquares = 0, reported = 0;
    for (int s = 0; s < seeds; ++s) {
        SamplerResult r = lab.measure(32, 100 + s).samplers[0];
        sum += r.value, sumSquares += r.value * r.value, reported += r.standardError;
    }
    const double mean = sum / seeds, sd = std::sqrt(std::max(0.0, sumSquares / seeds - mean * mean) * seeds / (seeds - 1));
    const double truth = converged.value;
    EXPECT_LT(mean, truth + 3 * sd / std::sqrt(double(seeds)) + 3 * converged.standardError) << "reads high";
    EXPECT_GT(mean, 0.85 * truth) << "falls far short";
    EXPECT_GT(reported / seeds, 0.5 * sd) << "the error misses the spread over seeds";
}

// The same wall: its five brightest strata lie within a few percent, so the folds'
// choices, made from data they mostly share, move together from run to run. The spread
// of the fold values alone then reads short of the value's spread over seeds; the error
// reported (a bootstrap of the whole cross-fitted estimate) must cover it, and not by
// much more.
TEST(Directional, TheReportedErrorCoversTheChoiceAmongNearEqualStrata) {
    const SceneLab lab(litWall());
    const int seeds = 60;
    double sum = 0, sumSquares = 0, reported = 0, foldsOnly = 0;
    for (int s = 0; s < seeds; ++s) {
        MeasureOptions o;
        o.pathsPerPoint = 64, o.seed = uint64_t(300 + s);
        const SamplerResult r = lab.measure(o).samplers[0];
        o.choiceError = false;
        const SamplerResult plain = lab.measure(o).samplers[0];
        ASSERT_EQ(r.value, plain.value) << "the error alone differs";
        sum += r.value, sumSquares += r.value * r.value;
        reported += r.standardError * r.standardError, foldsOnly += plain.standardError * plain.standardError;
    }
    const double mean = sum / seeds, sd = std::sqrt(std::max(0.0, sumSquares / seeds - mean * mean) * seeds / (seeds - 1));
    const double rms = std::sqrt(reported / seeds), foldsRms = std::sqrt(foldsOnly / seeds);
    // The spread over 60 seeds is itself known to about 9%.
    EXPECT_GT(rms, 0.8 * sd) << "the error misses the spread over seeds";
    EXPECT_LT(rms, 1.35 * sd) << "the error is far wider than the spread over seeds";
    EXPECT_LT(foldsRms, 0.8 * sd) << "the fold values' spread no longer misses the choice here: the test shows nothing";

    // At 16 paths per stratum (two per fold), each value's distance from the converged
    // one in its own reported errors: the fold values' spread put 11 of 60 beyond 3.
    const double converged = lab.measure(2000).samplers[0].value;
    double zSquares = 0;
    int beyond = 0;
    for (int s = 0; s < seeds; ++s) {
        const SamplerResult r = lab.measure(16, uint64_t(500 + s)).samplers[0];
        const double z = (r.value - converged) / r.standardError;
        zSquares += z * z, beyond += std::abs(z) > 3;
    }
    EXPECT_LT(std::sqrt(zSquares / seeds), 1.4) << "the error at 16 paths is far below the distance to the truth";
    EXPECT_LE(beyond, 2) << "of " << seeds << " values beyond 3 of their errors at 16 paths";
}

// One stratum far brighter than the rest (the sun in view): nothing to choose, and the
// error reported is the fold values' spread within the bootstrap's own error.
TEST(Directional, TheReportedErrorIsTheFoldSpreadWhereOneStratumStandsOut) {
    const Vec3 toSun = normalize(Vec3(0, -std::cos(radians(30)), std::sin(radians(30))));
    SceneLab lab(sunRoom(60000).sampler("sun", directionalSampler({3, 2, 0.8}, toSun, kZ, 20, 5), 0, 100).build());
    for (uint64_t seed : {1, 2, 3}) {
        MeasureOptions o;
        o.pathsPerPoint = 64, o.seed = seed;
        const SamplerResult r = lab.measure(o).samplers[0];
        o.choiceError = false;
        const SamplerResult plain = lab.measure(o).samplers[0];
        EXPECT_NEAR(r.standardError, plain.standardError, 0.25 * plain.standardError) << "seed " << seed;
        EXPECT_EQ(lab.measure(o).samplers[0].standardError, plain.standardError) << "the same paths, the same error";
    }
}

// A directional path adds to its own stratum and to those of its eye's light samples
// (the sun, the sky, a luminaire); a path cache record holds exactly that many.
TEST(PathContributions, HoldADirectionalPathsStrataAndRefuseMore) {
    PathContributions c(5);
    c.add(1.0);  // its own stratum
    for (int k = 0; k < SensorLight::kCapacity; ++k) c.add(k, 2.0 + k);
    c.add(1, 0.5);  // a stratum already there sums
    ASSERT_EQ(c.size(), PathContributions::kCapacity);
    EXPECT_EQ(c.itemAt(0), 5);
    EXPECT_EQ(c.valueAt(0), 1.0);
    EXPECT_EQ(c.valueAt(2), 3.5);
    EXPECT_THROW(c.add(7, 1.0), std::logic_error);
}

// Strata of a sampler that shares paths are strata of one stratified estimate: a
// constant per stratum has no variance.
TEST(ItemEstimates, StratifiedErrorIgnoresTheSpreadBetweenSources) {
    ItemEstimates e(1, 2);
    for (int g = 0; g < ItemEstimates::kFolds; ++g)
        for (int k = 0; k < 4; ++k) e.cell(0, 0, g).add(1.0), e.cell(0, 1, g).add(3.0);
    Estimate x = e.of(0);
    EXPECT_DOUBLE_EQ(x.value, 2.0);
    EXPECT_DOUBLE_EQ(x.standardError, 0.0);
    EXPECT_EQ(e.pathsInFold(0, 0), 8u);
    EXPECT_DOUBLE_EQ(e.ofFold(0, 0).value, 2.0);
    EXPECT_DOUBLE_EQ(e.ofAllBut(0, 0).value, 2.0);
    EXPECT_DOUBLE_EQ(e.ofAllBut(0, 0).standardError, 0.0);
}

// A held-out fold is taken from cached totals by subtraction: it must equal the
// estimate merged from scratch out of the other folds; so must the kept estimate of all.
TEST(ItemEstimates, HeldOutFoldMatchesTheOtherFoldsMergedFromScratch) {
    const int items = 3, sources = 3;
    ItemEstimates e(items, sources);
    Rng rng(4);
    for (int i = 0; i < items; ++i)
        for (int s = 0; s < sources; ++s)
            for (int g = 0; g < ItemEstimates::kFolds; ++g)
                for (int k = 0, n = 1 + int(5 * rng.uniform()); k < n; ++k) e.cell(i, s, g).add(100 * rng.uniform());
    for (int i = 0; i < items; ++i)
        for (int g = 0; g < ItemEstimates::kFolds; ++g) {
            double mean = 0, variance = 0;
            for (int s = 0; s < sources; ++s) {
                MeanEstimator m;
                for (int h = 0; h < ItemEstimates::kFolds; ++h)
                    if (h != g) m.merge(e.cell(i, s, h));
                mean += m.mean() / sources, variance += m.variance() / double(m.count()) / (sources * sources);
            }
            Estimate x = e.ofAllBut(i, g);
            EXPECT_NEAR(x.value, mean, 1e-12 * mean);
            EXPECT_NEAR(x.standardError, std::sqrt(variance), 1e-9 * std::sqrt(variance));
        }
    // All folds, each item's estimate kept once computed: asked in any order, again and
    // again, it is the one merged from scratch.
    for (int pass = 0; pass < 2; ++pass)
        for (int i = items - 1; i >= 0; --i) {
            double mean = 0, variance = 0;
            for (int s = 0; s < sources; ++s) {
                MeanEstimator m;
                for (int h = 0; h < ItemEstimates::kFolds; ++h) m.merge(e.cell(i, s, h));
                mean += m.mean() / sources, variance += m.variance() / double(m.count()) / (sources * sources);
            }
            EXPECT_NEAR(e.of(i).value, mean, 1e-12 * mean) << "item " << i << ", pass " << pass;
            EXPECT_NEAR(e.of(i).standardError, std::sqrt(variance), 1e-9 * std::sqrt(variance));
        }
}

// A look refills only the cells of the sources its round traced and says so
// (ItemEstimates::changed): every estimate, kept or computed afresh, must then equal a
// fresh object's with the same cells, bit for bit, over rounds that refill some sources.
TEST(ItemEstimates, RefilledSourcesEqualAFreshObject) {
    const int items = 4, sources = 4;
    Rng rng(9);
    std::vector<MeanEstimator> truth(size_t(items) * sources * ItemEstimates::kFolds);
    auto at = [&](int i, int s, int g) -> MeanEstimator& { return truth[(size_t(i) * sources + s) * ItemEstimates::kFolds + g]; };
    ItemEstimates kept(items, sources);
    auto refill = [&](int s) {
        for (int i = 0; i < items; ++i) {
            for (int g = 0; g < ItemEstimates::kFolds; ++g) {
                for (int k = 0, n = int(4 * rng.uniform()); k < n; ++k) at(i, s, g).add(rng.uniform() < 0.5 ? 0 : 50 * rng.uniform());
                kept.cell(i, s, g) = at(i, s, g);
            }
            kept.changed(i, s);
        }
    };
    auto same = [](const Estimate& a, const Estimate& b) {
        return std::bit_cast<uint64_t>(a.value) == std::bit_cast<uint64_t>(b.value) &&
               std::bit_cast<uint64_t>(a.standardError) == std::bit_cast<uint64_t>(b.standardError);
    };
    for (int s = 0; s < sources; ++s) refill(s);
    for (int round = 0; round < 12; ++round) {
        ItemEstimates fresh(items, sources);
        for (int i = 0; i < items; ++i)
            for (int s = 0; s < sources; ++s)
                for (int g = 0; g < ItemEstimates::kFolds; ++g) fresh.cell(i, s, g) = at(i, s, g);
        for (int i = 0; i < items; ++i) {
            EXPECT_TRUE(same(kept.of(i), fresh.of(i))) << "round " << round << ", item " << i;
            for (int g = 0; g < ItemEstimates::kFolds; ++g) {
                EXPECT_TRUE(same(kept.ofAllBut(i, g), fresh.ofAllBut(i, g))) << "round " << round << ", item " << i;
                EXPECT_TRUE(same(kept.ofFold(i, g), fresh.ofFold(i, g))) << "round " << round << ", item " << i;
            }
        }
        // Then one or two sources traced on, as a focused look does.
        refill(int(rng.uniform() * sources));
        if (round % 3 == 0) refill(int(rng.uniform() * sources));
    }
}

// With unequal path counts per source, each source still weighs 1 / sources (a pooled
// mean would weigh the busier source more), and the error adds each source's own.
TEST(ItemEstimates, SourcesWeighEquallyWhateverTheirPathCounts) {
    ItemEstimates e(1, 2);
    for (int k = 0; k < 4; ++k) e.cell(0, 0, 0).add(k % 2 ? 0.0 : 2.0);  // mean 1, variance 4/3
    for (int k = 0; k < 12; ++k) e.cell(0, 1, 0).add(3.0);
    Estimate x = e.of(0);
    EXPECT_DOUBLE_EQ(x.value, 2.0);
    EXPECT_NEAR(x.standardError, std::sqrt(4.0 / 3 / 4) / 2, 1e-12);
}

}  // namespace
}  // namespace luxplan
