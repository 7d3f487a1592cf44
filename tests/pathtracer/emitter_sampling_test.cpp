// Emitter choice: the selection probabilities sum to one and vanish behind one-sided
// emitters; sampling through the set (choice included) matches the set's pdf. Each
// shape's own sampling is tested in tests/emitters/.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <luxplan/core/rng.h>
#include <luxplan/pathtracer/emitters.h>
#include "support/chi2.h"

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

// The weights are flux / max(d^2, reach^2), 0 behind a one-sided emitter: a row of
// disks, a two-sided bulb and a disk whose back faces the point, seen from a point 1 m
// below the row and from one 0.1 m under a disk (within its reach of 0.2 m, where the
// weight stops growing).
TEST(EmitterSampling, WeightsAreFluxOverSquaredDistance) {
    Scene s;
    for (int i = 0; i < 5; ++i) s.emitters.push_back(disk({double(i), 0, 3}, 0.2, 100.0 * (i + 1)));
    Emitter bulb;
    bulb.shape = sphereEmitter({0, 0, 1}, 0.1), bulb.fluxLm = 50;
    s.emitters.push_back(bulb);
    s.emitters.push_back(disk({1, 1, 0.5}, 0.3, 700));  // its back faces p
    const EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    for (Vec3 p : {Vec3(1.5, 0.5, 2), Vec3(3, 0, 2.9)}) {
        std::vector<double> w;
        for (int i = 0; i < 5; ++i) w.push_back(100.0 * (i + 1) / std::max(lengthSquared(Vec3(i, 0, 3) - p), 0.04));
        w.push_back(50 / std::max(lengthSquared(Vec3(0, 0, 1) - p), 0.01));
        w.push_back(0);
        double total = 0;
        for (double x : w) total += x;
        for (size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(set.selectionProbability(i, p), w[i] / total, 1e-12) << i;
    }
}

// The choice is a binary search over the weights' running sums: it must pick the
// emitter a scan of the selection probabilities picks, past the 64 weights kept on the
// stack, with emitters that weigh nothing (behind their plane) among them, and the last
// one with weight at the very top.
TEST(EmitterSampling, TheChoiceIsTheScansOverManyEmitters) {
    for (int count : {5, 64, 65, 150}) {
        Scene s;
        for (int i = 0; i < count; ++i) {
            Emitter e = disk({0.3 * i, 0.2 * (i % 7), 3}, 0.1, 100.0 + 37 * (i % 11));
            if (i % 5 == 2 || i == count - 1) e.shape = diskEmitter({0.3 * i, 0, 0.5}, {0, 0, -1}, 0.1);  // faces away from p
            s.emitters.push_back(e);
        }
        const EmitterSet set(s, {}, EmitterSelection::PowerDistance);
        const Vec3 p(4, 0.5, 1.5);
        std::vector<double> cumulative;
        double acc = 0;
        for (size_t k = 0; k < set.size(); ++k) cumulative.push_back(acc += set.selectionProbability(k, p));
        ASSERT_NEAR(acc, 1, 1e-12);
        Rng rng{uint64_t(count)};
        for (int n = 0; n < 2000; ++n) {
            const double u = rng.uniform();
            const size_t expected = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
            // A u within rounding of a boundary may go either way.
            if (expected < set.size() && std::abs(cumulative[expected] - u) < 1e-12) continue;
            if (expected > 0 && std::abs(cumulative[expected - 1] - u) < 1e-12) continue;
            const EmitterSample e = set.sample(p, u, {0.5, 0.5});
            ASSERT_EQ(e.emitter, int(expected)) << count << " emitters, u " << u;
            EXPECT_EQ(e.emitter, set.sample(set.viewFrom(p), u, {0.5, 0.5}).emitter);
        }
        int last = -1;
        for (size_t k = 0; k < set.size(); ++k)
            if (set.selectionProbability(k, p) > 0) last = int(k);
        EXPECT_EQ(set.sample(p, std::nextafter(1.0, 0.0), {0.5, 0.5}).emitter, last);
        EXPECT_EQ(set.sample(p, 1.0, {0.5, 0.5}).emitter, last);  // the target at the total itself
        EXPECT_EQ(set.sample(p, 0, {0.5, 0.5}).emitter, 0);
    }
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

namespace luxplan {
namespace {

// A lopsided distribution: 12 planes, gammas every 15 degrees to 180, brightest
// towards C 60 and gamma 40, some uplight.
std::shared_ptr<const IntensityDistribution> lopsided() {
    PhotometricTable t;
    for (int c = 0; c < 360; c += 30) t.cDeg.push_back(c);
    for (int g = 0; g <= 180; g += 15) t.gammaDeg.push_back(g);
    for (double c : t.cDeg)
        for (double g : t.gammaDeg)
            t.candela.push_back(g == 180 ? 0
                                         : 800 * std::exp(-std::pow((g - 40) / 25, 2)) * (1.3 + std::cos((c - 60) * kPi / 180)) +
                                               (g > 90 ? 20 : 0));
    return std::make_shared<IntensityDistribution>(t);
}

Emitter luminaire(std::shared_ptr<const EmitterShape> opening, Vec3 axis, Vec3 c0, double flux) {
    Emitter e;
    e.shape = photometricEmitter(opening, lopsided(), axis, c0);
    e.fluxLm = flux;
    return e;
}

TEST(PhotometricEmission, RadianceIsIntensityOverProjectedArea) {
    Scene s;
    const double r = 0.05, flux = 1500;
    s.emitters = {luminaire(diskEmitter({0, 0, 3}, {0, 0, -1}, r), {0, 0, -1}, {1, 0, 0}, flux),
                  luminaire(sphereEmitter({2, 0, 3}, r), {0, 0, -1}, {1, 0, 0}, flux)};
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    auto d = lopsided();
    const double scale = flux / d->flux();
    // Towards C 90 (+y: c0 x normal = x x -z), gamma 30, the light leaves along
    // (0, sin 30, -cos 30); the viewer looks back along w.
    Vec3 out(0, 0.5, -std::sqrt(3.0) / 2), w = -out;
    double I = scale * d->intensity(PhotometricAngles{kPi / 2, kPi / 6});
    EXPECT_NEAR(set.emitted(0, w), I / (kPi * r * r * std::sqrt(3.0) / 2), 1e-9 * I);
    EXPECT_NEAR(set.emitted(1, w), I / (kPi * r * r), 1e-9 * I);
    // The distribution sends light upwards, so the flat opening emits from its back too.
    EXPECT_FALSE(set[0].normal.has_value());
    Vec3 up(std::sqrt(3.0) / 2, 0, 0.5);  // C 0, gamma 120
    EXPECT_NEAR(set.emitted(0, -up), scale * d->intensity(PhotometricAngles{0, 2 * kPi / 3}) / (kPi * r * r * 0.5), 1e-9 * I);
    EXPECT_GT(set.emitted(0, -up), 0.0);
}

TEST(PhotometricEmission, FarAwayIlluminanceIsIntensityOverDistanceSquared) {
    Scene s;
    // A 1 mm opening: the bilinear table has kinks at its planes, and an opening's
    // extent averages across them (a 1 cm one reads 0.5% high at C 270, gamma 15).
    s.emitters = {luminaire(diskEmitter({0, 0, 3}, {0, 0, -1}, 0.001), {0, 0, -1}, {1, 0, 0}, 2000)};
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    auto d = lopsided();
    const double scale = 2000 / d->flux(), dist = 2.5;
    Rng rng(4);
    for (double cDeg : {0.0, 60.0, 150.0, 270.0})
        for (double gDeg : {15.0, 45.0, 75.0, 120.0}) {
            double c = cDeg * kPi / 180, g = gDeg * kPi / 180;
            // x: C 0, y: C 90, -z: gamma 0.
            Vec3 out(std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), -std::cos(g));
            Vec3 p = Vec3(0, 0, 3) + out * dist, n = normalize(Vec3(0.3, -0.2, 1) * (gDeg > 90 ? -1.0 : 1.0));
            double E = 0;
            const int samples = 256;
            for (int k = 0; k < samples; ++k) {
                EmitterSample e = set.sample(p, rng.uniform(), {rng.uniform(), rng.uniform()});
                ASSERT_GE(e.emitter, 0);
                E += e.Lv * std::max(0.0, dot(e.wi, n)) / e.pdf / samples;
            }
            double expected = scale * d->intensity(PhotometricAngles{c, g}) * std::max(0.0, dot(-out, n)) / (dist * dist);
            EXPECT_NEAR(E, expected, 2e-3 * expected) << "C " << cDeg << " gamma " << gDeg;
        }
}

TEST(PhotometricEmission, SetPdfMatchesSampleAndVanishesWhereNothingIsSent) {
    Scene s;
    s.emitters = {luminaire(rectEmitter({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, {0.3, 0.2}), {0, 0, -1}, {1, 0, 0}, 1000),
                  luminaire(diskEmitter({1, 0.5, 2.8}, {0, 0, -1}, 0.1), {0, 0, -1}, {0, 1, 0}, 800), disk({-1, 0, 3}, 0.2, 500)};
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    Rng rng(8);
    for (Vec3 p : {Vec3(0.5, 0.2, 0.5), Vec3(-0.4, 1.1, 1.2), Vec3(0.2, 0.1, 3.5)}) {
        for (int k = 0; k < 100; ++k) {
            EmitterSample e = set.sample(p, rng.uniform(), {rng.uniform(), rng.uniform()});
            if (e.emitter < 0) continue;
            Vec3 q = p + e.wi * e.distance;
            EXPECT_NEAR(e.pdf, set.pdf(size_t(e.emitter), p, q), 1e-9 * e.pdf);
            EXPECT_NEAR(e.Lv, set.emitted(size_t(e.emitter), e.wi), 1e-12 * e.Lv);
        }
    }
    // Straight up (gamma 180) the distribution sends nothing: a point right above the
    // rect never chooses it.
    EXPECT_EQ(set.selectionProbability(0, {0, 0, 4}), 0.0);
}

// The choice among photometric luminaires follows each one's intensity towards the
// point over distance squared (chi-square over the emitters).
TEST(PhotometricEmission, ChoiceFollowsTheIntensityTowardsThePoint) {
    Scene s;
    const Vec3 p(0.3, -0.2, 0.8);
    std::vector<Vec3> centers = {{0, 0, 3}, {2, 1, 2.5}, {-1.5, 0.5, 3}, {0.5, -2, 2.8}, {1, 1, 0.2}, {-1, -1, 1.5}};
    std::vector<Vec3> c0s = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, -1, 0}};
    for (size_t i = 0; i < centers.size(); ++i) {
        Vec3 axis = i == 4 ? Vec3(0, 0, 1) : Vec3(0, 0, -1);
        s.emitters.push_back(luminaire(diskEmitter(centers[i], axis, 0.05), axis, c0s[i], 500.0 * double(i + 1)));
    }
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    auto d = lopsided();
    std::vector<double> weight;
    double total = 0;
    for (size_t i = 0; i < centers.size(); ++i) {
        auto* l = set[i].photometric;
        ASSERT_NE(l, nullptr);
        Vec3 to = p - centers[i];
        weight.push_back(set[i].intensityScale * l->intensity(normalize(to)) / lengthSquared(to));
        total += weight.back();
    }
    const int samples = 200000;
    std::vector<double> observed(centers.size(), 0.0), expected(centers.size());
    Rng rng(12);
    for (int k = 0; k < samples; ++k) {
        EmitterSample e = set.sample(p, rng.uniform(), {rng.uniform(), rng.uniform()});
        ASSERT_GE(e.emitter, 0);
        observed[size_t(e.emitter)] += 1;
    }
    for (size_t i = 0; i < centers.size(); ++i) {
        expected[i] = samples * weight[i] / total;
        EXPECT_NEAR(set.selectionProbability(i, p), weight[i] / total, 1e-12);
    }
    auto r = test::chi2Test(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

TEST(PhotometricEmission, AxesMoveWithTheEmitter) {
    auto l = photometricEmitter(diskEmitter({1, 0, 2}, {0, 0, -1}, 0.1), lopsided(), {0, 0, -1}, std::nullopt);
    EXPECT_NEAR(length(l->c0() - Vec3(1, 0, 0)), 0, 1e-12);  // world +x projected
    EXPECT_NEAR(length(l->c90() - Vec3(0, 1, 0)), 0, 1e-12);  // c0 x normal
    auto placed = std::dynamic_pointer_cast<const PhotometricEmitter>(l->transformed(Transform::placement({0, 0, 0}, 90)));
    ASSERT_NE(placed, nullptr);
    EXPECT_NEAR(length(placed->c0() - Vec3(0, 1, 0)), 0, 1e-12);
    EXPECT_NEAR(length(placed->center() - Vec3(0, 1, 2)), 0, 1e-12);
    EXPECT_NEAR(placed->intensity(Vec3(0, 0.6, -0.8)), l->intensity(Vec3(0.6, 0, -0.8)), 1e-9);
    // A rect's C 0 is its first side by default.
    auto rect = rectEmitter({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.3});
    EXPECT_NEAR(length(defaultC0(*rect, {0, 0, -1}) - *rect->firstSide()), 0, 1e-12);
    EXPECT_NEAR(length(*rect->firstSide() - Vec3(-1, 0, 0)), 0, 1e-12);
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// A sensor point's view of the luminaires (its choice weights and each shape's set-up,
// kept per thread) gives exactly what sampling from the point afresh gives, for every
// shape, and follows its point and its set.
int compareViewWithFresh(const EmitterSet& set, const Vec3& p, Rng& rng) {
    int compared = 0;
    for (int k = 0; k < 200; ++k) {
        const double uSelect = rng.uniform();
        const Vec2 u(rng.uniform(), rng.uniform());
        const EmitterSample a = set.sample(p, uSelect, u), b = set.sample(set.viewFrom(p), uSelect, u);
        EXPECT_EQ(a.emitter, b.emitter);
        EXPECT_EQ(a.pdf, b.pdf);
        EXPECT_EQ(a.Lv, b.Lv);
        EXPECT_EQ(a.distance, b.distance);
        EXPECT_TRUE(a.wi == b.wi);
        if (a.emitter < 0 || a.emitter != b.emitter) continue;
        const Vec3 q = p + a.wi * a.distance;
        for (size_t i = 0; i < set.size(); ++i) EXPECT_EQ(set.pdf(i, p, q), set.pdf(i, set.viewFrom(p), q)) << i;
        ++compared;
    }
    return compared;
}

TEST(EmitterPointView, SamplesAndDensitiesAreThoseFromThePointItself) {
    Scene s;
    s.emitters = {luminaire(rectEmitter({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, {0.3, 0.2}), {0, 0, -1}, {1, 0, 0}, 1000),
                  disk({-1, 0, 3}, 0.2, 500)};
    Emitter panel, bulb;
    panel.shape = rectEmitter({1, 1, 2.9}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), panel.fluxLm = 3000;
    bulb.shape = sphereEmitter({0.5, -1, 2}, 0.05), bulb.fluxLm = 400;
    s.emitters.push_back(panel), s.emitters.push_back(bulb);
    const EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    Rng rng(21);
    int compared = 0;
    for (Vec3 p : {Vec3(0.5, 0.2, 0.75), Vec3(-0.4, 1.1, 1.2), Vec3(0.5, 0.2, 0.75), Vec3(1, 1, 2.95)})
        compared += compareViewWithFresh(set, p, rng);
    EXPECT_GT(compared, 600);
    // Another set from the same point (the bulb moved): its own weights, not the view
    // the thread kept of the first set.
    s.emitters[3].shape = sphereEmitter({0.6, 0.3, 0.9}, 0.05);
    const EmitterSet moved(s, {}, EmitterSelection::PowerDistance);
    const Vec3 p(0.5, 0.2, 0.75);
    ASSERT_NE(moved.selectionProbability(3, p), set.selectionProbability(3, p));
    (void)set.viewFrom(p);
    EXPECT_GT(compareViewWithFresh(moved, p, rng), 150);
}

}  // namespace
}  // namespace luxplan
