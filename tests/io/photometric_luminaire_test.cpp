// Photometric luminaires through the loader: "photometry" on a fixed luminaire and
// on a carried emitter, "c0", "flux_lm" scaling, the file's errors through the
// scene's JSON path; and the truth: far from a small opening, E = I cos(incidence) /
// d^2 at the file's own angles, from the path tracer and from the emitters directly.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/core/error.h>
#include <luxplan/emitters/photometric_emitter.h>
#include <luxplan/io/scene_loader.h>
#include "support/scene_lab.h"
#include "support/temp_files.h"
#include "support/test_data.h"

namespace luxplan {
namespace {

using nlohmann::json;

using test::kPhotometryFiles;
constexpr double kDeg = kPi / 180;

// A scene of the given luminaires (and entities) in a black void.
Scene loadLuminaires(const json& luminaires, test::TempDir& dir, const json& entities = json::array()) {
    json s = {{"luxplan", 1}, {"luminaires", luminaires}, {"entities", entities}};
    return io::loadScene(dir.write("scene.json", s.dump(2)));
}
std::vector<std::string> luminaireProblems(const json& luminaires, test::TempDir& dir) {
    try {
        loadLuminaires(luminaires, dir);
    } catch (const SceneError& e) {
        std::vector<std::string> out;
        for (const auto& d : e.diagnostics()) out.push_back(d.jsonPath + ": " + d.message);
        return out;
    }
    return {};
}

// A 2 mm downlight opening at (0, 0, 3), C 0 towards +x (so C 90 towards +y).
json downlight(const std::string& file) {
    return {{"name", "dl"}, {"shape", "disk"}, {"center", {0, 0, 3}}, {"normal", {0, 0, -1}}, {"radius", 0.002},
            {"c0", {1, 0, 0}}, {"photometry", kPhotometryFiles + file}};
}

// Unit direction of (C, gamma) for that downlight.
Vec3 towards(double cDeg, double gammaDeg) {
    double c = cDeg * kDeg, g = gammaDeg * kDeg;
    return {std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), -std::cos(g)};
}

struct Truth {
    double maxRelativeError = 0;
};

// Illuminance at d = 2 m in direction (C, gamma) on a plane facing the luminaire
// and on a horizontal one, by the path tracer and by sampling the emitters, against
// `candela(C, gamma)` as the file lists it.
Truth checkInverseSquare(const Scene& scene, const std::vector<double>& cs, const std::vector<double>& gammas,
                         const std::function<double(double, double)>& candela) {
    test::SceneLab lab(scene);
    const EmitterSet& set = lab.tracer->emitters();
    const double d = 2;
    Truth t;
    Rng rng(21);
    RayStats stats;
    for (double c : cs)
        for (double g : gammas) {
            Vec3 w = towards(c, g), p = Vec3(0, 0, 3) + w * d;
            for (Vec3 n : {-w, Vec3(0, 0, 1)}) {
                double expected = candela(c, g) * dot(-w, n) / (d * d);
                double traced = 0, direct = 0;
                const int paths = 400;
                for (int k = 0; k < paths; ++k) {
                    traced += lab.tracer->illuminanceSample(p, n, rng, stats) / paths;
                    EmitterSample s = set.sample(p, rng.uniform(), {rng.uniform(), rng.uniform()});
                    if (s.emitter >= 0) direct += s.Lv * std::max(0.0, dot(s.wi, n)) / s.pdf / paths;
                }
                std::string where = "C " + std::to_string(c) + " gamma " + std::to_string(g);
                if (expected == 0) {
                    EXPECT_NEAR(traced, 0, 1e-9) << where;
                    continue;
                }
                EXPECT_NEAR(traced, expected, 0.01 * expected) << where;
                EXPECT_NEAR(direct, expected, 0.01 * expected) << where;
                t.maxRelativeError = std::max({t.maxRelativeError, std::abs(traced / expected - 1), std::abs(direct / expected - 1)});
            }
        }
    return t;
}

TEST(PhotometricLuminaire, InverseSquareFromAnAsymmetricIesFile) {
    test::TempDir dir;
    Scene s = loadLuminaires(json::array({downlight("asymmetric.ies")}), dir);
    // The file's candela (x 0.5) by plane, at gamma 0, 30, 60, 90.
    std::map<double, std::vector<double>> file = {
        {0, {1000, 800, 400, 0}}, {90, {1000, 600, 200, 0}}, {180, {1000, 500, 100, 0}}, {270, {1000, 700, 300, 0}}};
    Truth t = checkInverseSquare(s, {0, 90, 180, 270}, {0, 30, 60, 90},
                                 [&](double c, double g) { return file[c][size_t(g / 30)]; });
    RecordProperty("max_relative_error", std::to_string(t.maxRelativeError));
    std::cout << "asymmetric.ies: max relative error " << t.maxRelativeError << "\n";
    // C 90 is +y, as the contract says for c0 = +x facing down: 600 cd at gamma 30.
    test::SceneLab lab(s);
    Vec3 p(0, 2 * std::sin(30 * kDeg), 3 - 2 * std::cos(30 * kDeg));
    Rng rng(2);
    RayStats stats;
    double E = 0;
    for (int k = 0; k < 200; ++k) E += lab.tracer->illuminanceSample(p, normalize(Vec3(0, 0, 3) - p), rng, stats) / 200;
    EXPECT_NEAR(E, 600 / 4.0, 1.5);
}

TEST(PhotometricLuminaire, InverseSquareFromAnAsymmetricEulumdatFile) {
    test::TempDir dir;
    Scene s = loadLuminaires(json::array({downlight("asymmetric.ldt")}), dir);
    // cd/klm x 2000 lm / 1000.
    std::map<double, std::vector<double>> file = {
        {0, {1000, 800, 400, 0}}, {90, {1000, 500, 150, 0}}, {180, {1000, 700, 300, 0}}, {270, {1000, 900, 500, 0}}};
    Truth t = checkInverseSquare(s, {0, 90, 180, 270}, {0, 30, 60, 90},
                                 [&](double c, double g) { return file[c][size_t(g / 30)]; });
    std::cout << "asymmetric.ldt: max relative error " << t.maxRelativeError << "\n";
}

TEST(PhotometricLuminaire, FluxComesFromTheFileOrScalesToFluxLm) {
    test::TempDir dir;
    json a = downlight("asymmetric.ies"), b = downlight("asymmetric.ies");
    b["name"] = "scaled";
    b["flux_lm"] = 1200;
    Scene s = loadLuminaires(json::array({a, b}), dir);
    auto* luminaire = dynamic_cast<const PhotometricEmitter*>(s.emitters[0].shape.get());
    ASSERT_NE(luminaire, nullptr);
    const double fileFlux = luminaire->distribution().flux();
    EXPECT_DOUBLE_EQ(s.emitters[0].fluxLm, fileFlux);
    EXPECT_DOUBLE_EQ(s.emitters[1].fluxLm, 1200);
    EXPECT_EQ(s.emitters[0].shape->describe(), "disk of radius 0.002 m, photometric (" + kPhotometryFiles + "asymmetric.ies)");
    EmitterSet set(s, {}, EmitterSelection::PowerDistance);
    Vec3 w = -towards(90, 30);
    EXPECT_NEAR(set.emitted(1, w) / set.emitted(0, w), 1200 / fileFlux, 1e-12);
    // One file read for both luminaires.
    EXPECT_EQ(&luminaire->distribution(), &dynamic_cast<const PhotometricEmitter*>(s.emitters[1].shape.get())->distribution());
}

TEST(PhotometricLuminaire, CarriedEmitterTurnsWithItsEntity) {
    test::TempDir dir;
    json lamp = downlight("asymmetric.ies");
    lamp["center"] = {0, 0, 2};
    json entity = {{"name", "lamp"}, {"position", {1, 1}}, {"rotation", 90}, {"emitters", json::array({lamp})}};
    Scene s = loadLuminaires(json::array(), dir, json::array({entity}));
    ASSERT_EQ(s.emitters.size(), 1u);
    EXPECT_EQ(s.emitters[0].entity, 0);
    test::SceneLab lab(s);
    const WorldEmitter& e = lab.tracer->emitters()[0];
    ASSERT_NE(e.photometric, nullptr);
    // Turned by 90 degrees: C 0 points along +y, C 90 along -x.
    EXPECT_NEAR(length(e.photometric->c0() - Vec3(0, 1, 0)), 0, 1e-9);
    EXPECT_NEAR(length(e.photometric->c90() - Vec3(-1, 0, 0)), 0, 1e-9);
    EXPECT_NEAR(length(e.center - Vec3(1, 1, 2)), 0, 1e-9);
    // 800 cd at C 0, gamma 30: 2 m away along the turned C 0 plane, facing it.
    Vec3 w(0, std::sin(30 * kDeg), -std::cos(30 * kDeg)), p = e.center + w * 2;
    Rng rng(3);
    RayStats stats;
    double E = 0;
    for (int k = 0; k < 200; ++k) E += lab.tracer->illuminanceSample(p, -w, rng, stats) / 200;
    EXPECT_NEAR(E, 800 / 4.0, 2);
}

TEST(PhotometricLuminaire, RectAndSphereOpenings) {
    test::TempDir dir;
    json rect = {{"name", "panel"}, {"shape", "rect"}, {"center", {0, 0, 3}}, {"size", {0.6, 0.3}},
                 {"photometry", kPhotometryFiles + "asymmetric.ies"}};
    json sphere = {{"name", "bulb"}, {"shape", "sphere"}, {"center", {2, 0, 2}}, {"radius", 0.05},
                   {"normal", {0, 0, 1}}, {"photometry", kPhotometryFiles + "asymmetric.ldt"}, {"flux_lm", 500}};
    Scene s = loadLuminaires(json::array({rect, sphere}), dir);
    auto* panel = dynamic_cast<const PhotometricEmitter*>(s.emitters[0].shape.get());
    auto* bulb = dynamic_cast<const PhotometricEmitter*>(s.emitters[1].shape.get());
    ASSERT_TRUE(panel && bulb);
    // A rect's C 0 defaults to its first side (-x for up +y facing down); a sphere's
    // gamma 0 is its "normal", C 0 world +x projected.
    EXPECT_NEAR(length(panel->c0() - Vec3(-1, 0, 0)), 0, 1e-12);
    EXPECT_NEAR(length(bulb->axis() - Vec3(0, 0, 1)), 0, 1e-12);
    EXPECT_NEAR(length(bulb->c0() - Vec3(1, 0, 0)), 0, 1e-12);
    EXPECT_NEAR(bulb->projectedArea(Vec3(0, 1, 0)), kPi * 0.05 * 0.05, 1e-12);
}

TEST(PhotometricLuminaire, ErrorsNameTheFileAndTheJsonPath) {
    test::TempDir dir;
    json missing = downlight("asymmetric.ies");
    missing["photometry"] = "lum/none.ies";
    EXPECT_EQ(luminaireProblems(json::array({missing}), dir),
              std::vector<std::string>{"/luminaires/0/photometry: " + (dir.path() / "lum/none.ies").string() + ": no such file"});
    dir.write("lum/bad.ies", "IESNA:LM-63-2002\n[TEST] bad\nTILT=NONE\n1 -1 1 3 1 2 2 0 0 0\n1 1 0\n0 45 90\n0\n1 2 3\n");
    json bad = downlight("asymmetric.ies");
    bad["photometry"] = "lum/bad.ies";
    EXPECT_EQ(luminaireProblems(json::array({bad}), dir),
              std::vector<std::string>{"/luminaires/0/photometry: " + (dir.path() / "lum/bad.ies").string() +
                                       ":4: photometric type 2 (type B) is not supported: only type C (1)"});
    json noPhotometry = {{"name", "l"}, {"shape", "disk"}, {"center", {0, 0, 3}}, {"radius", 0.1}, {"c0", {1, 0, 0}}};
    EXPECT_EQ(luminaireProblems(json::array({noPhotometry}), dir),
              (std::vector<std::string>{"/luminaires/0: missing required key \"flux_lm\"",
                                        "/luminaires/0/c0: \"c0\" orients a photometric luminaire: it needs \"photometry\""}));
    json parallel = downlight("asymmetric.ies");
    parallel["c0"] = {0, 0, 2};
    EXPECT_EQ(luminaireProblems(json::array({parallel}), dir),
              std::vector<std::string>{"/luminaires/0/c0: \"c0\" is parallel to the luminaire's normal (gamma = 0)"});
    // A sphere takes "normal" only as a photometric luminaire's axis.
    json sphere = {{"name", "b"}, {"shape", "sphere"}, {"center", {0, 0, 2}}, {"radius", 0.1}, {"normal", {0, 0, 1}}, {"flux_lm", 100}};
    auto p = luminaireProblems(json::array({sphere}), dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/luminaires/0/normal: \"normal\" does not apply to a sphere emitter", 0), 0u) << p[0];
}

}  // namespace
}  // namespace luxplan
