// Exact incremental re-evaluation: the paths of the last committed layout, kept with
// their footprints, so that measuring a moved layout traces again only the paths a
// move can change. A path is seeded from (seed, sampler, point, path) and its rays see
// the scene only along its footprint; it is traced again when
//   - its sampler is carried by an entity whose world transform changed,
//   - one of its segments meets the old or the new bounds of a moved entity's
//     geometry or luminaires (a ray that missed both traces the same; the bounds are
//     the boxes of up to 32 clusters of its triangles in the entity's own frame, so
//     that a ray under a desk top, between a chair's legs or past the corner of a
//     rotated desk is not traced again), or
//     unless every such segment is a shadow query's and the query, asked again of the
//     new layout, answers as it did (a desk's shadow ray that the moved chair does not
//     block leaves the path as it was), or
//   - it read the emitter choice and a luminaire moved (the choice weighs every
//     luminaire by flux / distance^2, so every light sample's probability changes).
// Every other path reads as it did, so measuring with the cache gives the same numbers,
// bit for bit, as measuring the same layout from scratch (tests/incremental/
// path_cache_test.cpp): where a ray meets coincident faces, which one it hits is the
// first in a fixed order, not the BVH of the moment (EmbreeScene::intersect), but for
// faces of two entities' different materials that overlap in one plane and that a path
// meets before any see-through surface (docs/light-transport.md, "What is left",
// optimize --set check_cache=true finds them). What a measurement traces goes
// to a pending delta: commit() makes it the committed state (the optimizer accepted the
// layout), discard() drops it.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include <luxplan/incremental/entity_clusters.h>
#include <luxplan/incremental/footprint_geometry.h>
#include <luxplan/lightsamplers/path_source.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_footprint.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {

// As a path source (path_source.h) it gives the paths that hold and has the others
// traced afresh with their footprints, which it keeps.
class PathCache : public PathSource {
public:
    // `maxSegments` bounds the memory (24 bytes a segment, and 44 more for a shadow
    // query's, which keeps its rays and answer; the arrays may hold as many again of
    // replaced paths before they are packed): paths beyond it are traced every time,
    // which changes nothing but the time.
    explicit PathCache(const Scene& scene, size_t maxSegments = size_t(1) << 24);

    // Before a measurement of `rt`'s current layout with `workItems` work items (one per
    // sampler item) whose samplers are `workSampler`: what moved since the committed
    // layout. `streams` keys what a path's numbers are (the seed and the sampling
    // options): a different key clears the cache.
    void begin(const EmbreeScene& rt, const std::vector<int>& workSampler, uint64_t streams) override;
    // holds(), or else traced afresh.
    Path get(size_t work, int path, RayStats& stats, FreshPaths& fresh) override;
    // visit(), and keep() for a path traced afresh.
    void used(size_t work, int path, const Path& p, const FootprintView& footprint) override;
    // What the committed path `path` of work item `work` contributed, if that still
    // holds for the new layout, else null. Only reads: threads may ask about paths of
    // one work item at once. `askedAgain`: it holds because its shadow queries, asked
    // again, answered as before.
    const PathContributions* holds(size_t work, int path, bool& askedAgain) const;
    // What the measurement did with path `path` of work item `work`: reused (holds()
    // gave it) or traced afresh (keep() follows). Call for paths 0, 1, ... in order per
    // work item (from one thread per work item at a time).
    void visit(size_t work, int path, bool reused, bool askedAgain);
    // A path traced for the new layout (after visit() noted it traced afresh): what it
    // contributed and where its rays went (copied).
    void keep(size_t work, int path, const PathContributions& contributions, const FootprintView& footprint);
    // The measured layout becomes the committed one, with the paths it traced and the
    // committed paths it did not ask for that the move missed (nothing happens when no
    // measurement is pending).
    void commit();
    // Back to the committed layout's paths, with the paths the measurement traced
    // beyond them that the move missed.
    void discard();

    // The segments of the committed path that holds(work, path) just returned (valid
    // until the next commit or discard).
    std::span<const Segment> segmentsOf(size_t work, int path) const;

