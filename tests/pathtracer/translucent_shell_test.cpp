// A lamp inside a closed translucent box in a black void, against the closed form:
// the inner faces receive Phi / (1 - rho (1 - f)) in all (each lumen comes back
// rho (1 - f) of the time, f the share of the faces' light the lamp absorbs, at most
// r^2 / a^2), and a fraction tau of it leaves through them. Both are measured as the
// mean illuminance at random points just inside and just outside the faces, so light
// sampling through a translucent surface, its BSDF sampling to both sides and their
// MIS are checked for bias together.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

constexpr double kHalf = 0.25;     // the box's half side (m)
constexpr double kRadius = 0.01;   // the lamp's (m)
constexpr double kFlux = 1000;     // lm
constexpr double kOffset = 3e-4;   // sensors' distance from the faces (m)

struct Estimate {
    double mean = 0, error = 0;  // lx, and the standard error
};

// Mean illuminance over the box's faces, at kOffset inside (`inside`) or outside, the
// sensor facing into the box either way (inside: the interior's light; outside: the
// face's exitance).
Estimate faceIlluminance(const PathTracer& tracer, bool inside, int paths, uint64_t seed) {
    Rng rng(seed);
    RayStats stats;
    double sum = 0, sumSq = 0;
    for (int k = 0; k < paths; ++k) {
        int face = std::min(5, int(6 * rng.uniform()));
        int axis = face / 2;
        double sign = face % 2 ? 1 : -1;
        Vec3 p, n;
        p[axis] = sign * (kHalf + (inside ? -kOffset : kOffset));
        p[(axis + 1) % 3] = kHalf * (2 * rng.uniform() - 1);
        p[(axis + 2) % 3] = kHalf * (2 * rng.uniform() - 1);
        n[axis] = -sign;
        double e = tracer.illuminanceSample(p, n, rng, stats);
        sum += e, sumSq += e * e;
    }
    Estimate out;
    out.mean = sum / paths;
    out.error = std::sqrt(std::max(0.0, sumSq / paths - out.mean * out.mean) / paths);
    return out;
}

Scene shell(const Material& m) {
    return test::SceneBuilder()
        .material("shade", m)
        .box("shell", {-kHalf, -kHalf, -kHalf}, {kHalf, kHalf, kHalf}, "shade")
        .emitter("bulb", sphereEmitter({0, 0, 0}, kRadius), kFlux)
        .build();
}

// The inner faces receive the closed form whatever tau, and tau of it leaves. The
// sensors stand h = kOffset from the faces: inside, the irradiance there differs
// from the face's by O(h / a); outside, a sensor near an edge misses the strip
// beyond it, at most h / a of a cube's flux (half a strip of width h per face and
// unit edge length). Both are allowed for, with 4 standard errors.
void expectClosedForm(const Material& material, double rho, double tau, uint64_t seed) {
    const Scene scene = shell(material);
    EmbreeScene rt(scene, initialLayout(scene));
    PathTracer tracer(rt, nullptr);
    const double area = 6 * (2 * kHalf) * (2 * kHalf), edge = kOffset / kHalf;
    const double fMax = kRadius * kRadius / (kHalf * kHalf);
    const double high = kFlux / (1 - rho) / area, low = kFlux / (1 - rho * (1 - fMax)) / area;
    Estimate in = faceIlluminance(tracer, true, 60000, seed);
    EXPECT_GE(in.mean, low * (1 - edge) - 4 * in.error) << "rho " << rho << " tau " << tau << ", error " << in.error;
    EXPECT_LE(in.mean, high * (1 + edge) + 4 * in.error) << "rho " << rho << " tau " << tau << ", error " << in.error;
    Estimate out = faceIlluminance(tracer, false, 60000, seed + 1);
    if (tau == 0) {
        EXPECT_EQ(out.mean, 0.0) << "an opaque shell lets nothing out";
        return;
    }
    EXPECT_GE(out.mean, tau * low * (1 - edge) - 4 * out.error) << "rho " << rho << " tau " << tau << ", error " << out.error;
    EXPECT_LE(out.mean, tau * high + 4 * out.error) << "rho " << rho << " tau " << tau << ", error " << out.error;
}

TEST(TranslucentShell, TheFluxOutIsTauOfWhatReachesTheFaces) {
    expectClosedForm(test::translucent(0.5, 0.4), 0.5, 0.4, 11);
    expectClosedForm(test::translucent(0.1, 0.85), 0.1, 0.85, 21);
    expectClosedForm(test::translucent(0.0, 0.6), 0.0, 0.6, 31);
}

TEST(TranslucentShell, AnOpaqueShellLetsNothingOut) { expectClosedForm(test::diffuse(0.5), 0.5, 0.0, 41); }

}  // namespace
}  // namespace luxplan
