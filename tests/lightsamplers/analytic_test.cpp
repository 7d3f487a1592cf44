// The light samplers against analytic truth, with tolerances from the estimator's own
// standard error (4 sigma) plus, where a model is tabulated, its stated discretization.
#include <gtest/gtest.h>

#include <luxplan/materials/thin_glass.h>
#include "support/lab.h"
#include "support/threads.h"

namespace luxplan {
namespace {

std::string materials(double rho) {
    return R"("materials": {"grey": {"type": "diffuse", "reflectance": )" + std::to_string(rho) +
           R"(}, "black": {"type": "diffuse", "reflectance": 0}, "glass": {"type": "glass", "transmittance": 0.8}})";
}

// Illuminance at a point at height h below one corner of an a x b Lambertian rectangle
// of luminance L, parallel to the receiver: E = L/2 [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) +
// Y/sqrt(1+Y^2) atan(X/sqrt(1+Y^2))] with X = a/h, Y = b/h (the classic configuration factor).
double cornerIlluminance(double L, double a, double b, double h) {
    double X = a / h, Y = b / h;
    return L / 2 *
           (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
            Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)));
}
// Any point whose projection falls inside the rectangle [x0,x1] x [y0,y1]: four corners.
double rectIlluminance(double L, double x0, double x1, double y0, double y1, double px, double py, double h) {
    return cornerIlluminance(L, px - x0, py - y0, h) + cornerIlluminance(L, x1 - px, py - y0, h) +
           cornerIlluminance(L, px - x0, y1 - py, h) + cornerIlluminance(L, x1 - px, y1 - py, h);
}

void expectWithin(const SamplerResult& r, double expected, double relativeSystematic, const std::string& what) {
    double tolerance = 4 * r.standardError + relativeSystematic * std::abs(expected);
    EXPECT_NEAR(r.value, expected, tolerance) << what << ": standard error " << r.standardError;
}

TEST(Analytic, RectEmitterIlluminanceInABlackVoid) {
    // A 0.6 x 0.6 m panel of 3000 lm at z = 3 facing down; planar samplers below it.
    const double flux = 3000, L = flux / (kPi * 0.36);
    std::string json = R"({"luxplan": 1, )" + materials(0) + R"(,
      "luminaires": [{"name": "panel", "shape": "rect", "center": [0,0,3], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 3000}],
      "samplers": [
        {"name": "below", "type": "planar", "center": [0,0,0.8], "size": [0.001,0.001], "grid": [1,1], "target": [0,1e9]},
        {"name": "offset", "type": "planar", "center": [0.2,0.1,2.5], "size": [0.001,0.001], "grid": [1,1], "target": [0,1e9]},
        {"name": "beside", "type": "planar", "center": [1.5,-0.7,1.0], "size": [0.001,0.001], "grid": [1,1], "target": [0,1e9]}]})";
    test::Lab lab(json);
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
    std::string json = R"({"luxplan": 1, )" + materials(rho) + R"(,
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [4,3,2.5]},
                    "materials": {"floor": "grey", "walls": "grey", "ceiling": "grey"}}],
      "luminaires": [{"name": "bulb", "shape": "sphere", "center": [2.1,1.4,1.3], "radius": 0.01, "flux_lm": 2000}],
      "samplers": [
        {"name": "floor", "type": "planar", "center": [2,1.5,0.001], "normal": [0,0,1], "size": [4,3], "grid": [8,6], "target": [0,1e9]},
        {"name": "ceiling", "type": "planar", "center": [2,1.5,2.499], "normal": [0,0,-1], "size": [4,3], "grid": [8,6], "target": [0,1e9]},
        {"name": "south", "type": "planar", "center": [2,0.001,1.25], "normal": [0,1,0], "up": [0,0,1], "size": [4,2.5], "grid": [8,5], "target": [0,1e9]},
        {"name": "north", "type": "planar", "center": [2,2.999,1.25], "normal": [0,-1,0], "up": [0,0,1], "size": [4,2.5], "grid": [8,5], "target": [0,1e9]},
        {"name": "west", "type": "planar", "center": [0.001,1.5,1.25], "normal": [1,0,0], "up": [0,0,1], "size": [3,2.5], "grid": [6,5], "target": [0,1e9]},
        {"name": "east", "type": "planar", "center": [3.999,1.5,1.25], "normal": [-1,0,0], "up": [0,0,1], "size": [3,2.5], "grid": [6,5], "target": [0,1e9]}]})";
    test::Lab lab(json);
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
    test::Lab lab(R"({"luxplan": 1, "daylight": {"sky": {"model": "uniform", "luminance_nits": 2000}, "sun": false, "ground_reflectance": 0},
      "samplers": [{"name": "up", "type": "planar", "center": [0,0,0], "size": [1,1], "grid": [2,2], "target": [0, null]},
                   {"name": "sphere", "type": "volume", "center": [0,0,1], "axes": [[1,0,0],[0,1,0],[0,0,1]], "points": 4, "target": [0, null]}]})");
    auto r = lab.measure(2000);
    expectWithin(r.samplers[0], kPi * 2000, 1e-3, "planar");
    // Half the sphere sees the sky (2000), half the black ground.
    expectWithin(r.samplers[1], 1000, 1e-3, "volume");
}

