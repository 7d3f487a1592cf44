// The glare samplers against the formulas computed by hand (docs/glare.md): the Guth
// position index and DGP worked examples of docs/glare.md, and UGR and DGP of one
// small rect luminaire of known luminance seen against a uniform sky over a black
// ground, where every term of the formulas is known in closed form.
#include <cmath>

#include <gtest/gtest.h>

#include <luxplan/daylight/daylight_params.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/glare_sources.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"

namespace luxplan {
namespace {

TEST(GuthIndex, ValuesOfTheReferences) {
    EXPECT_NEAR(guthIndex(0, 0), 1.0, 1e-4);
    EXPECT_NEAR(guthIndex(0, 30), 3.3481, 1e-4);
    EXPECT_NEAR(guthIndex(90, 30), 1.4681, 1e-4);
    EXPECT_NEAR(guthIndex(45, 45), 4.4150, 1e-4);
    EXPECT_EQ(guthIndex(0, 60), 16);
}

TEST(GuthIndex, FromDirections) {
    const Vec3 f(1, 0, 0);
    EXPECT_NEAR(guthIndexOf(f, f), 1.0, 1e-9);
    EXPECT_NEAR(guthIndexOf(f, normalize(Vec3(std::cos(radians(30)), 0, std::sin(radians(30))))), 3.3481, 1e-4);
    EXPECT_NEAR(guthIndexOf(f, normalize(Vec3(std::cos(radians(30)), std::sin(radians(30)), 0))), 1.4681, 1e-3);
    EXPECT_EQ(guthIndexOf(f, Vec3(-1, 0, 0)), 16);
    // Below the line of sight, Iwata: 20 deg down gives r = tan 20 deg < 0.6, P = 1 + 0.8 r.
    EXPECT_NEAR(guthIndexOf(f, normalize(Vec3(std::cos(radians(20)), 0, -std::sin(radians(20))))),
                1 + 0.8 * std::tan(radians(20)), 1e-9);
}

GlareSource source(double L, double omega, double P) {
    GlareSource s;
    s.luminance = L, s.solidAngle = omega, s.positionIndex = P;
    return s;
}

TEST(DaylightGlareProbability, WorkedExamplesOfTheReferences) {
    EXPECT_NEAR(daylightGlareProbability(2000, {source(1e4, 0.01, 1)}), 0.29693, 1e-5);
    EXPECT_NEAR(daylightGlareProbability(3000, {source(5e4, 0.05, 2)}), 0.43029, 1e-5);
    EXPECT_NEAR(daylightGlareProbability(800, {}), 0.20596, 1e-5);
    EXPECT_NEAR(daylightGlareProbability(200, {}) / (0.159 + 5.87e-5 * 200), 0.690, 1e-3);
    EXPECT_EQ(daylightGlareProbability(1e6, {source(1e9, 1, 1)}), 1.0);
}

TEST(UnifiedGlareRating, WorkedExamplesOfTheReferences) {
    EXPECT_NEAR(unifiedGlareRating(40, {source(5000, 0.01, 2)}), 20.734, 1e-3);
    std::vector<GlareSource> four(4, source(5000, 0.01, 2));
    EXPECT_NEAR(unifiedGlareRating(40, four), 25.551, 1e-3);
    EXPECT_EQ(unifiedGlareRating(40, {}), 0);
}

// A 0.1 x 0.1 m rect facing down, 2 m ahead of and 1 m above an eye looking along +x,
// luminance L = flux / (pi A), under a uniform sky of luminance Ls over a black
// ground. omega = A cos(theta_e) / d^2, sigma = atan(1/2), tau = 0; the sky fills the
// upper half of the front hemisphere but for the luminaire: E_ind = pi Ls / 2 - Ls
// omega cos(sigma), and E_v = E_ind + L omega cos(sigma).
struct OneLuminaire {
    static constexpr double kSky = 1000, kLuminance = 20000, kSide = 0.1;
    static double flux() { return kLuminance * kPi * kSide * kSide; }
    static double distance() { return std::sqrt(5.0); }
    static double omega() { return kSide * kSide * (1 / distance()) / (distance() * distance()); }
    static double cosSigma() { return 2 / distance(); }
    static double P() { return guthIndex(0, degrees(std::atan(0.5))); }
    static double indirect() { return kPi * kSky / 2 - kSky * omega() * cosSigma(); }
    static Scene scene(std::shared_ptr<const SamplerType> sampler) {
        return test::SceneBuilder()
            .uniformSky(kSky)
            .emitter("panel", rectEmitter({2, 0, 1}, {0, 0, -1}, {0, 1, 0}, {kSide, kSide}), flux())
            .sampler("eye", sampler, 0, 100)
            .build();
    }
};

TEST(UgrSampler, OneLuminaireAgainstTheFormula) {
    using T = OneLuminaire;
    test::SceneLab lab(T::scene(ugrSampler({0, 0, 0}, {1, 0, 0})));
    SamplerResult r = lab.measure(4000).samplers[0];
    const double Lb = T::indirect() / kPi;
    const double expected = 8 * std::log10(0.25 / Lb * T::kLuminance * T::kLuminance * T::omega() / (T::P() * T::P()));
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 0.05) << "standard error " << r.standardError;
    EXPECT_GT(r.standardError, 0);
    EXPECT_LT(r.standardError, 0.2);
    const auto& survey = r.glare;
    ASSERT_TRUE(survey.has_value());
    ASSERT_EQ(survey->sources.size(), 1u);
    EXPECT_NEAR(survey->sources[0].luminance, T::kLuminance, 1e-3 * T::kLuminance);
    EXPECT_NEAR(survey->sources[0].solidAngle, T::omega(), 0.01 * T::omega());
    EXPECT_NEAR(survey->sources[0].positionIndex, T::P(), 0.01 * T::P());
    EXPECT_NEAR(survey->backgroundLuminance, Lb, 0.02 * Lb);
}

TEST(UgrSampler, LuminairesBehindOrBelowTheEyeDoNotCount) {
    using T = OneLuminaire;
    test::SceneLab behind(T::scene(ugrSampler({0, 0, 0}, {-1, 0, 0})));
    EXPECT_EQ(behind.measure(500).samplers[0].value, 0);
    test::SceneLab above(T::scene(ugrSampler({0, 0, 1.5}, {1, 0, 0})));  // the lamp is below the eye
    EXPECT_EQ(above.measure(500).samplers[0].value, 0);
}

// Every luminaire is a source of its own however many there are: the panel of
// OneLuminaire listed after 40 others behind the eye (which add nothing to what it sees)
// gives the same UGR and DGP as alone. Source slots were once 32: it read UGR 0.
TEST(GlareSamplers, EveryLuminaireCountsHoweverMany) {
    using T = OneLuminaire;
    auto crowd = [](std::shared_ptr<const SamplerType> sampler) {
        test::SceneBuilder b;
        b.uniformSky(T::kSky);
        for (int k = 0; k < 40; ++k)
            b.emitter("behind" + std::to_string(k), rectEmitter({-2, 0.2 * k - 4, 1}, {0, 0, -1}, {0, 1, 0}, {0.1, 0.1}), 1000);
        b.emitter("panel", rectEmitter({2, 0, 1}, {0, 0, -1}, {0, 1, 0}, {T::kSide, T::kSide}), T::flux());
        return b.sampler("eye", sampler, 0, 100).build();
    };
    const double sum = T::kLuminance * T::kLuminance * T::omega() / (T::P() * T::P());
    test::SceneLab ugr(crowd(ugrSampler({0, 0, 0}, {1, 0, 0})));
    SamplerResult u = ugr.measure(2000).samplers[0];
    EXPECT_NEAR(u.value, 8 * std::log10(0.25 / (T::indirect() / kPi) * sum), 4 * u.standardError + 0.05) << u.standardError;
    ASSERT_TRUE(u.glare.has_value());
    ASSERT_EQ(u.glare->sources.size(), 1u);
    EXPECT_EQ(u.glare->sources[0].index, 40);
    test::SceneLab dgp(crowd(dgpSampler({0, 0, 0}, {1, 0, 0}, 2000)));
    SamplerResult d = dgp.measure(2000).samplers[0];
    const double Ev = T::indirect() + T::kLuminance * T::omega() * T::cosSigma();
    EXPECT_NEAR(d.value, 5.87e-5 * Ev + 0.159 + 0.092 * std::log10(1 + sum / std::pow(Ev, 1.87)), 4 * d.standardError + 2e-3);
}

TEST(DgpSampler, OneLuminaireAgainstTheFormula) {
    using T = OneLuminaire;
    test::SceneLab lab(T::scene(dgpSampler({0, 0, 0}, {1, 0, 0}, 2000)));
    SamplerResult r = lab.measure(4000).samplers[0];
    const double Ev = T::indirect() + T::kLuminance * T::omega() * T::cosSigma();
    const double sum = T::kLuminance * T::kLuminance * T::omega() / (T::P() * T::P());
    const double expected = 5.87e-5 * Ev + 0.159 + 0.092 * std::log10(1 + sum / std::pow(Ev, 1.87));
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 2e-3) << "standard error " << r.standardError;
    EXPECT_GT(r.standardError, 0);
    // Above the luminaire's luminance, the threshold leaves no source: DGP from E_v alone.
    test::SceneLab dim(T::scene(dgpSampler({0, 0, 0}, {1, 0, 0}, 50000)));
    SamplerResult d = dim.measure(4000).samplers[0];
    EXPECT_NEAR(d.value, 5.87e-5 * Ev + 0.159, 4 * d.standardError + 1e-3);
}

