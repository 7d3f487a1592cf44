// Touching parts have coincident faces: a lamp shade's four walls, two halves of a
// translucent block. A ray that reaches their common plane hits one face or the
// other, as the order of the BVH decides, and a move anywhere in the room rebuilds
// the BVH. Of one material, both faces are the same surface for the path, so the light
// must not depend on which one it met: otherwise a path that the path cache keeps
// would differ from the one traced afresh after the move (lightsamplers/path_cache.h).
// Without +0 in the vertex's normals (path_tracer.cpp) 49 of these 5000 paths differ.
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

}  // namespace
}  // namespace luxplan
