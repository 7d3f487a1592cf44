// Exact incremental re-evaluation (incremental/path_cache.h): after any sequence of
// moves, some accepted (committed) and some refused (discarded), measuring with the
// cache gives the same numbers, bit for bit, as measuring the same layout from
// scratch (a fresh Embree scene and path tracer) with the same seed and paths; and
// it traces fewer paths when a move is small.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/incremental/checked_paths.h>
#include <luxplan/incremental/path_cache.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;
using test::kZ;

// A glazed, sunlit 6 x 4 m room with a ceiling panel: a desk carrying a task plane and
// a lamp (its own entity, with a shade emitter), a chair, a cabinet; a fixed plane on
// the floor, a fixed directional sampler looking at the window, a volume. With
// `terrace`, a sunlit terrace outside the window that paths see through it (the
// sun's light off it is then taken where the sky's portal samples meet it). `walls`:
// their reflectance (at 0.95 many paths run past 64 segments).
Scene studio(bool terrace = false, double walls = 0.6, bool foot = false) {
    SceneBuilder b;
    if (terrace) b.material("stone", test::diffuse(0.5)).box("terrace", {-4, -8, -0.3}, {10, -0.5, 0}, "stone");
    b.material("wall", test::diffuse(walls))
        .material("wood", test::diffuse(0.4))
        .material("glass", test::glass(0.8))
        .sunAndUniformSky({35, 170, 50000}, 3000, 0.2)
        .room({0, 0, 0}, {6, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 1, 2, 0.9, 1.4, "glass")
        .emitter("panel", rectEmitter({3, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
        .sampler("floor", planarSampler({3, 2, 0.01}, kZ, {0, 1, 0}, {4, 2}, {3, 2}), 100, 300, 50)
        .sampler("view", directionalSampler({3, 3, 1.2}, {0, -1, 0}, kZ, 60, 3), 0, 2000)
        .sampler("air", volumeSampler({4, 1, 1}, {Vec3(0.4, 0, 0), Vec3(0, 0.4, 0), Vec3(0, 0, 0.4)}, 4), 100, 500, 50)
        .sampler("face", cylindricalSampler({1, 1, 1.2}), 50, 150, 25)
        .entity("desk", {2, 2.5, 0}).region({0.8, 0.5}, {5.2, 3.5}, {0, 90, 180, 270})
        .part({1.4, 0.7, 0.75}, "wood", Vec3(0, 0, 0.375))
        .sampler("task", planarSampler({0, 0, 0.76}, kZ, {0, 1, 0}, {1.2, 0.6}, {2, 2}), 300, 500, 100)
        .entity("lamp", {0.5, 0.2, 0.75}).part({0.1, 0.1, 0.4}, "wood", Vec3(0, 0, 0.2))
        .emitter("shade", diskEmitter({0, 0, 0.45}, {0, 0, -1}, 0.08), 400)
        .end();
    // A monitor (presets.cpp: four boxes, whose triangles the path cache's clusters
    // split) whose foot, 2 cm high, holds the task plane's points at 0.76 m when it
    // stands over them.
    if (foot) b.entity("monitor", {0, 0, 0.75}).region({-0.6, -0.3}, {0.6, 0.3}).preset("monitor", "wood").end();
    return b.end()
        .entity("chair", {2, 1.5, 0}).region({0.5, 0.5}, {5.5, 3.5}, {0, 90, 180, 270}).part({0.5, 0.5, 0.9}, "wood", Vec3(0, 0, 0.45)).end()
        .entity("cabinet", {5, 3.5, 0}).region({4.5, 3.2}, {5.5, 3.7}).part({0.8, 0.4, 1.2}, "wood", Vec3(0, 0, 0.6)).end()
        .build();
}

struct FromScratch {
    std::unique_ptr<EmbreeScene> rt;
    std::unique_ptr<PathTracer> tracer;
    FromScratch(const Scene& scene, const Layout& layout, const DaylightEnvironment* daylight)
        : rt(std::make_unique<EmbreeScene>(scene, layout)), tracer(std::make_unique<PathTracer>(*rt, daylight)) {}
};

// Equal element by element, a NaN (a covered point) equal to a NaN.
bool sameValues(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
    return true;
}

void expectSame(const MeasureResult& a, const MeasureResult& b, const std::string& where) {
    ASSERT_EQ(a.samplers.size(), b.samplers.size());
    for (size_t k = 0; k < a.samplers.size(); ++k) {
        SCOPED_TRACE(where + ", sampler " + std::to_string(k));
        EXPECT_EQ(a.samplers[k].value, b.samplers[k].value);
        EXPECT_EQ(a.samplers[k].standardError, b.samplers[k].standardError);
        EXPECT_TRUE(sameValues(a.samplers[k].points, b.samplers[k].points));
        EXPECT_TRUE(sameValues(a.samplers[k].pointErrors, b.samplers[k].pointErrors));
        EXPECT_EQ(a.samplers[k].covered, b.samplers[k].covered);
        EXPECT_EQ(a.samplers[k].pathsPerPoint, b.samplers[k].pathsPerPoint);
        EXPECT_EQ(a.samplers[k].droppedNonFinite, b.samplers[k].droppedNonFinite);
    }
    EXPECT_EQ(a.paths, b.paths);
}

int entityNamed(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.entities.size(); ++i)
        if (s.entities[i].name == name) return int(i);
    return -1;
}

// A random move of one of the movable entities (the desk carries the task plane and
// the lamp), or of the lamp on the desk; rotations by right angles or any angle.
void randomMove(const Scene& scene, Layout& layout, Rng& rng) {
    static const char* names[] = {"desk", "chair", "cabinet", "lamp"};
    const int e = entityNamed(scene, names[int(rng.uniform() * 4) % 4]);
    ASSERT_GE(e, 0);
    Placement& p = layout.placements[size_t(e)];
    if (scene.entities[size_t(e)].name == "lamp") {
        p.position.x = -0.6 + 1.2 * rng.uniform(), p.position.y = -0.3 + 0.6 * rng.uniform();
        return;
    }
    p.position.x += 0.6 * (rng.uniform() - 0.5), p.position.y += 0.6 * (rng.uniform() - 0.5);
    if (rng.uniform() < 0.3) p.rotationDeg = rng.uniform() < 0.5 ? 90.0 * int(rng.uniform() * 4) : 360 * rng.uniform();
}

// The sequences' measurement: looks from 8 paths on, so that adaptive runs stop early.
// `chunkPaths`: how the looks at few items split their paths (MeasureOptions); the
// measurements from scratch never split them.
// `lightFloors`: the light samples' roulette (MeasureOptions), in both.
MeasureOptions sequenceOptions(bool adaptive, int paths, int chunkPaths = 0, const std::vector<double>& lightFloors = {}) {
    MeasureOptions o;
    o.pathsPerPoint = paths, o.seed = 7, o.adaptive = adaptive, o.batchPaths = 8, o.minPaths = 8;
    o.chunkPaths = chunkPaths;
    o.lightFloors = lightFloors;
    return o;
}

// Measures `layout` into the cache and commits it: where a sequence of moves starts.
void commitFirst(SceneLab& lab, const MeasureOptions& o, PathCache& cache, const Layout& layout) {
    lab.rt->setLayout(layout);
    lab.tracer->updateLayout();
    measureSamplers(*lab.tracer, o, &cache);
    cache.commit();
}

void runSequence(bool adaptive, int paths, int moves, uint64_t moveSeed, bool terrace = false, double walls = 0.6,
                 int chunkPaths = 0, double lightRoulette = 0) {
    SceneLab lab(studio(terrace, walls));
    ASSERT_EQ(lab.tracer->samplesExteriorSun(), terrace);
    const Scene& scene = lab.scene;
    const DaylightEnvironment* daylight = lab.daylight ? &*lab.daylight : nullptr;
    // The search's floors come from a pilot at the scene's layout, fixed for the run.
    const std::vector<double> floors = lightRoulette > 0 ? lightSampleFloors(*lab.tracer, lightRoulette, 7) : std::vector<double>{};
    if (lightRoulette > 0) {
        ASSERT_GT(*std::max_element(floors.begin(), floors.end()), 0.0);
    }
    const MeasureOptions o = sequenceOptions(adaptive, paths, chunkPaths, floors),
                         inOrder = sequenceOptions(adaptive, paths, 0, floors);
    PathCache cache(scene);
    Layout committed = initialLayout(scene);
    commitFirst(lab, o, cache, committed);
    Rng rng(moveSeed);
    uint64_t reused = 0, traced = 0;
    for (int m = 0; m < moves; ++m) {
        Layout proposed = committed;
        randomMove(scene, proposed, rng);
        if (rng.uniform() < 0.25) randomMove(scene, proposed, rng);  // two entities at once
        lab.rt->setLayout(proposed);
        lab.tracer->updateLayout();
        MeasureResult incremental = measureSamplers(*lab.tracer, o, &cache);
        FromScratch fresh(scene, proposed, daylight);
        MeasureResult scratch = measureSamplers(*fresh.tracer, inOrder);
        expectSame(incremental, scratch, "move " + std::to_string(m));
        EXPECT_EQ(scratch.reusedPaths, 0u);
        reused += incremental.reusedPaths, traced += incremental.paths;
        if (rng.uniform() < 0.5) {
            cache.commit();
            committed = proposed;
        } else {
            cache.discard();
        }
    }
    // Half the moves carry the lamp (every path chose an emitter): the rest reuse.
    EXPECT_GT(double(reused), 0.1 * double(traced));
    if (walls > 0.9) {
        EXPECT_GT(cache.longestPath(), 64u);
    }
}

TEST(PathCache, MovesEqualFromScratchFixedPaths) { runSequence(false, 24, 24, 11); }

TEST(PathCache, MovesEqualFromScratchAdaptive) { runSequence(true, 48, 24, 12); }

TEST(PathCache, MovesEqualFromScratchWithASunlitTerraceOutside) { runSequence(true, 48, 24, 13, true); }

// Long paths (a bright room: many of more than 64 segments), whose shadow queries far
// down the path are found and asked again.
TEST(PathCache, MovesEqualFromScratchWithLongPaths) { runSequence(true, 64, 24, 14, false, 0.95); }

// The looks at the cylindrical sampler's one point and at the directional sampler's
// focused stratum split into chunks of 3 paths, traced on any thread and merged in path
// order, with the cache's reads and keeps: the same numbers as in order from scratch.
TEST(PathCache, MovesEqualFromScratchWithLooksInChunks) { runSequence(true, 64, 16, 15, false, 0.6, 3); }

// The light samples' roulette, as the search traces: a shadow ray it skipped is no
// part of the path, whose value is the same whatever that ray would have met.
TEST(PathCache, MovesEqualFromScratchWithTheLightSamplesRoulette) { runSequence(true, 48, 24, 16, false, 0.6, 0, 0.5); }

// A monitor's foot put over one of the desk's task points (no light reaches a point in it: its
// paths are not traced, pathtracer/sealed_boxes.h), beside them, and away again, while
// the desk moves too: the same numbers as from scratch, and the point is sealed in
// some layouts and not in others.
TEST(PathCache, MovesEqualFromScratchWithAFootOverATaskPoint) {
    SceneLab lab(studio(false, 0.6, true));
    const Scene& scene = lab.scene;
    const int foot = entityNamed(scene, "monitor"), desk = entityNamed(scene, "desk");
    ASSERT_GE(foot, 0);
    const MeasureOptions o = sequenceOptions(true, 32);
    PathCache cache(scene);
    Layout committed = initialLayout(scene);
    commitFirst(lab, o, cache, committed);
    Rng rng(21);
    int sealedLayouts = 0, openLayouts = 0;
    for (int m = 0; m < 24; ++m) {
        Layout proposed = committed;
        Placement& p = proposed.placements[size_t(foot)];
        if (rng.uniform() < 0.6) {  // on a task point (+-0.3, +-0.15), a little off
            p.position.x = (rng.uniform() < 0.5 ? -0.3 : 0.3) + 0.1 * (rng.uniform() - 0.5);
            p.position.y = (rng.uniform() < 0.5 ? -0.15 : 0.15) + 0.1 * (rng.uniform() - 0.5);
        } else {
            p.position.x = -0.6 + 1.2 * rng.uniform(), p.position.y = -0.3 + 0.6 * rng.uniform();
        }
        if (rng.uniform() < 0.3) randomMove(scene, proposed, rng);
        lab.rt->setLayout(proposed);
        lab.tracer->updateLayout();
        MeasureResult incremental = measureSamplers(*lab.tracer, o, &cache);
        FromScratch fresh(scene, proposed, &*lab.daylight);
        expectSame(incremental, measureSamplers(*fresh.tracer, o), "move " + std::to_string(m));
        bool sealed = false;
        for (double x : {-0.3, 0.3})
            for (double y : {-0.15, 0.15})
                sealed = sealed || fresh.tracer->sealedAt(fresh.rt->worldFromEntity(desk).applyPoint({x, y, 0.76}));
        (sealed ? sealedLayouts : openLayouts)++;
        if (rng.uniform() < 0.5) {
            cache.commit();
            committed = proposed;
        } else {
            cache.discard();
        }
    }
    EXPECT_GE(sealedLayouts, 5);
    EXPECT_GE(openLayouts, 5);
}

// CheckedPaths traces every path the cache gives again: through moves, all agree
// and the numbers are the check-free ones.
TEST(PathCache, TheCheckTracesEveryReusedPathAgain) {
    SceneLab lab(studio());
    const MeasureOptions o = sequenceOptions(true, 32);
    PathCache cache(lab.scene);
    CheckedPaths checkedCache(cache);
    Layout committed = initialLayout(lab.scene);
    commitFirst(lab, o, cache, committed);
    Rng rng(31);
    uint64_t checked = 0;
    for (int m = 0; m < 8; ++m) {
        Layout proposed = committed;
        randomMove(lab.scene, proposed, rng);
        lab.rt->setLayout(proposed);
        lab.tracer->updateLayout();
        const MeasureResult r = measureSamplers(*lab.tracer, o, &checkedCache);
        const CacheCheck found = checkedCache.found();
        EXPECT_TRUE(found.on);
        EXPECT_EQ(found.checked, r.reusedPaths);
        EXPECT_EQ(found.differing, 0u);
        FromScratch fresh(lab.scene, proposed, &*lab.daylight);
        expectSame(r, measureSamplers(*fresh.tracer, o), "checked, move " + std::to_string(m));
        checked += found.checked;
        cache.commit();
        committed = proposed;
    }
    EXPECT_GT(checked, 0u);
}

// A cache whose paths are not what a fresh trace gives (here: kept by a tracer with
// daylight, read back by one without, which a caller must not do) is caught: every
// difference counted, the first ones named with where the rays part.
TEST(PathCache, TheCheckFindsPathsThatAFreshTraceGivesOtherwise) {
    SceneLab lab(studio());
    MeasureOptions o;
    o.pathsPerPoint = 16;
    PathCache cache(lab.scene);
    const MeasureResult kept = measureSamplers(*lab.tracer, o, &cache);
    cache.commit();
    PathTracer other(*lab.rt, nullptr);
    CheckedPaths checkedCache(cache);
    const MeasureResult r = measureSamplers(other, o, &checkedCache);
    const CacheCheck found = checkedCache.found();
    EXPECT_EQ(r.reusedPaths, r.paths);
    EXPECT_EQ(found.checked, r.paths);
    EXPECT_GT(found.differing, 0u);
    EXPECT_LE(found.differing, found.checked);  // every path here meets daylight (the covered points are not traced)
    ASSERT_EQ(found.first.size(), std::min<size_t>(CacheCheck::kKept, found.differing));
    const Bounds3 room({-0.01, -0.01, -0.01}, {6.01, 4.01, 3.01});
    for (const CacheDifference& d : found.first) {
        ASSERT_TRUE(d.where.has_value());  // no shadow rays towards the sun and sky
        EXPECT_TRUE(room.contains(*d.where)) << d.where->x << " " << d.where->y << " " << d.where->z;
        EXPECT_GE(d.sampler, 0);
        EXPECT_LT(d.sampler, int(lab.scene.samplers.size()));
    }
    expectSame(r, kept, "the check reads the cache's numbers");
}

TEST(PathCache, AnUnmovedLayoutReusesEveryPath) {
    SceneLab lab(studio());
    MeasureOptions o;
    o.pathsPerPoint = 16;
    PathCache cache(lab.scene);
    MeasureResult first = measureSamplers(*lab.tracer, o, &cache);
    EXPECT_EQ(first.reusedPaths, 0u);
    cache.commit();
    MeasureResult again = measureSamplers(*lab.tracer, o, &cache);
    EXPECT_EQ(again.reusedPaths, again.paths);
    EXPECT_EQ(again.rays.closest + again.rays.shadow, 0u);
    expectSame(again, first, "unmoved");
    // More paths than committed: the first ones are reused, the rest traced.
    cache.commit();
    o.pathsPerPoint = 24;
    MeasureResult more = measureSamplers(*lab.tracer, o, &cache);
    EXPECT_EQ(more.reusedPaths, first.paths);
    expectSame(more, lab.measure(24, 1), "more paths");
    // Another seed shares nothing.
    o.seed = 2;
    EXPECT_EQ(measureSamplers(*lab.tracer, o, &cache).reusedPaths, 0u);
}

// The studio measured and committed at its initial layout, then measured again with
// one entity moved by dx along x.
MeasureResult afterMoving(const char* entity, double dx, int paths) {
    SceneLab lab(studio());
    MeasureOptions o;
    o.pathsPerPoint = paths;
    PathCache cache(lab.scene);
    measureSamplers(*lab.tracer, o, &cache);
    cache.commit();
    Layout layout = initialLayout(lab.scene);
    layout.placements[size_t(entityNamed(lab.scene, entity))].position.x += dx;
    lab.rt->setLayout(layout);
    lab.tracer->updateLayout();
    return measureSamplers(*lab.tracer, o, &cache);
}

TEST(PathCache, MovingTheCabinetRetracesOnlyThePathsThatMetIt) {
    MeasureResult moved = afterMoving("cabinet", -0.3, 32);
    // A 0.8 x 0.4 x 1.2 m cabinet in a corner of a 6 x 4 x 3 m room.
    EXPECT_GT(double(moved.reusedPaths), 0.5 * double(moved.paths));
    EXPECT_LT(moved.reusedPaths, moved.paths);
    std::printf("cabinet move: %llu of %llu paths reused\n", (unsigned long long)moved.reusedPaths, (unsigned long long)moved.paths);
}

// A path that meets a moved chair only along shadow rays the chair blocks neither
// before nor after (or blocks both times) is read back, its queries asked again; the
// numbers stay those from scratch (runSequence's tests fail if the answers are not
// compared).
TEST(PathCache, ShadowRaysThatAnswerAsBeforeKeepTheirPaths) {
    SceneLab lab(studio());
    MeasureOptions o;
    o.pathsPerPoint = 32;
    PathCache cache(lab.scene);
    measureSamplers(*lab.tracer, o, &cache);
    cache.commit();
    Layout layout = initialLayout(lab.scene);
    layout.placements[size_t(entityNamed(lab.scene, "chair"))].position.x += 0.05;
    lab.rt->setLayout(layout);
    lab.tracer->updateLayout();
    const MeasureResult moved = measureSamplers(*lab.tracer, o, &cache);
    EXPECT_GT(cache.askedAgain(), 0u);
    EXPECT_LE(cache.askedAgain(), moved.reusedPaths);
    expectSame(moved, lab.measure(32, o.seed), "chair moved");
    std::printf("chair move: %llu of %llu paths reused, %llu of them by asking shadow rays again\n",
                (unsigned long long)moved.reusedPaths, (unsigned long long)moved.paths, (unsigned long long)cache.askedAgain());
}

// The cache's reach spans only the heights of what can move (no move of the optimizer
// changes a height). A layout that lifts the chair above them (to 1.6-2.5 m, over the
// cabinet's 1.2 m) is still measured right: its move lies outside the reach, so every
// kept path's segments are read, whatever its box.
TEST(PathCache, AChairLiftedAboveWhatMovesStillEqualsFromScratch) {
    SceneLab lab(studio());
    const DaylightEnvironment* daylight = lab.daylight ? &*lab.daylight : nullptr;
    MeasureOptions o;
    o.pathsPerPoint = 32;
    PathCache cache(lab.scene);
    Layout layout = initialLayout(lab.scene);
    commitFirst(lab, o, cache, layout);
    Placement& chair = layout.placements[size_t(entityNamed(lab.scene, "chair"))];
    for (double z : {1.6, 0.0}) {  // up, and back down to where the cache's paths were traced
        chair.position.z = z;
        chair.position.x += 0.4;
        lab.rt->setLayout(layout);
        lab.tracer->updateLayout();
        const MeasureResult moved = measureSamplers(*lab.tracer, o, &cache);
        FromScratch fresh(lab.scene, layout, daylight);
        expectSame(moved, measureSamplers(*fresh.tracer, o), "chair at z = " + std::to_string(z));
        EXPECT_GT(moved.reusedPaths, 0u);
        EXPECT_LT(moved.reusedPaths, moved.paths);
        cache.commit();
    }
}

TEST(PathCache, MovingTheLampRetracesEveryPathThatChoseAnEmitter) {
    // Every path samples an emitter at its first vertex (the scene has two).
    EXPECT_EQ(afterMoving("lamp", 0.1, 8).reusedPaths, 0u);
}

static void memoryBoundOnlyCostsTime(size_t bound) {
    SceneLab lab(studio());
    MeasureOptions o;
    o.pathsPerPoint = 16;
    PathCache cache(lab.scene, /* maxSegments = */ bound);
    MeasureResult first = measureSamplers(*lab.tracer, o, &cache);
    cache.commit();
    EXPECT_LE(cache.segments(), bound);
    MeasureResult again = measureSamplers(*lab.tracer, o, &cache);
    EXPECT_GT(again.reusedPaths, 0u);
    EXPECT_LT(again.reusedPaths, again.paths);
    expectSame(again, first, "bounded");
    // The bound holds through moves, accepted and refused, and more paths per point.
    Rng rng(5);
    Layout layout = initialLayout(lab.scene);
    for (int m = 0; m < 6; ++m) {
        Layout proposed = layout;
        randomMove(lab.scene, proposed, rng);
        lab.rt->setLayout(proposed);
        lab.tracer->updateLayout();
        o.pathsPerPoint = 16 + 4 * m;
        MeasureResult moved = measureSamplers(*lab.tracer, o, &cache);
        expectSame(moved, lab.measure(o.pathsPerPoint, o.seed), "bounded, move " + std::to_string(m));
        if (m % 2 == 0) {
            cache.commit();
            layout = proposed;
        } else {
            cache.discard();
            lab.rt->setLayout(layout);
            lab.tracer->updateLayout();
        }
        EXPECT_LE(cache.segments(), bound);
    }
}

// Work items reserve the bound's segments in grants of at most the bound over twice
// their number (about ten paths' at 5000, four at 2000), and exactly what a path needs
// once a grant no longer fits; a grant counting wrong fails here (segments() > bound).
TEST(PathCache, AMemoryBoundOnlyCostsTime) {
    for (const size_t bound : {size_t(2000), size_t(5000)}) {
        SCOPED_TRACE("bound " + std::to_string(bound));
        memoryBoundOnlyCostsTime(bound);
    }
}

TEST(PathFootprint, SegmentsMeetBoxesAsTheSlabsSay) {
    const Bounds3 box({0, 0, 0}, {1, 1, 1});
    auto seg = [](Vec3 a, Vec3 b) { return Segment{{float(a.x), float(a.y), float(a.z)}, {float(b.x), float(b.y), float(b.z)}}; };
    auto meets = [](const Segment& s, const Bounds3& b, double margin) {
        return SegmentProbe(s).meets({b.lo - Vec3(margin, margin, margin), b.hi + Vec3(margin, margin, margin)});
    };
    EXPECT_TRUE(meets(seg({-1, 0.5, 0.5}, {2, 0.5, 0.5}), box, 0));   // through
    EXPECT_TRUE(meets(seg({0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}), box, 0)); // inside
    EXPECT_FALSE(meets(seg({-1, 0.5, 0.5}, {-0.1, 0.5, 0.5}), box, 0)); // stops short
    EXPECT_TRUE(meets(seg({-1, 0.5, 0.5}, {-0.1, 0.5, 0.5}), box, 0.2)); // within the margin
    EXPECT_FALSE(meets(seg({-1, 2, 0.5}, {2, 2, 0.5}), box, 0));      // parallel, beside
    EXPECT_FALSE(meets(seg({-1, 0, 0.5}, {0.5, -1.5, 0.5}), box, 0)); // passes the corner
    EXPECT_TRUE(meets(seg({1, 1, 1}, {1, 1, 1}), box, 0));            // a point on the corner
    PathFootprint f;
    f.add({-5, 0.5, 0.5}, {1, 0, 0}, 0, kInf);  // no end: runs far past the box
    ASSERT_EQ(f.segments.size(), 1u);
    EXPECT_TRUE(meets(f.segments[0], box, 0));
    f.add({-5, 0.5, 0.5}, {2, 0, 0}, 0, 2);  // t in units of the direction's length
    EXPECT_FALSE(meets(f.segments[1], box, 0));
    f.add({-5, 0.5, 0.5}, {2, 0, 0}, 0, 2.6);
    EXPECT_TRUE(meets(f.segments[2], box, 0));
}

// The path cache's first test of every segment says "apart" only of segments that the
// exact slab test says miss the box: over random boxes and segments, short and long
// (to the 1e6 m a ray with no end keeps), grazing ones included; and it is as sharp:
// it tells apart every segment that misses the box by more than a millimetre.
TEST(PathFootprint, TheSegmentBoxFilterNeverMissesWhatTheSlabsMeet) {
    Rng rng(5);
    auto point = [&](double r) { return Vec3(r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1)); };
    auto seg = [](Vec3 a, Vec3 b) { return Segment{{float(a.x), float(a.y), float(a.z)}, {float(b.x), float(b.y), float(b.z)}}; };
    int met = 0, missed = 0, missedTold = 0;
    for (int i = 0; i < 200000; ++i) {
        const Vec3 c = point(10), h(rng.uniform() * 2, rng.uniform() * 2, rng.uniform() * 0.5);
        const Bounds3 box(c - h, c + h);
        const Vec3 p = c + point(4);
        Vec3 q = i % 4 == 0 ? p + point(1) * 1e6 : c + point(4);                 // a quarter run 1e6 m away
        if (i % 7 == 0) q = Vec3(p.x + rng.uniform(), p.y, p.z);                 // parallel to an axis
        if (i % 11 == 0) q = p;                                                  // a point
        const Segment s = seg(p, q);
        const SegmentBoxFilter filter(box);
        const bool meets = SegmentProbe(s).meets(box);
        if (meets) {
            ASSERT_TRUE(filter.mayMeet(s)) << "segment " << i << " meets the box, the filter says apart";
            ++met;
        } else if (!SegmentProbe(s).meets({box.lo - Vec3(1e-3, 1e-3, 1e-3), box.hi + Vec3(1e-3, 1e-3, 1e-3)})) {
            ++missed;
            missedTold += !filter.mayMeet(s);
        }
    }
    EXPECT_GT(met, 10000);
    EXPECT_GT(missed, 20000);
    EXPECT_EQ(missedTold, missed);
    // Grazing: along a face, and past an edge by a hair.
    const Bounds3 unit({0, 0, 0}, {1, 1, 1});
    EXPECT_TRUE(SegmentBoxFilter(unit).mayMeet(seg({-1, 1, 0.5}, {2, 1, 0.5})));
    EXPECT_FALSE(SegmentBoxFilter(unit).mayMeet(seg({-1, 1.001, 0.5}, {2, 1.001, 0.5})));
    EXPECT_FALSE(SegmentBoxFilter(unit).mayMeet(seg({-1, 0, 0.5}, {0.5, -1.5, 0.5})));  // past the corner
    EXPECT_FALSE(SegmentBoxFilter(Bounds3()).mayMeet(seg({0, 0, 0}, {1, 1, 1})));       // empty
}

// Up to 32 segments at once (two per vector): bit i answers for segment i as it would
// alone, for every count (odd ones share their last pair with themselves), and no bit
// at or above the count is set.
TEST(PathFootprint, TheSegmentBoxFilterAnswersManySegmentsAsOneByOne) {
    Rng rng(11);
    auto point = [&](double r) { return Vec3(r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1)); };
    const SegmentBoxFilter filter(Bounds3({1, 1, 0}, {2.6, 1.8, 1.2}));
    int mayMeet = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::array<Segment, 32> segments;
        for (Segment& s : segments) {
            const Vec3 p = Vec3(2, 1.5, 0.5) + point(3), q = trial % 5 == 0 ? p + point(1) * 1e6 : Vec3(2, 1.5, 0.5) + point(3);
            s = {{float(p.x), float(p.y), float(p.z)}, {float(q.x), float(q.y), float(q.z)}};
        }
        const uint32_t n = 1 + uint32_t(trial % 32);
        const uint32_t mask = filter.mayMeet(segments.data(), n);
        for (uint32_t i = 0; i < 32; ++i) {
            const bool bit = (mask >> i) & 1;
            if (i >= n) {
                ASSERT_FALSE(bit) << "trial " << trial << ": bit " << i << " of " << n << " segments";
                continue;
            }
            ASSERT_EQ(bit, filter.mayMeet(segments[i])) << "trial " << trial << ", segment " << i << " of " << n;
            mayMeet += bit;
        }
    }
    EXPECT_GT(mayMeet, 2000);  // both answers are common
    EXPECT_LT(mayMeet, 25000);
}