// A uniform sky of 3000 cd/m2 over a black ground, seen by an eye looking along +x
// with nothing around it: the upper half of the front hemisphere is one region
// brighter than the 2000 cd/m2 threshold, omega = pi, L = 3000, centred 45 degrees up
// (the centroid of a quarter sphere is along (1, 0, 1)), P = P(tau 0, sigma 45); its
// direct light is all of E_v = pi L / 2.
TEST(DgpSampler, ABrightSkyIsOneRegionAgainstTheFormula) {
    constexpr double kSky = 3000;
    test::SceneLab lab(test::SceneBuilder().uniformSky(kSky).sampler("eye", dgpSampler({0, 0, 0}, {1, 0, 0}, 2000, 16), 0, 1).build());
    SamplerResult r = lab.measure(200).samplers[0];
    const auto& survey = r.glare;
    ASSERT_TRUE(survey.has_value());
    ASSERT_EQ(survey->sources.size(), 1u);
    const GlareSource& g = survey->sources[0];
    EXPECT_EQ(g.kind, GlareSource::Kind::Region);
    EXPECT_NEAR(g.solidAngle, kPi, 1e-9);
    EXPECT_NEAR(g.luminance, kSky, 1e-6 * kSky);
    EXPECT_NEAR(degrees(std::acos(dot(g.direction, normalize(Vec3(1, 0, 1))))), 0, 0.2);
    const double P = guthIndex(0, 45);
    EXPECT_NEAR(g.positionIndex, P, 0.02 * P);
    const double Ev = kPi * kSky / 2;
    EXPECT_NEAR(survey->verticalIlluminance, Ev, 0.01 * Ev);
    EXPECT_NEAR(survey->directIlluminance, Ev, 1e-3 * Ev);
    const double expected = 5.87e-5 * Ev + 0.159 + 0.092 * std::log10(1 + kSky * kSky * kPi / (P * P) / std::pow(Ev, 1.87));
    EXPECT_NEAR(r.value, expected, 4 * r.standardError + 1e-3);
    // Below the sky's luminance the threshold leaves no source.
    test::SceneLab dim(test::SceneBuilder().uniformSky(kSky).sampler("eye", dgpSampler({0, 0, 0}, {1, 0, 0}, 4000, 16), 0, 1).build());
    EXPECT_TRUE(dim.measure(50).samplers[0].glare->sources.empty());
}