    // Paths the measurement in progress, or else the last one, reused.
    uint64_t reused() const override;
    // ... of which met the move only along shadow queries that answered as before.
    uint64_t askedAgain() const;
    size_t segments() const { return committedSegments_; }
    // The most segments one committed path holds.
    size_t longestPath() const;

private:
    // A path's footprint lives in its work item's arrays (one allocation per work
    // item, not two per path, and read in order: the checks of a measurement walk
    // every kept segment, so they wait on memory unless it is contiguous).
    struct Record {
        PathContributions contributions{0};
        uint32_t firstSegment = 0, segmentCount = 0, firstTest = 0, testCount = 0;
        // The box of its segments' parts inside reach_: a move inside reach_ that misses
        // it misses the path, and the check reads no segment (most paths of a
        // measurement pass far from the move).
        std::array<float, 3> lo{}, hi{};
        bool usedEmitterChoice = false;
        bool kept = false;  // false: no record (never traced, or over the memory bound)
    };
    struct Paths {
        std::vector<Record> records;  // by path index (committed), or in the order traced (pending)
        std::vector<Segment> segments;
        std::vector<OcclusionTest> tests;  // OcclusionTest::segment counts from its record's first
        size_t garbage = 0;  // segments no record refers to any more
        // `r` (a record of `from`) with its footprint copied to the end of these arrays.
        Record append(const Record& r, const Paths& from);
    };
    // A work item's part of the measurement, written by one thread at a time: counters
    // shared by the threads would bounce their cache line between the cores at every path.
    struct Pending {
        int visited = 0;  // paths [0, visited) were asked for
        std::vector<int> tracedPaths;  // path index of each of traced.records
        Paths traced;
        uint64_t reused = 0, askedAgain = 0;
        size_t granted = 0;  // segments reserved under the memory bound and not yet used
        void clear() {  // keeping the arrays' memory for the next measurement
            visited = 0;
            tracedPaths.clear();
            traced.records.clear(), traced.segments.clear(), traced.tests.clear(), traced.garbage = 0;
            reused = askedAgain = 0;
            granted = 0;
        }
    };
    // Reserves n more segments for `p` under maxSegments_, in grants of many paths'
    // worth, so that threads seldom meet on the shared count; false when they do not fit.
    bool reserve(Pending& p, size_t n);
    // Whether a record holds for the layout being measured: changed, missed by the move,
    // or met by it only along shadow queries that answer as they did. `requery`: those
    // may be asked again of the scene (false when the record is to hold for the
    // committed layout, which the scene no longer is).
    enum class Verdict { Changed, Missed, SameAnswers };
    Verdict check(size_t work, const Record& r, const Paths& in, bool requery) const;
    static void prefetchAfter(const Paths& paths, size_t path);
    void endMeasurement();  // no measurement pending (its paths are committed or dropped)
    // The world box, in the scene's own layout, of every entity that can move (movable,
    // or carried by one that is) with its luminaires; empty if none (reach_'s heights).
    Bounds3 movingBounds(const Scene& scene) const;

    const Scene& scene_;
    size_t maxSegments_;
    EntityClusters clusters_;
    // Where moves happen: the room's box with a margin (rays to the sky leave it, and
    // their parts outside never meet a move inside), between the lowest and the highest
    // point of what can move; everywhere without a room. A move outside it is still
    // found: its segments are then read whatever a path's box (movedInReach_).
    Bounds3 reach_;
    PartsInside reachParts_;  // reach_'s

    // Committed state.
    bool hasCommitted_ = false;
    uint64_t streams_ = 0;
    std::vector<Transform> world_;
    std::vector<Paths> committed_;  // per work item
    size_t committedSegments_ = 0;

    // The measurement in progress.
    bool measuring_ = false;
    const EmbreeScene* rt_ = nullptr;  // the layout being measured
    std::vector<Transform> newWorld_;
    std::vector<PlacedBoxes> moved_;  // old and new, of every moved entity with geometry
    Bounds3 movedUnion_;
    SegmentBoxFilter movedFilter_;  // movedUnion_'s, the first test of each segment
    bool movedInReach_ = false;  // movedUnion_ lies inside reach_: a path's box decides a miss
    std::vector<char> workMoved_;    // per work item: its sampler moved
    bool emittersMoved_ = false;
    std::vector<Pending> pending_;
    std::atomic<size_t> pendingSegments_{0};  // granted to the work items so far
    uint64_t reusedLast_ = 0, askedAgainLast_ = 0;  // of the last measurement, once it ended
};

}  // namespace luxplan