// A kept path's box (PartsInside): it holds every part of its segments inside the clip
// box, as long double slabs clip them, and no more than their parts inside the clip box
// widened by its micrometre. Segments inside, leaving (to the 1e6 m a ray with no end
// keeps), passing through, missing, along an axis, in a face's plane, single points.
TEST(PathFootprint, PartsInsideHoldEveryPartInsideTheClipBoxAndNoMore) {
    using Real = long double;
    const Bounds3 clip({-0.5, -0.5, -0.5}, {7.5, 5.5, 3.5});
    const PartsInside parts(clip);
    Rng rng(9);
    auto point = [&](double r) { return Vec3(r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1)); };
    auto seg = [](Vec3 a, Vec3 b) { return Segment{{float(a.x), float(a.y), float(a.z)}, {float(b.x), float(b.y), float(b.z)}}; };
    // The exact part of s inside clip widened by `pad`, extended into box.
    auto reference = [&](const Segment& s, double pad, Bounds3& box) {
        Real t0 = 0, t1 = 1;
        for (int a = 0; a < 3; ++a) {
            const Real from = s.from[a], d = Real(s.to[a]) - from, lo = Real(clip.lo[a]) - pad, hi = Real(clip.hi[a]) + pad;
            if (d == 0) {
                if (from < lo || from > hi) return;
                continue;
            }
            Real enter = (lo - from) / d, leave = (hi - from) / d;
            if (enter > leave) std::swap(enter, leave);
            t0 = std::max(t0, enter), t1 = std::min(t1, leave);
        }
        if (t0 > t1) return;
        for (Real t : {t0, t1}) {
            Vec3 p;
            for (int a = 0; a < 3; ++a) p[a] = double(s.from[a] + (Real(s.to[a]) - s.from[a]) * t);
            box.extend(p);
        }
    };
    const Vec3 centre = (clip.lo + clip.hi) * 0.5, lo = clip.lo;
    int leaving = 0, empty = 0;
    for (int i = 0; i < 20000; ++i) {
        std::vector<Segment> segments;
        for (int k = 0; k < 1 + i % 9; ++k) {
            Vec3 p = centre + point(6), q = centre + point(6);
            if (k % 3 == 1) q = p + point(1) * 1e6;        // escapes
            if (k % 5 == 2) q = Vec3(p.x, p.y, p.z + 9);   // along an axis
            if (k % 7 == 3) p.y = q.y = lo.y;              // in a face's plane
            if (k % 11 == 4) q = p;                        // a point
            if (i % 13 == 5) p = p + Vec3(30, 0, 0);        // far outside
            segments.push_back(seg(p, q));
        }
        Bounds3 exact, widened;
        for (const Segment& s : segments) {
            reference(s, 0, exact);
            reference(s, 1e-6, widened);
            leaving += std::abs(s.to[0]) > 1e5 && !parts.of(std::span(&s, 1)).empty();
        }
        const Bounds3 got = parts.of(segments);
        empty += exact.empty();
        if (widened.empty()) {
            EXPECT_TRUE(got.empty()) << "segment set " << i;
            continue;
        }
        ASSERT_FALSE(got.empty()) << "segment set " << i;
        for (int a = 0; a < 3; ++a) {  // long double against double: a few 1e-10 m
            if (!exact.empty()) {
                ASSERT_LE(got.lo[a], exact.lo[a] + 1e-9) << "set " << i << " axis " << a;
                ASSERT_GE(got.hi[a], exact.hi[a] - 1e-9) << "set " << i << " axis " << a;
            }
            ASSERT_GE(got.lo[a], widened.lo[a] - 1e-9) << "set " << i << " axis " << a;
            ASSERT_LE(got.hi[a], widened.hi[a] + 1e-9) << "set " << i << " axis " << a;
        }
    }
    EXPECT_GT(leaving, 1000);
    EXPECT_GT(empty, 100);
    EXPECT_TRUE(parts.of({}).empty());
}

