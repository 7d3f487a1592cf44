// The light samplers against analytic truth, with tolerances from the estimator's own
// standard error (4 sigma) plus, where a model is tabulated, its stated discretization.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/materials/thin_glass.h>
#include "support/scene_builder.h"
#include "support/rect_illuminance.h"
#include "support/scene_lab.h"
#include "support/threads.h"

namespace luxplan {
namespace {

using test::SceneBuilder;
using test::SceneLab;
using test::cornerIlluminance;
using test::rectIlluminance;

SceneBuilder withMaterials(double rho) {
    SceneBuilder b;
    b.material("grey", test::diffuse(rho)).material("black", test::diffuse(0)).material("glass", test::glass(0.8));
    return b;
}

// A planar sampler of one point: the illuminance there on a plane facing `normal`.
std::shared_ptr<const SamplerType> point(Vec3 center, Vec3 normal = {0, 0, 1}, Vec3 up = {0, 1, 0}) {
    return planarSampler(center, normal, up, {0.001, 0.001}, {1, 1});
}
std::shared_ptr<const SamplerType> plane(Vec3 center, Vec3 normal, Vec3 up, Vec2 size, std::array<int, 2> grid) {
    return planarSampler(center, normal, up, size, grid);
}
const Vec3 kUp(0, 1, 0);
using test::kZ;

void expectWithin(const SamplerResult& r, double expected, double relativeSystematic, const std::string& what) {
    double tolerance = 4 * r.standardError + relativeSystematic * std::abs(expected);
    EXPECT_NEAR(r.value, expected, tolerance) << what << ": standard error " << r.standardError;
}

TEST(Analytic, RectEmitterIlluminanceInABlackVoid) {
    // A 0.6 x 0.6 m panel of 3000 lm at z = 3 facing down; planar samplers below it.
    const double flux = 3000, L = flux / (kPi * 0.36);
    SceneLab lab(withMaterials(0)
                     .emitter("panel", rectEmitter({0, 0, 3}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
                     .sampler("below", point({0, 0, 0.8}), 0, 1e9)
                     .sampler("offset", point({0.2, 0.1, 2.5}), 0, 1e9)
                     .sampler("beside", point({1.5, -0.7, 1.0}), 0, 1e9)
                     .build());
    auto r = lab.measure(4000);
    expectWithin(r.samplers[0], rectIlluminance(L, -0.3, 0.3, -0.3, 0.3, 0, 0, 2.2), 0, "below");
    expectWithin(r.samplers[1], rectIlluminance(L, -0.3, 0.3, -0.3, 0.3, 0.2, 0.1, 0.5), 0, "offset");
    // Outside the projection: the rectangle [x0,x1] seen from px > x1 is the difference of two.
    double px = 1.5, py = -0.7, h = 2.0;
    auto corner = [&](double dx, double dy) { return cornerIlluminance(L, std::abs(dx), std::abs(dy), h); };
    // Rectangle [x0,x1] x [y0,y1] with px > x1 and py < y0: inclusion-exclusion over corners.
    double E = corner(px + 0.3, py - 0.3) - corner(px - 0.3, py - 0.3) - corner(px + 0.3, py + 0.3) + corner(px - 0.3, py + 0.3);
    expectWithin(r.samplers[2], E, 0, "beside");
}

TEST(Analytic, ClosedGreyRoomEnergyBalance) {
    // Closed 4 x 3 x 2.5 m room of reflectance 0.6, a small sphere of 2000 lm in the middle.
    // Every lumen is absorbed after 1/(1 - rho) reflections on average, so the area-weighted
    // mean illuminance is flux / (A (1 - rho)). The 1 cm sphere absorbs 7e-6 of the area.
    const double rho = 0.6, flux = 2000;
    const double A = 2 * (4 * 3 + 4 * 2.5 + 3 * 2.5);
    SceneLab lab(withMaterials(rho)
                     .room({0, 0, 0}, {4, 3, 2.5}, "grey", "grey", "grey")
                     .emitter("bulb", sphereEmitter({2.1, 1.4, 1.3}, 0.01), 2000)
                     .sampler("floor", plane({2, 1.5, 0.001}, {0, 0, 1}, kUp, {4, 3}, {8, 6}), 0, 1e9)
                     .sampler("ceiling", plane({2, 1.5, 2.499}, {0, 0, -1}, kUp, {4, 3}, {8, 6}), 0, 1e9)
                     .sampler("south", plane({2, 0.001, 1.25}, {0, 1, 0}, kZ, {4, 2.5}, {8, 5}), 0, 1e9)
                     .sampler("north", plane({2, 2.999, 1.25}, {0, -1, 0}, kZ, {4, 2.5}, {8, 5}), 0, 1e9)
                     .sampler("west", plane({0.001, 1.5, 1.25}, {1, 0, 0}, kZ, {3, 2.5}, {6, 5}), 0, 1e9)
                     .sampler("east", plane({3.999, 1.5, 1.25}, {-1, 0, 0}, kZ, {3, 2.5}, {6, 5}), 0, 1e9)
                     .build());
    auto r = lab.measure(600);
    double areas[6] = {12, 12, 10, 10, 7.5, 7.5};
    double mean = 0, variance = 0;
    for (int k = 0; k < 6; ++k) {
        mean += areas[k] * r.samplers[k].value / A;
        variance += std::pow(areas[k] / A * r.samplers[k].standardError, 2);
    }
    double expected = flux / (A * (1 - rho));
    // The grid-point mean approximates each face's mean: 1% allowance for that quadrature.
    EXPECT_NEAR(mean, expected, 4 * std::sqrt(variance) + 0.01 * expected) << "sigma " << std::sqrt(variance);
}

TEST(Analytic, UniformSkyGivesPiL) {
    SceneLab lab(SceneBuilder()
                     .uniformSky(2000)
                     .sampler("up", plane({0, 0, 0}, kZ, kUp, {1, 1}, {2, 2}), 0)
                     .sampler("sphere", volumeSampler({0, 0, 1}, {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, 4), 0)
                     .build());
    auto r = lab.measure(2000);
    expectWithin(r.samplers[0], kPi * 2000, 1e-3, "planar");
    // Half the sphere sees the sky (2000), half the black ground.
    expectWithin(r.samplers[1], 1000, 1e-3, "volume");
}

TEST(Analytic, CieOvercastHorizontalAndVertical) {
    SceneLab lab(SceneBuilder()
                     .overcastSky(10000, 0)
                     .sampler("horizontal", plane({0, 0, 0}, kZ, kUp, {1, 1}, {1, 1}), 0)
                     .sampler("vertical", plane({0, 0, 0}, {1, 0, 0}, kZ, {1, 1}, {1, 1}), 0)
                     .build());
    auto r = lab.measure(20000);
    expectWithin(r.samplers[0], 10000, 2e-3, "horizontal");
    expectWithin(r.samplers[1], 0.396 * 10000, 3e-3, "vertical");
}

TEST(Analytic, GlazedOpeningScalesByThePanesTransmittance) {
    // Black room, uniform sky over a black ground, one window: E = L * integral over the
    // part of the window above the horizon of T(cos) cos dw.
    auto room = [](const std::string& pane) {
        return withMaterials(0)
            .uniformSky(1000)
            .room({0, 0, 0}, {4, 4, 3}, "black", "black", "black")
            .window(Wall::South, 1, 2, 1, 1.5, pane)
            .sampler("p", point({2, 1.5, 1.2}, {0, -1, 0}, kZ), 0)
            .build();
    };
    // Quadrature over the window (x in [1,3], z in [1,2.5] at y = 0) seen from (2, 1.5, 1.2).
    auto expected = [](double normalTransmittance) {
        const int n = 400;
        double sum = 0, dA = 2.0 * 1.5 / (n * n);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                Vec3 q(1 + 2.0 * (i + 0.5) / n, 0, 1 + 1.5 * (j + 0.5) / n);
                Vec3 d = q - Vec3(2, 1.5, 1.2);
                if (d.z <= 0) continue;  // below the horizon: the black ground
                double dist = length(d), cosR = -d.y / dist;  // receiver normal -y, window normal +y
                double T = normalTransmittance < 1 ? thinGlassTransmittance(cosR, normalTransmittance) : 1.0;
                sum += 1000 * T * cosR * cosR * dA / (dist * dist);
            }
        return sum;
    };
    SceneLab open(room(""));
    SceneLab glazed(room("glass"));
    auto ro = open.measure(4000), rg = glazed.measure(4000);
    expectWithin(ro.samplers[0], expected(1.0), 1e-3, "open");
    expectWithin(rg.samplers[0], expected(0.8), 1e-3, "glazed");
}

TEST(Analytic, WindowPanesAndGlassFurnitureMultiplyTheirTransmittances) {
    // The window's pane is crossed analytically (pathtracer/panes.h), a glass sheet in
    // front of the sensor by Embree: parallel to the window, its two faces and the pane
    // each pass T(cos) of the same angle.
    const Scene scene = withMaterials(0)
                            .uniformSky(1000)
                            .room({0, 0, 0}, {4, 4, 3}, "black", "black", "black")
                            .window(Wall::South, 1, 2, 1, 1.5, "glass")
                            .box("sheet", {0.5, 0.9, 0.5}, {3.5, 0.92, 3}, "glass")
                            .sampler("p", point({2, 1.5, 1.2}, {0, -1, 0}, kZ), 0)
                            .build();
    const int n = 400;
    double expected = 0, dA = 2.0 * 1.5 / (n * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            Vec3 d = Vec3(1 + 2.0 * (i + 0.5) / n, 0, 1 + 1.5 * (j + 0.5) / n) - Vec3(2, 1.5, 1.2);
            if (d.z <= 0) continue;
            double dist = length(d), cosR = -d.y / dist;
            expected += 1000 * std::pow(thinGlassTransmittance(cosR, 0.8), 3) * cosR * cosR * dA / (dist * dist);
        }
    expectWithin(SceneLab(scene).measure(4000).samplers[0], expected, 1e-3, "pane and sheet");
}

TEST(Analytic, SeveralPortalsSumTheirProjectedSolidAngles) {
    // Black room, uniform sky over a black ground, two windows on different walls, a
    // door and a skylight: an upward sensor gets L times the projected solid angle of
    // the openings above its horizon. Portal sampling (one opening by weight, then its
    // spherical rectangle) and plain sky-map sampling must both give it.
    const Scene scene = withMaterials(0)
                            .uniformSky(1000)
                            .room({0, 0, 0}, {4, 4, 3}, "black", "black", "black")
                            .window(Wall::South, 1, 2, 1, 1.5)
                            .window(Wall::East, 0.5, 1, 1.2, 1)
                            .window(Wall::North, 2.5, 1, 0, 2.1)
                            .skylight({1.5, 2.5}, {0.8, 0.6})
                            .sampler("p", point({2, 1.6, 1.0}), 0)
                            .build();
    // Quadrature of L cos(receiver) cos(opening) dA / d^2 over each opening.
    const Vec3 p(2, 1.6, 1.0);
    auto opening = [&](Vec3 corner, Vec3 u, Vec3 v, Vec3 normal) {
        const int n = 300;
        double sum = 0, dA = length(u) * length(v) / (n * n);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                Vec3 d = corner + u * ((i + 0.5) / n) + v * ((j + 0.5) / n) - p;
                double dist = length(d);
                if (d.z <= 0) continue;  // below the horizon: the receiver does not see it
                sum += 1000 * (d.z / dist) * std::abs(dot(d, normal)) / dist * dA / (dist * dist);
            }
        return sum;
    };
    double expected = opening({1, 0, 1}, {2, 0, 0}, {0, 0, 1.5}, {0, 1, 0}) +     // south
                      opening({4, 0.5, 1.2}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}) +   // east
                      opening({2.5, 4, 0}, {1, 0, 0}, {0, 0, 2.1}, {0, 1, 0}) +   // north door
                      opening({1.1, 2.2, 3}, {0.8, 0, 0}, {0, 0.6, 0}, {0, 0, 1});  // skylight
    PathTracerOptions noPortals;
    noPortals.portals = false;
    SceneLab portals(scene), skyMap(scene, noPortals);
    SamplerResult a = portals.measure(20000).samplers[0], b = skyMap.measure(20000).samplers[0];
    expectWithin(a, expected, 2e-3, "portals");
    expectWithin(b, expected, 5e-3, "sky map");  // the map's pixels cut the opening edges
    EXPECT_LT(a.standardError, 0.5 * b.standardError);
}

// An opening closed by an opaque panel (a door) is not a portal: the sky is sampled
// through the open window alone, exactly as if the door were wall.
TEST(Portals, AnOpeningClosedByAnOpaquePanelIsNotOne) {
    auto scene = [](bool door) {
        SceneBuilder b = withMaterials(0.5);
        b.uniformSky(1000).room({0, 0, 0}, {4, 4, 3}, "grey", "grey", "grey").window(Wall::South, 1, 2, 1, 1.5);
        if (door) b.window(Wall::North, 1, 1.5, 0, 2.1, "grey");
        return b.sampler("p", point({2, 2, 0.8}), 0).build();
    };
    SceneLab closed(scene(true));
    SkyLight sky(closed.scene, &*closed.daylight, true);
    SkyLight::View view;
    sky.view({2, 2, 0.8}, view);
    EXPECT_TRUE(view.active);
    EXPECT_EQ(view.count, 1);
    SamplerResult withDoor = closed.measure(2000).samplers[0];
    SamplerResult without = SceneLab(scene(false)).measure(2000).samplers[0];
    EXPECT_NEAR(withDoor.value, without.value, 4 * std::hypot(withDoor.standardError, without.standardError));
}

TEST(Analytic, SunPatchFallsWhereGeometryPutsIt) {
    // Sun from the south at 45 degrees through a 2 x 1 m opening with sill 1 m: the patch
    // on the floor spans x in [2, 4], y in [1, 2] (up to the disk's half-degree blur).
    DaylightParams sun;
    sun.model = SkyModelType::Uniform;
    sun.luminanceNits = 0;
    sun.sunOverride = SunOverride{45, 180, 50000};
    sun.groundReflectance = 0;
    SceneLab lab(withMaterials(0)
                     .daylight(sun)
                     .room({0, 0, 0}, {6, 4, 3}, "black", "black", "black")
                     .window(Wall::South, 2, 2, 1, 1)
                     .sampler("in", plane({3, 1.5, 0.001}, kZ, kUp, {0.6, 0.3}, {3, 2}), 0)
                     .sampler("out", plane({3, 3, 0.001}, kZ, kUp, {1, 0.5}, {2, 2}), 0)
                     .sampler("side", plane({1, 1.5, 0.001}, kZ, kUp, {0.5, 0.5}, {2, 2}), 0)
                     .build());
    auto r = lab.measure(200);
    expectWithin(r.samplers[0], 50000 * std::sin(radians(45)), 2e-3, "in the patch");
    EXPECT_EQ(r.samplers[1].value, 0.0);
    EXPECT_EQ(r.samplers[2].value, 0.0);
}

TEST(Analytic, GlossyScreenFacingAWindowGlaresMoreThanAMatteOne) {
    auto screen = [](const char* material) {
        return SceneBuilder()
            .material("wall", test::diffuse(0.5))
            .material("glossy", test::glossy(0.05, 0.05, 0.02))
            .material("matte", test::diffuse(0.07))
            .overcastSky(20000, 0.2)
            .room({0, 0, 0}, {5, 5, 3}, "wall", "wall", "wall")
            .window(Wall::South, 1.5, 2, 0.8, 1.8)
            .entity("monitor", {2.5, 2.5, 0}, 0)
            .part({0.6, 0.02, 0.4}, material, Vec3(0, 0, 1.1))
            .sampler("glare", directionalSampler({0, -0.7, 1.2}, {0, 1, -0.05}, kZ, 20, 4), 0, 100)
            .end()
            .build();
    };
    // The screen's front (-y) faces the window; the viewer stands between them and sees
    // the window mirrored in the screen.
    SceneLab glossy(screen("glossy")), matte(screen("matte"));
    double g = glossy.measure(400).samplers[0].value, m = matte.measure(400).samplers[0].value;
    EXPECT_GT(g, 2 * m) << "glossy " << g << " matte " << m;
}

TEST(Determinism, SameResultWithOneAndTwoThreads) {
    SceneLab lab(withMaterials(0.5)
                     .overcastSky(10000)
                     .room({0, 0, 0}, {4, 3, 2.5}, "grey", "grey", "grey")
                     .window(Wall::South, 1, 2, 0.8, 1.2, "glass")
                     .emitter("l", diskEmitter({2, 1.5, 2.49}, {0, 0, -1}, 0.2), 2000)
                     .sampler("p", plane({2, 1.5, 0.75}, kZ, kUp, {1, 1}, {3, 3}), 300, 500)
                     .sampler("v", volumeSampler({2, 1.5, 1.2}, {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, 5), 0)
                     .sampler("d", directionalSampler({2, 2.5, 1.2}, {0, -1, 0}, kZ, 60, 3), 0, 100)
                     .build());
    auto one = test::withThreads(1, [&] { return lab.measure(64, 7); });
    auto two = test::withThreads(2, [&] { return lab.measure(64, 7); });
    for (size_t k = 0; k < one.samplers.size(); ++k) {
        EXPECT_EQ(one.samplers[k].points, two.samplers[k].points);
        EXPECT_GT(one.samplers[k].value, 0);
    }
    EXPECT_NE(lab.measure(64, 8).samplers[0].value, one.samplers[0].value);
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// Twelve panels along a corridor; the point sits under the first. Choosing emitters by
// flux / distance^2 must give the same illuminance as a uniform choice, with less noise.
TEST(EmitterSelection, PowerDistanceAgreesWithUniformAndHasLessVariance) {
    SceneBuilder corridor;
    for (int i = 0; i < 12; ++i)
        corridor.emitter(std::string(1, 'l').append(std::to_string(i)), rectEmitter({double(1 + 2 * i), 1, 2.9}, {0, 0, -1}, {0, 1, 0}, {0.5, 0.5}), 2000);
    const Scene scene = corridor.sampler("p", point({1, 1, 0.8}), 0).build();
    PathTracerOptions uniform;
    uniform.emitterSelection = EmitterSelection::Uniform;
    SceneLab byPower(scene), byUniform(scene, uniform);
    SamplerResult a = byPower.measure(20000).samplers[0], b = byUniform.measure(20000).samplers[0];
    EXPECT_NEAR(a.value, b.value, 4 * std::hypot(a.standardError, b.standardError));
    EXPECT_LT(a.standardError, 0.5 * b.standardError);
}

// Luminaires shadow one another as a path sees them: a point under a panel that
// faces away (its dark back) and another panel above it that faces the point gets no
// light at all; with the first panel moved aside, the second one's analytic value.
TEST(EmitterShadows, ALuminaireBlocksTheLightOfAnotherBehindIt) {
    const double flux = 4000, side = 0.6, h = 2.5 - 0.8;
    auto scene = [&](double lowerX) {
        return SceneBuilder()
            .emitter("facing_up", rectEmitter({lowerX, 0, 2}, {0, 0, 1}, {0, 1, 0}, {1, 1}), flux)
            .emitter("facing_down", rectEmitter({0, 0, 2.5}, {0, 0, -1}, {0, 1, 0}, {side, side}), flux)
            .sampler("p", point({0, 0, 0.8}), 0)
            .build();
    };
    EXPECT_EQ(SceneLab(scene(0)).measure(2000).samplers[0].value, 0.0);
    SamplerResult aside = SceneLab(scene(5)).measure(2000).samplers[0];
    const double L = flux / (kPi * side * side);
    expectWithin(aside, rectIlluminance(L, -side / 2, side / 2, -side / 2, side / 2, 0, 0, h), 2e-3, "unblocked");
}

// A panel never shadows its own light, however near the point is to its plane (the
// shadow ray then steps past the panel's own hit instead of stopping short of it in
// one query), and a bulb hidden behind a larger one sends nothing past it.
TEST(EmitterShadows, ALuminaireNeverShadowsItselfNearOrFar) {
    const double flux = 3000, side = 0.6, L = flux / (kPi * side * side);
    for (double h : {1e-3, 0.05, 1.0}) {
        SceneLab lab(SceneBuilder()
                         .emitter("above", rectEmitter({0, 0, 2.5}, {0, 0, -1}, {0, 1, 0}, {side, side}), flux)
                         .emitter("aside", rectEmitter({10, 0, 2.5}, {0, 0, -1}, {0, 1, 0}, {side, side}), flux)
                         .sampler("p", point({0, 0, 2.5 - h}), 0)
                         .build());
        const double s = side / 2;
        expectWithin(lab.measure(2000).samplers[0],
                     rectIlluminance(L, -s, s, -s, s, 0, 0, h) + rectIlluminance(L, 10 - s, 10 + s, -s, s, 0, 0, h), 2e-3,
                     "h = " + std::to_string(h));
    }
    // Spheres: 0.3 m across at 1 m hides one of 0.05 m at 2 m (E = flux / 4 pi d^2).
    SceneLab bulbs(SceneBuilder()
                       .emitter("near", sphereEmitter({0, 0, 1}, 0.3), flux)
                       .emitter("hidden", sphereEmitter({0, 0, 2}, 0.05), flux)
                       .sampler("p", point({0, 0, 0}), 0)
                       .build());
    expectWithin(bulbs.measure(4000).samplers[0], flux / (4 * kPi), 2e-3, "bulbs");
}

// A sampler point lying on a surface (a work plane at a desk's top, carried by a
// rotated entity: a micron off either way) must see the light above it, not the
// surface it lies on: rays from a sensor skip their first 0.1 mm.
TEST(SensorOnASurface, SeesTheLightAboveIt) {
    const double flux = 1000, h = 1.0;
    for (double z : {0.0, 0.75}) {
        SceneLab lab(withMaterials(0)
                         .box("top", {-2, -2, z - 0.05}, {2, 2, z}, "black")
                         .emitter("bulb", sphereEmitter({0.3, 0.2, z + h}, 0.05), flux)
                         .sampler("p", plane({0.3, 0.2, z - 1e-6}, kZ, kUp, {0.4, 0.4}, {4, 4}), 0)
                         .build());
        SamplerResult r = lab.measure(400).samplers[0];
        // Points at (+-0.05, +-0.15) from below the bulb: E = I cos / d^2 = I h / d^3.
        double expected = 0;
        for (double dx : {-0.15, -0.05, 0.05, 0.15})
            for (double dy : {-0.15, -0.05, 0.05, 0.15}) {
                double d = std::sqrt(dx * dx + dy * dy + h * h);
                expected += flux / (4 * kPi) * h / (d * d * d) / 16;
            }
        expectWithin(r, expected, 1e-3, "work plane at z = " + std::to_string(z));
    }
}

// A stand lamp carried by a movable entity lights the table it is moved to.
TEST(CarriedEmitters, FollowTheLayout) {
    SceneLab lab(SceneBuilder()
                     .entity("lamp", {0, 0, 0})
                     .region({0, 0}, {10, 0})
                     .emitter("bulb", sphereEmitter({0, 0, 1.5}, 0.05), 1000)
                     .end()
                     .sampler("p", point({5, 0, 0.75}), 0)
                     .build());
    double far = lab.measure(2000).samplers[0].value;
    Layout layout = initialLayout(lab.scene);
    layout.placements[0].position = {5, 0, 0};
    lab.rt->setLayout(layout);
    lab.tracer->updateLayout();
    SamplerResult near = lab.measure(2000).samplers[0];
    // A point source of 1000 lm at 0.75 m straight above: E = (1000 / 4 pi) / 0.75^2.
    EXPECT_NEAR(near.value, 1000 / (4 * kPi) / (0.75 * 0.75), 4 * near.standardError + 1e-3 * near.value);
    EXPECT_LT(far, 0.01 * near.value);
}

}  // namespace
}  // namespace luxplan
