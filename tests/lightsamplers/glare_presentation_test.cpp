// How the glare samplers present themselves (sampler_type.h's presentation hooks):
// UGR below 10 reads "<10", DGP with three decimals; their survey as measure's line and
// as report.json's "glare"; and that they, not the other types, survey sources.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/lightsamplers/glare_sources.h>

namespace luxplan {
namespace {

SamplerResult surveyedResult(double value) {
    SamplerResult r;
    r.value = value;
    GlareSurvey g;
    g.verticalIlluminance = 2100.4, g.directIlluminance = 1500, g.backgroundLuminance = 31.04;
    GlareSource s;
    s.kind = GlareSource::Kind::Luminaire, s.luminance = 5200.2, s.solidAngle = 1.2344e-3, s.positionIndex = 2.1;
    s.direction = normalize(Vec3(0, 1, 1)), s.index = 3;
    g.sources = {s};
    r.glare = g;
    return r;
}

TEST(GlarePresentation, ValuesReadInTheTypesFormat) {
    const ValueFormat ugr = ugrSampler({0, 0, 0}, {1, 0, 0})->valueFormat();
    EXPECT_EQ(ugr.text(9.7, 1), "<10");  // CIE 117's scale starts at 10
    EXPECT_EQ(ugr.text(13.24, 1), "13.2");
    EXPECT_EQ(ugr.text(10, 1), "10.0");
    EXPECT_TRUE(ugr.unitless);
    const ValueFormat dgp = dgpSampler({0, 0, 0}, {1, 0, 0})->valueFormat();
    EXPECT_EQ(dgp.text(0.05, dgp.digits), "0.050");
    EXPECT_EQ(dgp.summaryDigits, 2);
    const ValueFormat planar = planarSampler({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2})->valueFormat();
    EXPECT_EQ(planar.text(3.25, 1), "3.2");  // 3.25 is 3.25 exactly: round half to even
    EXPECT_FALSE(planar.unitless);
}

TEST(GlarePresentation, OnlyGlareEyesSurveySources) {
    EXPECT_TRUE(ugrSampler({0, 0, 0}, {1, 0, 0})->surveysSources());
    EXPECT_TRUE(dgpSampler({0, 0, 0}, {1, 0, 0})->surveysSources());
    EXPECT_FALSE(planarSampler({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2})->surveysSources());
    EXPECT_FALSE(cylindricalSampler({0, 0, 1})->surveysSources());
    EXPECT_EQ(ugrSampler({0, 0, 0}, {1, 0, 0})->resultGroup(), ResultGroup::Glare);
    EXPECT_EQ(planarSampler({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2})->resultGroup(), ResultGroup::TaskArea);
}

TEST(GlarePresentation, TheSurveyAsTextAndJson) {
    const auto ugr = ugrSampler({0, 0, 0}, {1, 0, 0});
    EXPECT_EQ(ugr->detailsText(surveyedResult(9.2)),
              "UGR <10, Lb 31.0 cd/m2, 1 source; luminaire [0.00 0.71 0.71] L 5200 cd/m2, omega 1.234 msr, P 2.10");
    const auto dgp = dgpSampler({0, 0, 0}, {1, 0, 0});
    SamplerResult none = surveyedResult(0.3521);
    none.glare->sources.clear();
    EXPECT_EQ(dgp->detailsText(none), "DGP 0.352, Ev 2100 lx, 0 sources");

    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    ugr->addDetails(surveyedResult(13), j);
    ASSERT_TRUE(j.contains("glare"));
    EXPECT_EQ(j["glare"]["vertical_illuminance"], 2100.4);
    EXPECT_EQ(j["glare"]["background_luminance"], 31.04);
    ASSERT_EQ(j["glare"]["sources"].size(), 1u);
    EXPECT_EQ(j["glare"]["sources"][0]["kind"], "luminaire");
    EXPECT_EQ(j["glare"]["sources"][0]["slot"], 3);
    EXPECT_EQ(j["glare"]["sources"][0]["luminance"], 5200.2);

    // Without a survey: no details.
    SamplerResult plain;
    plain.value = 12;
    EXPECT_EQ(ugr->detailsText(plain), "");
    nlohmann::ordered_json empty = nlohmann::ordered_json::object();
    ugr->addDetails(plain, empty);
    EXPECT_TRUE(empty.empty());
}

}  // namespace
}  // namespace luxplan
