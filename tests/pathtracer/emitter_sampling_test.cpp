// Emitter choice: the selection probabilities sum to one and vanish behind one-sided
// emitters; sampling through the set (choice included) matches the set's pdf. Each
// shape's own sampling is tested in tests/emitters/.
#include <gtest/gtest.h>

#include <luxplan/core/rng.h>
#include <luxplan/pathtracer/emitters.h>

namespace luxplan {
namespace {

Emitter disk(Vec3 center, double radius, double flux) {
    Emitter e;
    e.shape = diskEmitter(center, {0, 0, -1}, radius);
    e.fluxLm = flux;
    return e;
}

TEST(EmitterSampling, SelectionProbabilitiesSumToOne) {
    Scene s;
    for (int i = 0; i < 5; ++i) s.emitters.push_back(disk({double(i), 0, 3}, 0.2, 100.0 * (i + 1)));
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    double sum = 0;
    for (size_t i = 0; i < set.size(); ++i) sum += set.selectionProbability(i, {1.5, 0.5, 0.8});
    EXPECT_NEAR(sum, 1.0, 1e-12);
    // A point above the one-sided disks is lit by none of them.
    EXPECT_EQ(set.selectionProbability(0, {0, 0, 4}), 0.0);
}

TEST(EmitterSampling, SetPdfIncludesTheChoice) {
    Scene s;
    s.emitters = {disk({0, 0, 3}, 0.2, 100), disk({2, 0, 3}, 0.3, 300)};
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    Rng rng(3);
    Vec3 p(0.5, 0.2, 0.5);
    for (int k = 0; k < 100; ++k) {
        EmitterSample e = set.sample(p, rng.uniform(), {rng.uniform(), rng.uniform()});
        ASSERT_GE(e.emitter, 0);
        Vec3 q = p + e.wi * e.distance;
        EXPECT_NEAR(e.pdf, set.pdf(size_t(e.emitter), p, q), 1e-9 * e.pdf);
        EXPECT_NEAR(e.pdf, set.selectionProbability(size_t(e.emitter), p) * set[size_t(e.emitter)].shape->pdf(p, q),
                    1e-9 * e.pdf);
    }
}

}  // namespace
}  // namespace luxplan
