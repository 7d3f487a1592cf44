// The row presenter (optimizer/sampler_report.h): one measured sampler's terms, point
// statistics, value, error and target as measure's table and the reports show them.
#include <gtest/gtest.h>

#include <cmath>

#include <luxplan/optimizer/sampler_report.h>

namespace luxplan {
namespace {

LightSamplerSpec rowSpec(std::shared_ptr<const SamplerType> type, double lo, double hi) {
    LightSamplerSpec s;
    s.name = "desk";
    s.type = std::move(type);
    s.targetMin = lo, s.targetMax = hi, s.tolerance = 100;
    return s;
}

TEST(SamplerRow, APlanarSamplersRow) {
    const LightSamplerSpec spec = rowSpec(planarSampler({0, 0, 0.75}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 1}), 300, 500);
    SamplerResult r;
    r.value = 250, r.standardError = 2.345, r.pathsPerPoint = 64;
    r.points = {200, 300}, r.pointErrors = {2, 3};
    const SamplerRow row(spec, r);
    EXPECT_EQ(row.valueText(), "250.0");
    EXPECT_EQ(row.errorText(), "2.3");  // the type's one decimal
    EXPECT_EQ(row.targetText(), "[300, 500]");
    EXPECT_EQ(row.penalty(), lightingPenalty(spec, 250));
    EXPECT_GT(row.penalty(), 0);
    EXPECT_FALSE(row.met());
    ASSERT_TRUE(row.statistics());
    EXPECT_DOUBLE_EQ(row.statistics()->u0.value, 0.8);
    EXPECT_EQ(row.detailsText(), "Em 250.0 lx, Emin 200.0, Emax 300.0, U0 0.80, 2 x 1 grid");
    const nlohmann::ordered_json j = row.detailsJson();
    EXPECT_EQ(j["grid"], nlohmann::ordered_json::array({2, 1}));
    EXPECT_EQ(j["stats"]["min"], 200.0);
    EXPECT_EQ(j["terms"][0]["statistic"], "mean");
    EXPECT_FALSE(j.contains("glare"));
}

TEST(SamplerRow, OpenTargetsAndFewPaths) {
    const LightSamplerSpec spec = rowSpec(cylindricalSampler({0, 0, 1.2}), 150, kInf);
    SamplerResult r;
    r.value = 180, r.standardError = 0, r.pathsPerPoint = 1;
    r.points = {180}, r.pointErrors = {0};
    const SamplerRow row(spec, r);
    EXPECT_EQ(row.targetText(), "[150, inf]");
    EXPECT_EQ(row.errorText(), "n/a");  // one path per point gives no error
    EXPECT_TRUE(row.met());
    EXPECT_FALSE(row.statistics());
    EXPECT_EQ(row.detailsText(), "");
    EXPECT_TRUE(row.detailsJson()["terms"][0]["target"][1].is_null());
}

}  // namespace
}  // namespace luxplan
