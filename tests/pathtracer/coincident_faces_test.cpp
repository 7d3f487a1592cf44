// Touching parts have coincident faces: a lamp shade's four walls, two halves of a
// translucent block. A ray that reaches their common plane hits one face or the
// other, as the order of the BVH decides, and a move anywhere in the room rebuilds
// the BVH. Of one material, both faces are the same surface for the path, so the light
// must not depend on which one it met: otherwise a path that the path cache keeps
// would differ from the one traced afresh after the move (incremental/path_cache.h).
// Without +0 in the vertex's normals (path_tracer.cpp) 49 of these 5000 paths differ.
// Of two materials (a glass slab resting on a wooden block), the faces are different
// surfaces, and the tie goes to the first in a fixed order (EmbreeScene::intersect).
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

// A closed room with a lamp inside a translucent block of two halves that touch,
// turned by 90 degrees (so that the normals of the shared plane have zero components),
// its halves listed in either order. The two scenes are the same surfaces, but nearly
// every ray that meets the shared plane hits the face of the half listed first.
Scene splitBlock(bool swapped) {
    const double first = swapped ? 0.125 : -0.125;
    return test::SceneBuilder()
        .material("wall", test::diffuse(0.6))
        .material("shade", test::translucent(0.5, 0.4))
        .room({0, 0, 0}, {2, 2, 2}, "wall", "wall", "wall")
        .entity("block", {1, 1, 1}, 90)
        .part({0.25, 0.5, 0.5}, "shade", Vec3(first, 0, 0))
        .part({0.25, 0.5, 0.5}, "shade", Vec3(-first, 0, 0))
        .emitter("bulb", sphereEmitter({-0.1, 0.03, -0.02}, 0.01), 1000)
        .end()
        .build();
}

TEST(CoincidentFaces, TheLightIsTheSameWhicheverFaceARayMeets) {
    const Scene a = splitBlock(false), b = splitBlock(true);
    EmbreeScene rtA(a, initialLayout(a)), rtB(b, initialLayout(b));
    PathTracer tracerA(rtA, nullptr), tracerB(rtB, nullptr);
    // Sensors around the block, facing it: their paths cross the shared plane inside
    // the block, many of them more than once.
    constexpr int kPoints = 5000;
    Rng points(5);
    int lit = 0, differ = 0;
    for (int k = 0; k < kPoints; ++k) {
        const Vec3 p(0.5 + points.uniform(), 0.5 + points.uniform(), 0.5 + points.uniform());
        const Vec3 n = normalize(Vec3(1, 1, 1) - p);
        Rng rngA(1000 + uint64_t(k)), rngB(1000 + uint64_t(k));
        RayStats stats;
        const double ea = tracerA.illuminanceSample(p, n, rngA, stats), eb = tracerB.illuminanceSample(p, n, rngB, stats);
        lit += ea > 0;
        differ += ea != eb;
    }
    EXPECT_GT(lit, kPoints / 4);
    EXPECT_EQ(differ, 0) << "of " << kPoints << " paths, bit for bit";
}

// A wooden block with a plastic core whose top lies flush with the block's: two
// materials' faces overlapping in one plane, which a ray from above meets; the parts
// listed in either order. And a glass slab resting on a wooden leg, whose faces meet in
// one plane that a ray inside the slab reaches.
Scene flushAndSlab(bool plasticFirst) {
    test::SceneBuilder b;
    b.material("wall", test::diffuse(0.6))
        .material("wood", test::diffuse(0.5))
        .material("plastic", test::diffuse(0.1))
        .material("glass", test::glass(0.85))
        .room({0, 0, 0}, {3, 2, 2}, "wall", "wall", "wall")
        .entity("flush table", {2.2, 1, 0}, 90);
    if (plasticFirst) b.part({0.3, 0.3, 0.4}, "plastic", Vec3(0, 0, 0.2)).part({0.6, 0.6, 0.4}, "wood", Vec3(0, 0, 0.2));
    else b.part({0.6, 0.6, 0.4}, "wood", Vec3(0, 0, 0.2)).part({0.3, 0.3, 0.4}, "plastic", Vec3(0, 0, 0.2));
    return b.end()
        .entity("glass table", {0.8, 1, 0})
        .part({1.0, 0.6, 0.01}, "glass", Vec3(0, 0, 0.405))
        .part({0.2, 0.2, 0.4}, "wood", Vec3(0, 0, 0.2))
        .end()
        .build();
}

// Which face a ray meets where two materials' faces coincide is the first in a fixed
// order (EmbreeScene::intersect: instance, geometry, triangle), the same whatever the
// BVH. Without it, Embree returns the plastic for some of these rays and the wood for
// the others (which one, the BVH of the moment decides: a move anywhere rebuilds it).
TEST(CoincidentFaces, ATieBetweenTwoMaterialsGoesToTheFirstInAFixedOrder) {
    for (const bool plasticFirst : {false, true}) {
        SCOPED_TRACE(plasticFirst ? "plastic listed first" : "wood listed first");
        const Scene scene = flushAndSlab(plasticFirst);
        EmbreeScene rt(scene, initialLayout(scene));
        const uint32_t first = scene.materialIndex.at(plasticFirst ? "plastic" : "wood");
        // Straight down onto the core's top (a tie for every ray, the plane being flush).
        int hits = 0, firstHits = 0;
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j) {
                const Vec3 o(2.2 - 0.14 + 0.28 * (i + 0.5) / 20, 1 - 0.14 + 0.28 * (j + 0.5) / 20, 1.0);
                const auto hit = rt.intersect({o, {0, 0, -1}});
                ASSERT_TRUE(hit.has_value());
                EXPECT_NEAR(hit->point.z, 0.4, 1e-6);
                ++hits;
                firstHits += hit->material == first;
            }
        EXPECT_EQ(firstHits, hits);
        // Down from inside the glass slab onto the leg: when asked (the path tracer asks once
        // a path has passed a see-through surface), the opaque geometry, attached first.
        const uint32_t wood = scene.materialIndex.at("wood");
        for (int i = 0; i < 50; ++i) {
            const Vec3 o(0.8 - 0.09 + 0.18 * (i + 0.5) / 50, 1.03, 0.4053);
            Ray down{o, normalize(Vec3(0.01, -0.02, -1))};
            down.breakTies = true;
            const auto hit = rt.intersect(down);
            ASSERT_TRUE(hit.has_value());
            EXPECT_NEAR(hit->point.z, 0.4, 1e-6);
            EXPECT_EQ(hit->material, wood);
        }
    }
}

}  // namespace
}  // namespace luxplan
