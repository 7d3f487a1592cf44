// Points no light reaches (pathtracer/sealed_boxes.h): inside a closed opaque box
// without a luminaire, a path reads exactly 0 and traces no ray, and tracing it would
// have read exactly 0 too; glass, translucent and lit boxes, points at a face and
// boxes that moved away seal nothing.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/daylight/daylight.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

const Vec3 kUp(0, 0, 1);

// A sunlit room with a window and a ceiling panel; a fixed box of `material` on the
// floor, (2.5..3.5, 1.5..2.5, 0..0.5), and a movable block (1.0 x 0.2 x 0.1 m) on it,
// rotated by 30 degrees, of the same material.
Scene room(const std::string& material, bool lampInBox = false) {
    test::SceneBuilder b;
    b.material("wall", test::diffuse(0.6))
        .material("paint", test::diffuse(0.5))
        .material("glass", test::glass(0.8))
        .material("cloth", test::translucent(0.3, 0.5))
        .sunAndUniformSky({35, 170, 50000}, 3000, 0.2)
        .room({0, 0, 0}, {6, 4, 3}, "wall", "wall", "wall")
        .window(Wall::South, 1, 2, 0.9, 1.4)
        .emitter("panel", rectEmitter({3, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
        .box("plinth", {2.5, 1.5, 0}, {3.5, 2.5, 0.5}, material);
    if (lampInBox) b.emitter("bulb", sphereEmitter({3.3, 2.3, 0.3}, 0.02), 200);
    return b.entity("block", {3, 2, 0.5}, 30).region({1, 1}, {5, 3}).part({1.0, 0.2, 0.1}, material).end().build();
}

struct Lab {
    Scene scene;
    std::unique_ptr<EmbreeScene> rt;
    std::unique_ptr<PathTracer> tracer;
    std::optional<DaylightEnvironment> daylight;
    explicit Lab(Scene s) : scene(std::move(s)) {
        daylight = buildDaylight(*scene.daylight, scene.site);
        rt = std::make_unique<EmbreeScene>(scene, initialLayout(scene));
        tracer = std::make_unique<PathTracer>(*rt, &*daylight);
    }
};

TEST(SealedBoxes, APointInAClosedOpaqueBoxReadsZeroWithoutARay) {
    Lab lab(room("paint"));
    const Vec3 p(3.2, 1.8, 0.3);  // in the plinth
    ASSERT_TRUE(lab.tracer->sealedAt(p));
    Rng rng(1);
    RayStats stats;
    PathFootprint footprint;
    PathParams params;
    params.footprint = &footprint;
    for (int k = 0; k < 100; ++k) {
        PathSamples samples(rng);
        EXPECT_EQ(lab.tracer->sample(CosineSensor(p, kUp), samples, stats, params), 0.0);
    }
    EXPECT_EQ(stats.closest + stats.shadow, 0u);
    // The way out reaches the plinth's nearest face (its top, 0.2 m up), so a move
    // of the box meets the path; and any luminaire's move does.
    ASSERT_FALSE(footprint.segments.empty());
    const Segment& s = footprint.segments.back();
    EXPECT_FLOAT_EQ(s.from[2], 0.3f);
    EXPECT_FLOAT_EQ(s.to[2], 0.5f);
    EXPECT_TRUE(footprint.usedEmitterChoice);

    // Traced through, the same box (its triangles alone, not known to be closed) lets
    // no light in either: skipping the paths changes no number.
    Scene unknown = room("paint");
    for (StaticItem& item : unknown.geometry) item.mesh.solidBoxes.clear();
    Lab traced(std::move(unknown));
    ASSERT_FALSE(traced.tracer->sealedAt(p));
    RayStats tracedStats;
    for (int k = 0; k < 2000; ++k) EXPECT_EQ(traced.tracer->sample(CosineSensor(p, kUp), rng, tracedStats), 0.0);
    EXPECT_GT(tracedStats.closest, 2000u);
}

TEST(SealedBoxes, GlassTranslucentAndLitBoxesSealNothing) {
    const Vec3 p(3.2, 1.8, 0.3);
    EXPECT_TRUE(Lab(room("paint")).tracer->sealedAt(p));
    EXPECT_FALSE(Lab(room("glass")).tracer->sealedAt(p));
    EXPECT_FALSE(Lab(room("cloth")).tracer->sealedAt(p));
    EXPECT_FALSE(Lab(room("paint", true)).tracer->sealedAt(p));  // a bulb inside
    // Outside, and too near a face to be sure of the first ray (kInset).
    Lab lab(room("paint"));
    EXPECT_FALSE(lab.tracer->sealedAt({3.2, 1.8, 0.6}));
    EXPECT_FALSE(lab.tracer->sealedAt({3.2, 1.8, 0.5 - 0.5 * SealedBoxes::kInset}));
    EXPECT_TRUE(lab.tracer->sealedAt({3.2, 1.8, 0.5 - 2 * SealedBoxes::kInset}));
}

TEST(SealedBoxes, FollowTheLayout) {
    Lab lab(room("paint"));
    // The block, turned 30 degrees about its centre (3, 2): a point along its long
    // axis is inside, one as far along x is not.
    const double c = std::cos(radians(30.0)), s = std::sin(radians(30.0));
    const Vec3 along(3 + 0.4 * c, 2 + 0.4 * s, 0.55), beside(3.4, 2, 0.55);
    EXPECT_TRUE(lab.tracer->sealedAt(along));
    EXPECT_FALSE(lab.tracer->sealedAt(beside));
    // Moved away (and the tracer told): nothing there seals any more.
    Layout moved = initialLayout(lab.scene);
    moved.placements[0].position = {1.5, 1.2, 0};
    lab.rt->setLayout(moved);
    lab.tracer->updateLayout();
    EXPECT_FALSE(lab.tracer->sealedAt(along));
    EXPECT_TRUE(lab.tracer->sealedAt({1.5, 1.2, 0.05}));
}

TEST(SealedBoxes, AMeshKeepsItsBoxesOnlyWhereTheyStayBoxes) {
    TriangleMesh box;
    addBox(box, Bounds3({0, 0, 0}, {1, 2, 3}), 4);
    ASSERT_EQ(box.solidBoxes.size(), 1u);
    TriangleMesh moved;
    moved.append(box, Transform::placement({1, 1, 1}, 90));
    ASSERT_EQ(moved.solidBoxes.size(), 1u);
    EXPECT_NEAR(moved.solidBoxes[0].box.lo.x, -1, 1e-12);
    EXPECT_NEAR(moved.solidBoxes[0].box.hi.y, 2, 1e-12);
    EXPECT_NEAR(moved.solidBoxes[0].box.hi.z, 4, 1e-12);
    EXPECT_EQ(moved.solidBoxes[0].material, 4u);
    TriangleMesh turned;
    turned.append(box, Transform::placement({}, 30));
    EXPECT_TRUE(turned.solidBoxes.empty());
    EXPECT_EQ(turned.triangleCount(), 12u);
}

}  // namespace
}  // namespace luxplan