// The sun 20 degrees up straight ahead, 2000 lx at normal incidence, in a uniform sky
// of 500 cd/m2 (below the threshold): the sun disk is the one source, surveyed by its
// slot; the direction cell it falls in hides it (else that cell's mean, ~2e5 cd/m2,
// would add a second, spurious source).
TEST(DgpSampler, TheSunIsOneSourceNotTwo) {
    constexpr double kSky = 500, kSunLx = 2000;
    DaylightParams d;
    d.model = SkyModelType::Uniform;
    d.luminanceNits = kSky;
    d.sunOverride = SunOverride{20, 180, kSunLx};
    d.groundReflectance = 0;
    const Vec3 south(0, -1, 0);
    test::SceneLab lab(test::SceneBuilder().daylight(d).sampler("eye", dgpSampler({0, 0, 0}, south, 2000), 0, 1).build());
    SamplerResult r = lab.measure(400).samplers[0];
    const auto& survey = r.glare;
    ASSERT_TRUE(survey.has_value());
    ASSERT_EQ(survey->sources.size(), 1u);
    const GlareSource& sun = survey->sources[0];
    EXPECT_EQ(sun.kind, GlareSource::Kind::Sun);
    EXPECT_NEAR(sun.luminance * sun.solidAngle, kSunLx, 0.01 * kSunLx);
    const double P = guthIndex(0, 20);
    EXPECT_NEAR(sun.positionIndex, P, 0.01 * P);
    const double Ev = kPi * kSky / 2 + kSunLx * std::cos(radians(20));
    EXPECT_NEAR(survey->verticalIlluminance, Ev, 0.01 * Ev);
    const double sum = sun.luminance * sun.luminance * sun.solidAngle / (P * P);
    EXPECT_NEAR(r.value, 5.87e-5 * Ev + 0.159 + 0.092 * std::log10(1 + sum / std::pow(Ev, 1.87)), 4 * r.standardError + 2e-3);
}