// The distance from x to triangle (a, b, c), exactly (the closest point by regions:
// Ericson, "Real-Time Collision Detection", 5.1.5).
double distanceToTriangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ax = x - a;
    const double d1 = dot(ab, ax), d2 = dot(ac, ax);
    if (d1 <= 0 && d2 <= 0) return length(x - a);
    const Vec3 bx = x - b;
    const double d3 = dot(ab, bx), d4 = dot(ac, bx);
    if (d3 >= 0 && d4 <= d3) return length(x - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(x - (a + ab * (d1 / (d1 - d3))));
    const Vec3 cx = x - c;
    const double d5 = dot(ab, cx), d6 = dot(ac, cx);
    if (d6 >= 0 && d5 <= d6) return length(x - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(x - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return length(x - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1 / (va + vb + vc);
    return length(x - (a + ab * (vb * denom) + ac * (vc * denom)));
}

// The segment's distance to the triangle: the distance to a convex set is convex along
// the segment, so a ternary search finds its minimum.
double segmentToTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    double lo = 0, hi = 1;
    auto f = [&](double t) { return distanceToTriangle(p + (q - p) * t, a, b, c); };
    for (int i = 0; i < 200; ++i) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (f(m1) < f(m2) ? hi : lo) = (f(m1) < f(m2) ? m2 : m1);
    }
    return std::min({f(0), f(1), f(0.5 * (lo + hi))});
}

// A segment that TriangleProximity says stays away from a triangle does: over random
// triangles and segments near them, never within the margin by the exact distance; and
// the test is worth its cost: most segments well outside the margin are told apart.
TEST(PathFootprint, ATriangleIsNearOnlyWhereTheSegmentComesWithinTheMargin) {
    Rng rng(3);
    auto point = [&](double r) { return Vec3(r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1), r * (2 * rng.uniform() - 1)); };
    int far = 0, farTold = 0, crossing = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a = point(1), b = point(1), c = point(1);
        const double margin = i % 2 ? 1e-3 : 0.05;
        const Vec3 p = point(1.5), q = i % 3 ? point(1.5) : p + (b - a) * rng.uniform();  // a third parallel to an edge
        const TriangleProximity t(a, b, c);
        const double d = segmentToTriangle(p, q, a, b, c);
        const bool near = t.near(p, q, margin);
        if (d <= margin) {
            ASSERT_TRUE(near) << "triangle " << i << ": the segment comes within " << d << " of it, margin " << margin;
            ++crossing;
        } else if (d > 2 * margin) {
            ++far;
            farTold += !near;
        }
    }
    EXPECT_GT(crossing, 500);
    EXPECT_GT(double(farTold), 0.95 * double(far)) << farTold << " of " << far;
    std::printf("%d segments within the margin, %d of %d beyond twice it told apart\n", crossing, farTold, far);
    // Exactly on the margin's edge, above the middle of a unit triangle, and through it.
    const TriangleProximity unit({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    EXPECT_FALSE(unit.near({0.2, 0.2, 0.011}, {0.3, 0.2, 0.011}, 0.01));
    EXPECT_TRUE(unit.near({0.2, 0.2, 0.009}, {0.3, 0.2, 0.009}, 0.01));
    EXPECT_TRUE(unit.near({0.2, 0.2, -1}, {0.2, 0.2, 1}, 0.01));
    EXPECT_FALSE(unit.near({0.8, 0.8, -1}, {0.8, 0.8, 1}, 0.01));  // through the plane, past the long edge
    EXPECT_TRUE(TriangleProximity({0, 0, 0}, {1, 0, 0}, {2, 0, 0}).near({5, 5, 5}, {6, 6, 6}, 0.01));  // degenerate: always
}

// A cluster's box with its triangles: a segment through the box's empty part misses an
// L of two panels, which the box alone cannot tell; a box part whose faces cover its box
// meets whatever enters the box.
TEST(PathFootprint, PlacedBoxesTestTheTrianglesTheyBound) {
    // A floor panel z = 0 and a wall panel x = 0, 1 m square, each two triangles.
    const std::vector<Bounds3> box{Bounds3({0, 0, 0}, {1, 1, 1})};
    std::vector<BoxedTriangles> l(1);
    l[0].triangles = {TriangleProximity({0, 0, 0}, {1, 0, 0}, {1, 1, 0}), TriangleProximity({0, 0, 0}, {1, 1, 0}, {0, 1, 0}),
                      TriangleProximity({0, 0, 0}, {0, 1, 0}, {0, 1, 1}), TriangleProximity({0, 0, 0}, {0, 1, 1}, {0, 0, 1})};
    auto seg = [](Vec3 a, Vec3 b) { return Segment{{float(a.x), float(a.y), float(a.z)}, {float(b.x), float(b.y), float(b.z)}}; };
    const Segment through = seg({0.5, -1, 0.5}, {0.5, 2, 0.5}), ontoFloor = seg({0.5, 0.5, 2}, {0.5, 0.5, 0.5e-3});
    const PlacedBoxes alone(Transform::placement({3, 3, 0}, 30), box, 1e-3, 0);
    const PlacedBoxes withTriangles(Transform::placement({3, 3, 0}, 30), box, 1e-3, 0, &l);
    const Transform world = Transform::placement({3, 3, 0}, 30);
    auto placed = [&](const Segment& s) {
        const Vec3 a = world.applyPoint({s.from[0], s.from[1], s.from[2]}), b = world.applyPoint({s.to[0], s.to[1], s.to[2]});
        return seg(a, b);
    };
    EXPECT_TRUE(alone.meets(placed(through), SegmentProbe(placed(through))));
    EXPECT_FALSE(withTriangles.meets(placed(through), SegmentProbe(placed(through))));
    EXPECT_TRUE(withTriangles.meets(placed(ontoFloor), SegmentProbe(placed(ontoFloor))));  // ends within the margin
    l[0].coversBox = true;  // then the box decides for a segment inside it
    EXPECT_TRUE(withTriangles.meets(placed(through), SegmentProbe(placed(through))));
}

TEST(PathFootprint, PlacedBoxesAreOrientedWithTheirObject) {
    // A 2 x 0.1 x 1 m plank turned 45 degrees about z at (5, 5, 0): its world box is
    // about 1.48 m square, but a segment across that box's corner misses the plank.
    const std::vector<Bounds3> plank{Bounds3({-1, -0.05, 0}, {1, 0.05, 1})};
    const PlacedBoxes boxes(Transform::placement({5, 5, 0}, 45), plank, 1e-3, 0);
    auto seg = [](Vec3 a, Vec3 b) { return Segment{{float(a.x), float(a.y), float(a.z)}, {float(b.x), float(b.y), float(b.z)}}; };
    auto meets = [&](const Segment& s) { return boxes.meets(s, SegmentProbe(s)); };
    EXPECT_NEAR(boxes.worldBounds().hi.x - boxes.worldBounds().lo.x, 2 * (std::sqrt(0.5) + 0.05 * std::sqrt(0.5)) + 2e-3, 1e-6);
    const Segment corner = seg({5.7, 4.3, 0.5}, {5.3, 4.3, 0.5});  // inside the world box, far from the plank
    EXPECT_TRUE(SegmentProbe(corner).meets(boxes.worldBounds()));
    EXPECT_FALSE(meets(corner));
    EXPECT_TRUE(meets(seg({4, 6, 0.5}, {6, 4, 0.5})));             // across the plank's middle
    EXPECT_TRUE(meets(seg({5.7, 5.7, 0.5}, {5.7, 5.7, 1.5})));     // down onto its end, near the axis
    EXPECT_FALSE(meets(seg({5, 5, 1.01}, {6, 6, 1.01})));          // along its top, above the margin
    EXPECT_TRUE(meets(seg({5, 5, 1.0005}, {6, 6, 1.0005})));       // ... within it
    // The margin is in world units, whatever the transform's scale.
    Transform scaled = Transform::placement({5, 5, 0}, 45) * Transform::scale(10.0);
    const std::vector<Bounds3> small{Bounds3({-0.1, -0.005, 0}, {0.1, 0.005, 0.1})};
    const PlacedBoxes big(scaled, small, 1e-3, 0);
    EXPECT_TRUE(big.meets(seg({5, 5, 1.0009}, {6, 6, 1.0009}), SegmentProbe(seg({5, 5, 1.0009}, {6, 6, 1.0009}))));
}

}  // namespace
}  // namespace luxplan