TEST(Analytic, CieOvercastHorizontalAndVertical) {
    test::Lab lab(R"({"luxplan": 1, "daylight": {"sky": {"model": "cie_overcast", "horizontal_illuminance_lx": 10000}, "ground_reflectance": 0},
      "samplers": [{"name": "horizontal", "type": "planar", "center": [0,0,0], "size": [1,1], "grid": [1,1], "target": [0, null]},
                   {"name": "vertical", "type": "planar", "center": [0,0,0], "normal": [1,0,0], "up": [0,0,1], "size": [1,1], "grid": [1,1], "target": [0, null]}]})");
    auto r = lab.measure(20000);
    expectWithin(r.samplers[0], 10000, 2e-3, "horizontal");
    expectWithin(r.samplers[1], 0.396 * 10000, 3e-3, "vertical");
}

TEST(Analytic, GlazedOpeningScalesByThePanesTransmittance) {
    // Black room, uniform sky over a black ground, one window: E = L * integral over the
    // part of the window above the horizon of T(cos) cos dw.
    auto room = [](const std::string& pane) {
        return R"({"luxplan": 1, )" + materials(0) + R"(,
          "daylight": {"sky": {"model": "uniform", "luminance_nits": 1000}, "sun": false, "ground_reflectance": 0},
          "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [4,4,3]},
                        "materials": {"floor": "black", "walls": "black", "ceiling": "black"},
                        "openings": [{"wall": "south", "offset": 1, "width": 2, "sill": 1, "height": 1.5)" + pane + R"(}]}],
          "samplers": [{"name": "p", "type": "planar", "center": [2,1.5,1.2], "normal": [0,-1,0], "up": [0,0,1],
                        "size": [0.001,0.001], "grid": [1,1], "target": [0, null]}]})";
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
    test::Lab open(room(""));
    test::Lab glazed(room(R"(, "material": "glass")"));
    auto ro = open.measure(4000), rg = glazed.measure(4000);
    expectWithin(ro.samplers[0], expected(1.0), 1e-3, "open");
    expectWithin(rg.samplers[0], expected(0.8), 1e-3, "glazed");
}

TEST(Analytic, SeveralPortalsSumTheirProjectedSolidAngles) {
    // Black room, uniform sky over a black ground, two windows on different walls, a
    // door and a skylight: an upward sensor gets L times the projected solid angle of
    // the openings above its horizon. Portal sampling (one opening by weight, then its
    // spherical rectangle) and plain sky-map sampling must both give it.
    const std::string json = R"({"luxplan": 1, )" + materials(0) + R"(,
      "daylight": {"sky": {"model": "uniform", "luminance_nits": 1000}, "sun": false, "ground_reflectance": 0},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [4,4,3]},
                    "materials": {"floor": "black", "walls": "black", "ceiling": "black"},
                    "openings": [{"wall": "south", "offset": 1, "width": 2, "sill": 1, "height": 1.5},
                                 {"wall": "east", "offset": 0.5, "width": 1, "sill": 1.2, "height": 1},
                                 {"wall": "north", "offset": 2.5, "width": 1, "sill": 0, "height": 2.1},
                                 {"wall": "ceiling", "center": [1.5, 2.5], "size": [0.8, 0.6]}]}],
      "samplers": [{"name": "p", "type": "planar", "center": [2,1.6,1.0], "size": [0.001,0.001], "grid": [1,1], "target": [0, null]}]})";
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
    test::Lab portals(json), skyMap(json, noPortals);
    SamplerResult a = portals.measure(20000).samplers[0], b = skyMap.measure(20000).samplers[0];
    expectWithin(a, expected, 2e-3, "portals");
    expectWithin(b, expected, 5e-3, "sky map");  // the map's pixels cut the opening edges
    EXPECT_LT(a.standardError, 0.5 * b.standardError);
}

TEST(Analytic, SunPatchFallsWhereGeometryPutsIt) {
    // Sun from the south at 45 degrees through a 2 x 1 m opening with sill 1 m: the patch
    // on the floor spans x in [2, 4], y in [1, 2] (up to the disk's half-degree blur).
    test::Lab lab(R"({"luxplan": 1, )" + materials(0) + R"(,
      "daylight": {"sky": {"model": "uniform", "luminance_nits": 0}, "sun": {"altitude_deg": 45, "azimuth_deg": 180, "normal_illuminance_lx": 50000},
                   "ground_reflectance": 0},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                    "materials": {"floor": "black", "walls": "black", "ceiling": "black"},
                    "openings": [{"wall": "south", "offset": 2, "width": 2, "sill": 1, "height": 1}]}],
      "samplers": [{"name": "in", "type": "planar", "center": [3,1.5,0.001], "size": [0.6,0.3], "grid": [3,2], "target": [0, null]},
                   {"name": "out", "type": "planar", "center": [3,3,0.001], "size": [1,0.5], "grid": [2,2], "target": [0, null]},
                   {"name": "side", "type": "planar", "center": [1,1.5,0.001], "size": [0.5,0.5], "grid": [2,2], "target": [0, null]}]})");
    auto r = lab.measure(200);
    expectWithin(r.samplers[0], 50000 * std::sin(radians(45)), 2e-3, "in the patch");
    EXPECT_EQ(r.samplers[1].value, 0.0);
    EXPECT_EQ(r.samplers[2].value, 0.0);
}