// Adaptive measurement stops only the direction cells surely below the threshold:
// E_v, the source slots and cells that may be bright keep their paths.
TEST(DgpSampler, AdaptiveStopsOnlyTheCellsSurelyBelowTheThreshold) {
    auto type = dgpSampler({0, 0, 0}, {1, 0, 0}, 2000, 2);
    auto placed = type->place(Transform());
    placed->setSources(1, 0);  // one luminaire: items 1-6
    const int first = 1 + PlacedGlare::kQuantities;
    ASSERT_EQ(placed->items(), first + 4);
    ItemEstimates e(placed->items(), 1);
    const double cell[4][2] = {{100, 110}, {5000, 5200}, {1900, 2050}, {0, 4000}};  // two paths each
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 2; ++k) e.cell(first + c, 0, k).add(cell[c][k]);
    const std::vector<char> keep = placed->stillNeeded(e, 3, 0, kInf);
    EXPECT_TRUE(keep[0]);  // E_v
    EXPECT_TRUE(keep[1]);  // a slot
    EXPECT_FALSE(keep[size_t(first)]);  // 105 +- 5: surely dark
    EXPECT_TRUE(keep[size_t(first + 1)]);  // bright
    EXPECT_TRUE(keep[size_t(first + 2)]);  // near the threshold
    EXPECT_TRUE(keep[size_t(first + 3)]);  // too noisy to tell
}

TEST(GlareSamplers, DeterministicForASeed) {
    using T = OneLuminaire;
    test::SceneLab lab(T::scene(dgpSampler({0, 0, 0}, {1, 0, 0})));
    EXPECT_EQ(lab.measure(300, 7).samplers[0].value, lab.measure(300, 7).samplers[0].value);
}

TEST(GlareSamplers, ReadTheirKeys) {
    const SamplerTypeEntry* ugr = findSamplerType("ugr");
    const SamplerTypeEntry* dgp = findSamplerType("dgp");
    ASSERT_NE(ugr, nullptr);
    ASSERT_NE(dgp, nullptr);
    EXPECT_EQ(json::probeKeys([&](const json::Fields& f) { ugr->read(f); }), (std::vector<std::string>{"origin", "direction"}));
    EXPECT_EQ(json::probeKeys([&](const json::Fields& f) { dgp->read(f); }),
              (std::vector<std::string>{"origin", "direction", "source_threshold_nits", "direction_cells"}));
}

}  // namespace
}  // namespace luxplan
