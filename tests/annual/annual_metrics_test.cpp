// Annual metrics against hand counts: sDA300/50% and ASE1000,250 (IES LM-83-12) and
// UDI at their boundaries, covered points left out, an empty series, and the JSON of
// measure --annual.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include <luxplan/annual/annual_metrics.h>

namespace luxplan {
namespace annual_metrics_test {

// `n` hours from 2026-01-01T08:30-06:00 on, one an hour.
std::vector<DateTime> someHours(int n) {
    std::vector<DateTime> hours;
    DateTime t{2026, 1, 1, 8, 30, 0, -360};
    for (int i = 0; i < n; ++i) hours.push_back(t.plusMinutes(60.0 * i));
    return hours;
}

// 4 points x 10 hours, the third covered; target 300-500 lx.
//   A: 300 lx for 5 hours, 299 for 5: exactly 300 lx for exactly 50% of the hours (passes sDA).
//   B: 301 lx for 4 hours, 299.9 for 6: 40% (fails).
//   D: the UDI boundaries: 100 and 3000 are useful, 99.9 short, 3000.1 exceeded; >= 300 in 5 hours.
AnnualSeries tenHours() {
    AnnualSeries s;
    s.hours = someHours(10);
    AnnualSampler a;
    a.name = "desk";
    a.type = "planar";
    a.planar = true;
    a.targetMin = 300, a.targetMax = 500;
    a.values = {299.99, 300, 400, 500, 500.01, 0, 450, 350, 1000, 300};
    a.points = {{300, 300, 300, 300, 300, 299, 299, 299, 299, 299},
                {301, 301, 301, 301, 299.9, 299.9, 299.9, 299.9, 299.9, 299.9},
                {},
                {100, 3000, 99.9, 3000.1, 50, 5000, 2000, 100, 3000, 0}};
    a.directSun = {std::vector<double>(10, 0), std::vector<double>(10, 0), {}, std::vector<double>(10, 0)};
    s.samplers.push_back(a);
    return s;
}

TEST(AnnualMetrics, MeanAndInRangeOverHours) {
    const AnnualSeries s = tenHours();
    const AnnualMetrics m = annualMetrics(s.samplers[0], s);
    EXPECT_EQ(m.hours, 10);
    // (299.99 + 300 + 400 + 500 + 500.01 + 0 + 450 + 350 + 1000 + 300) / 10
    EXPECT_NEAR(m.mean, 410, 1e-12);
    // In [300, 500], both ends inclusive: 300, 400, 500, 450, 350, 300.
    EXPECT_DOUBLE_EQ(m.inRange, 0.6);
}

TEST(AnnualMetrics, SdaAtItsBoundariesLeavesCoveredPointsOut) {
    const AnnualSeries s = tenHours();
    const AnnualMetrics m = annualMetrics(s.samplers[0], s);
    EXPECT_EQ(m.points, 3);
    EXPECT_DOUBLE_EQ(m.sda, 2.0 / 3.0);  // A and D of A, B, D
}

TEST(AnnualMetrics, UdiBinsOverPointHours) {
    const AnnualSeries s = tenHours();
    const AnnualMetrics m = annualMetrics(s.samplers[0], s);
    // 30 point-hours: A and B all useful; D 3 short (99.9, 50, 0), 5 useful, 2 exceeded (3000.1, 5000).
    EXPECT_DOUBLE_EQ(m.udi[0], 3.0 / 30);
    EXPECT_DOUBLE_EQ(m.udi[1], 25.0 / 30);
    EXPECT_DOUBLE_EQ(m.udi[2], 2.0 / 30);
}

TEST(AnnualMetrics, PointsInRangeForThePlan) {
    const AnnualSeries s = tenHours();
    const AnnualMetrics m = annualMetrics(s.samplers[0], s);
    ASSERT_EQ(m.pointsInRange.size(), 4u);
    EXPECT_DOUBLE_EQ(m.pointsInRange[0], 0.5);
    EXPECT_DOUBLE_EQ(m.pointsInRange[1], 0.4);
    EXPECT_TRUE(std::isnan(m.pointsInRange[2]));
    EXPECT_DOUBLE_EQ(m.pointsInRange[3], 0.0);
    EXPECT_DOUBLE_EQ(m.ase, 0.0);
}

TEST(AnnualMetrics, AseCountsMoreThan250HoursAbove1000Lux) {
    AnnualSeries s;
    s.hours = someHours(300);
    AnnualSampler a;
    a.name = "floor";
    a.type = "planar";
    a.planar = true;
    a.values.assign(300, 500);
    a.points.assign(5, std::vector<double>(300, 500));
    a.points[4].clear();  // covered
    a.directSun.assign(5, std::vector<double>(300, 0));
    a.directSun[4].clear();
    for (int h = 0; h < 250; ++h) a.directSun[0][size_t(h)] = 1000.5;  // exactly 250 hours: passes
    for (int h = 0; h < 251; ++h) a.directSun[1][size_t(h)] = 1000.5;  // 251 hours: exposed
    a.directSun[2].assign(300, 1000);                                  // 1000 lx is not above 1000
    for (int h = 0; h < 251; ++h) a.directSun[3][size_t(h)] = 2e5;     // 251 hours of strong sun: exposed
    const AnnualMetrics m = annualMetrics(a, s);
    EXPECT_EQ(m.points, 4);
    EXPECT_DOUBLE_EQ(m.ase, 0.5);
    EXPECT_DOUBLE_EQ(m.sda, 1.0);
    EXPECT_DOUBLE_EQ(m.udi[1], 1.0);
}

TEST(AnnualMetrics, WithoutDirectSunAseIsUndefined) {
    AnnualSeries s = tenHours();
    s.samplers[0].directSun.clear();
    const AnnualMetrics m = annualMetrics(s.samplers[0], s);
    EXPECT_TRUE(std::isnan(m.ase));
    EXPECT_DOUBLE_EQ(m.sda, 2.0 / 3.0);
}

TEST(AnnualMetrics, EmptySeriesAndAllCoveredAreUndefined) {
    AnnualSeries s = tenHours();
    s.hours.clear();
    const AnnualMetrics m = annualMetrics(s.samplers[0], s);
    EXPECT_EQ(m.hours, 0);
    EXPECT_TRUE(std::isnan(m.mean));
    EXPECT_TRUE(std::isnan(m.inRange));
    EXPECT_TRUE(std::isnan(m.sda));
    EXPECT_TRUE(std::isnan(m.ase));
    EXPECT_TRUE(std::isnan(m.udi[1]));

    AnnualSeries covered = tenHours();
    for (auto& row : covered.samplers[0].points) row.clear();
    for (auto& row : covered.samplers[0].directSun) row.clear();
    const AnnualMetrics c = annualMetrics(covered.samplers[0], covered);
    EXPECT_EQ(c.points, 0);
    EXPECT_TRUE(std::isnan(c.sda));
    EXPECT_TRUE(std::isnan(c.udi[0]));
    EXPECT_NEAR(c.mean, 410, 1e-12);  // the sampler's own values still count
}

TEST(AnnualMetrics, NonPlanarSamplersHaveNoPointMetrics) {
    AnnualSampler lum;
    lum.name = "eye";
    lum.type = "directional";
    lum.targetMin = 0, lum.targetMax = 100;
    lum.values = {50, 150, 100, 0};
    const AnnualMetrics m = annualMetrics(lum, 4);
    EXPECT_FALSE(m.planar);
    EXPECT_DOUBLE_EQ(m.mean, 75);
    EXPECT_DOUBLE_EQ(m.inRange, 0.75);
    EXPECT_TRUE(std::isnan(m.sda));
    EXPECT_TRUE(m.pointsInRange.empty());
}

TEST(AnnualJson, KeysAndValuesAsTheContractNamesThem) {
    AnnualSeries s = tenHours();
    AnnualSampler eye;
    eye.name = "chair.eye";
    eye.type = "directional";
    eye.targetMin = 0, eye.targetMax = 2000;
    eye.values = {1, 2, 3, 4, 5, 6, 7, 8, 9, std::nan("")};
    s.samplers.push_back(eye);
    nlohmann::json out = {{"samplers", {{{"name", "chair.eye"}, {"value", 3}}, {{"name", "desk"}, {"value", 410}}}}};
    addAnnualJson(out, s);

    ASSERT_EQ(out["hours"].size(), 10u);
    EXPECT_EQ(out["hours"][0], "2026-01-01T08:30-06:00");
    EXPECT_EQ(out["hours"][9], "2026-01-01T17:30-06:00");

    const nlohmann::json& desk = out["samplers"][1];
    EXPECT_EQ(desk["value"], 410);  // measure's own keys stay
    const nlohmann::json& a = desk["annual"];
    EXPECT_EQ(a["hours"], 10);
    EXPECT_NEAR(a["mean"].get<double>(), 410, 1e-12);
    EXPECT_DOUBLE_EQ(a["in_range"].get<double>(), 0.6);
    ASSERT_EQ(a["values"].size(), 10u);
    EXPECT_DOUBLE_EQ(a["values"][0].get<double>(), 299.99);
    EXPECT_DOUBLE_EQ(a["sda"].get<double>(), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(a["ase"].get<double>(), 0.0);
    ASSERT_EQ(a["udi"].size(), 3u);
    EXPECT_DOUBLE_EQ(a["udi"][2].get<double>(), 2.0 / 30);
    ASSERT_EQ(a["points_in_range"].size(), 4u);
    EXPECT_TRUE(a["points_in_range"][2].is_null());  // the covered point
    // Also beside "annual".
    EXPECT_EQ(desk["sda"], a["sda"]);
    EXPECT_EQ(desk["ase"], a["ase"]);
    EXPECT_EQ(desk["udi"], a["udi"]);

    const nlohmann::json& e = out["samplers"][0];
    EXPECT_FALSE(e.contains("sda"));
    EXPECT_FALSE(e["annual"].contains("sda"));
    EXPECT_FALSE(e["annual"].contains("points_in_range"));
    EXPECT_TRUE(e["annual"]["values"][9].is_null());  // non-finite as null
    EXPECT_TRUE(e["annual"]["mean"].is_null());
    EXPECT_DOUBLE_EQ(e["annual"]["in_range"].get<double>(), 0.9);
}

TEST(AnnualJson, AnUnmatchedSamplerGetsItsOwnObjectAndAnEmptySeriesGivesNulls) {
    AnnualSeries s = tenHours();
    s.hours.clear();
    nlohmann::json out = nlohmann::json::object();
    addAnnualJson(out, s);
    EXPECT_TRUE(out["hours"].is_array());
    EXPECT_TRUE(out["hours"].empty());
    ASSERT_EQ(out["samplers"].size(), 1u);
    const nlohmann::json& desk = out["samplers"][0];
    EXPECT_EQ(desk["name"], "desk");
    EXPECT_EQ(desk["type"], "planar");
    EXPECT_EQ(desk["annual"]["hours"], 0);
    EXPECT_TRUE(desk["annual"]["values"].empty());
    EXPECT_TRUE(desk["annual"]["mean"].is_null());
    EXPECT_TRUE(desk["sda"].is_null());
    EXPECT_TRUE(desk["udi"][0].is_null());
}

TEST(AnnualText, ATableOfPercentages) {
    const std::string text = annualText(tenHours());
    EXPECT_NE(text.find("sDA %"), std::string::npos) << text;
    EXPECT_NE(text.find("desk"), std::string::npos) << text;
    EXPECT_NE(text.find("410.0"), std::string::npos) << text;  // mean
    EXPECT_NE(text.find("60.0"), std::string::npos) << text;   // in range
    EXPECT_NE(text.find("66.7"), std::string::npos) << text;   // sDA
    EXPECT_NE(text.find("83.3"), std::string::npos) << text;   // UDI useful
    EXPECT_NE(text.find("10 hours from 2026-01-01T08:30-06:00"), std::string::npos) << text;
}

}  // namespace annual_metrics_test
}  // namespace luxplan
