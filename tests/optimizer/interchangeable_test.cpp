// Entities a swap cannot tell apart (optimizer/interchangeable.h) and the search's
// swap partners without them (MoveSet).
#include <gtest/gtest.h>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/optimizer/interchangeable.h>
#include <luxplan/optimizer/moves.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::kZ;

std::string named(const char* prefix, int i) {
    std::string s(prefix);
    s += std::to_string(i);
    return s;
}

// Three tables alike (a top, a task plane, the same region), pairwise distance rules;
// `variant` changes the third: 0 none, 1 its target, 2 a focus rule of its own, 3 a
// movable chair, 4 its part.
Scene tables(int variant) {
    SceneBuilder b;
    b.material("m", test::diffuse(0.5));
    for (int i = 0; i < 3; ++i) {
        const bool third = i == 2;
        b.entity(named("t", i + 1), {1.0 + 2 * i, 1, 0}).region({0.5, 0.5}, {7.5, 3.5});
        b.part({third && variant == 4 ? 1.2 : 1.0, 1, 0.05}, "m", Vec3(0, 0, 0.7));
        b.sampler(named("top", i), planarSampler({0, 0, 0.76}, kZ, {0, 1, 0}, {0.8, 0.8}, {2, 2}), 150,
                  third && variant == 1 ? 400 : 350);
        if (third && variant == 3) b.entity("chair", {0.6, 0, 0}).region({0.5, -0.2}, {0.7, 0.2}).part({0.4, 0.4, 0.4}, "m").end();
        b.end();
    }
    b.entity("stage", {4, 3.8, 0}).part({2, 0.4, 0.5}, "m").end();
    for (int i = 1; i <= 3; ++i)
        for (int j = i + 1; j <= 3; ++j)
            b.constraint(distanceConstraint({1.5, kInf, std::nullopt}), named("t", i), named("t", j));
    if (variant == 2) b.constraint(focusConstraint(20), "t3", "stage");
    return b.build();
}

TEST(Interchangeable, AlikeTablesWithSymmetricRules) {
    const Scene s = tables(0);
    const int t1 = s.findEntity("t1"), t2 = s.findEntity("t2"), t3 = s.findEntity("t3");
    EXPECT_TRUE(interchangeable(s, t1, t2));
    EXPECT_TRUE(interchangeable(s, t2, t3));
    EXPECT_FALSE(interchangeable(s, t1, t1));
    EXPECT_FALSE(interchangeable(s, t1, s.findEntity("stage")));  // not movable alike
}

TEST(Interchangeable, AnyDifferenceTheCostSeesMakesThemDistinct) {
    for (int variant : {1, 2, 3, 4}) {
        const Scene s = tables(variant);
        const int t1 = s.findEntity("t1"), t2 = s.findEntity("t2"), t3 = s.findEntity("t3");
        EXPECT_TRUE(interchangeable(s, t1, t2)) << "variant " << variant;
        EXPECT_FALSE(interchangeable(s, t1, t3)) << "variant " << variant;
    }
}

TEST(Interchangeable, HeldToOtherBoundsTheyAreDistinct) {
    // A region bounding the footprint, or a footprint free to leave the room, is a rule
    // of its own: a swap with such an entity is a real move.
    for (int variant : {0, 1}) {
        Scene s = tables(0);
        const int t1 = s.findEntity("t1"), t2 = s.findEntity("t2"), t3 = s.findEntity("t3");
        if (variant == 0) s.entities[size_t(t3)].regions[0].bound = RegionBound::Footprint;
        else s.entities[size_t(t3)].inRoom = false;
        EXPECT_TRUE(interchangeable(s, t1, t2)) << "variant " << variant;
        EXPECT_FALSE(interchangeable(s, t1, t3)) << "variant " << variant;
    }
}

TEST(Interchangeable, DirectedRulesMustMapOntoThemselves) {
    // t1 faces t2 and t2 faces t1: symmetric under the trade; t1 faces t3 alone is not.
    SceneBuilder b;
    b.material("m", test::diffuse(0.5));
    for (const char* name : {"t1", "t2", "t3"}) b.entity(name, {1, 1, 0}).region({0, 0}, {5, 5}).part({1, 1, 1}, "m").end();
    b.constraint(focusConstraint(20), "t1", "t2").constraint(focusConstraint(20), "t2", "t1");
    b.constraint(focusConstraint(20), "t1", "t3");
    const Scene s = b.build();
    EXPECT_FALSE(interchangeable(s, s.findEntity("t1"), s.findEntity("t2")));  // t1 -> t3 has no t2 -> t3
    SceneBuilder c;
    c.material("m", test::diffuse(0.5));
    for (const char* name : {"t1", "t2"}) c.entity(name, {1, 1, 0}).region({0, 0}, {5, 5}).part({1, 1, 1}, "m").end();
    c.constraint(focusConstraint(20), "t1", "t2").constraint(focusConstraint(20), "t2", "t1");
    const Scene s2 = c.build();
    EXPECT_TRUE(interchangeable(s2, s2.findEntity("t1"), s2.findEntity("t2")));
}

TEST(Interchangeable, TheSearchProposesNoSwapOfAlikeEntities) {
    const Scene alike = tables(0), distinct = tables(1);
    std::vector<int> all = {alike.findEntity("t1"), alike.findEntity("t2"), alike.findEntity("t3")};
    MoveSet none(alike, all, {});
    Rng rng(3);
    for (int k = 0; k < 200; ++k) {
        Layout layout = initialLayout(alike);
        EXPECT_NE(none.propose(layout, rng).type, MoveType::Swap);
    }
    // t3 differs: it may swap with t1 and t2, which never swap with each other.
    MoveSet some(distinct, all, {});
    int swaps = 0;
    for (int k = 0; k < 400; ++k) {
        Layout layout = initialLayout(distinct);
        Proposal p = some.propose(layout, rng);
        if (p.type != MoveType::Swap) continue;
        ++swaps;
        EXPECT_TRUE(p.entity == all[2] || p.partner == all[2]) << p.entity << " " << p.partner;
    }
    EXPECT_GT(swaps, 0);
}

}  // namespace
}  // namespace luxplan