TEST(Analytic, GlossyScreenFacingAWindowGlaresMoreThanAMatteOne) {
    auto screen = [](const char* material) {
        return std::string(R"({"luxplan": 1, "materials": {"wall": {"type": "diffuse", "reflectance": 0.5},
            "glossy": {"type": "glossy", "reflectance": 0.05, "roughness": 0.05, "base": 0.02},
            "matte": {"type": "diffuse", "reflectance": 0.07}},
          "daylight": {"sky": {"model": "cie_overcast", "horizontal_illuminance_lx": 20000}, "ground_reflectance": 0.2},
          "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [5,5,3]},
                        "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"},
                        "openings": [{"wall": "south", "offset": 1.5, "width": 2, "sill": 0.8, "height": 1.8}]}],
          "entities": [{"name": "monitor", "position": [2.5, 2.5], "rotation": 0,
                        "parts": [{"box": {"size": [0.6, 0.02, 0.4], "center": [0, 0, 1.1]}, "material": ")") + material + R"("}],
                        "samplers": [{"name": "glare", "type": "directional", "origin": [0, -0.7, 1.2], "direction": [0, 1, -0.05],
                                      "fov_deg": 20, "strata": 4, "target": [0, 100]}]}]})";
    };
    // The screen's front (-y) faces the window; the viewer stands between them and sees
    // the window mirrored in the screen.
    test::Lab glossy(screen("glossy")), matte(screen("matte"));
    double g = glossy.measure(400).samplers[0].value, m = matte.measure(400).samplers[0].value;
    EXPECT_GT(g, 2 * m) << "glossy " << g << " matte " << m;
}

TEST(Determinism, SameResultWithOneAndTwoThreads) {
    test::Lab lab(R"({"luxplan": 1, )" + materials(0.5) + R"(,
      "daylight": {"sky": {"model": "cie_overcast", "horizontal_illuminance_lx": 10000}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [4,3,2.5]},
                    "materials": {"floor": "grey", "walls": "grey", "ceiling": "grey"},
                    "openings": [{"wall": "south", "offset": 1, "width": 2, "sill": 0.8, "height": 1.2, "material": "glass"}]}],
      "luminaires": [{"name": "l", "shape": "disk", "center": [2,1.5,2.49], "normal": [0,0,-1], "radius": 0.2, "flux_lm": 2000}],
      "samplers": [{"name": "p", "type": "planar", "center": [2,1.5,0.75], "size": [1,1], "grid": [3,3], "target": [300, 500]},
                   {"name": "v", "type": "volume", "center": [2,1.5,1.2], "axes": [[1,0,0],[0,1,0],[0,0,1]], "points": 5, "target": [0, null]},
                   {"name": "d", "type": "directional", "origin": [2,2.5,1.2], "direction": [0,-1,0], "strata": 3, "target": [0, 100]}]})");
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
    std::string luminaires;
    for (int i = 0; i < 12; ++i)
        luminaires += std::string(i ? "," : "") + R"({"name": "l)" + std::to_string(i) + R"(", "shape": "rect", "center": [)" +
                      std::to_string(1 + 2 * i) + R"(,1,2.9], "normal": [0,0,-1], "size": [0.5,0.5], "flux_lm": 2000})";
    std::string json = R"({"luxplan": 1, "luminaires": [)" + luminaires + R"(],
      "samplers": [{"name": "p", "type": "planar", "center": [1,1,0.8], "size": [0.001,0.001], "grid": [1,1], "target": [0, null]}]})";
    PathTracerOptions uniform;
    uniform.emitterSelection = EmitterSelection::Uniform;
    test::Lab byPower(json), byUniform(json, uniform);
    SamplerResult a = byPower.measure(20000).samplers[0], b = byUniform.measure(20000).samplers[0];
    EXPECT_NEAR(a.value, b.value, 4 * std::hypot(a.standardError, b.standardError));
    EXPECT_LT(a.standardError, 0.5 * b.standardError);
}

// A stand lamp carried by a movable entity lights the table it is moved to.
TEST(CarriedEmitters, FollowTheLayout) {
    test::Lab lab(R"({"luxplan": 1,
      "entities": [{"name": "lamp", "position": [0, 0],
                    "placement": {"regions": [{"min": [0,0], "max": [10,0]}]},
                    "emitters": [{"name": "bulb", "shape": "sphere", "center": [0,0,1.5], "radius": 0.05, "flux_lm": 1000}]}],
      "samplers": [{"name": "p", "type": "planar", "center": [5,0,0.75], "size": [0.001,0.001], "grid": [1,1], "target": [0, null]}]})");
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
