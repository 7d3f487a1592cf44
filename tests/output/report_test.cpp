// report.html: escaping, links only to files that exist, sampler and constraint
// tables with their status, and the optimizer's sections when there is a result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <regex>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/lightsamplers/glare_sources.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/output/report_html.h>
#include <luxplan/output/report_viewer.h>
#include "support/scene_builder.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

// Names that need escaping, two boxes too close for their distance constraint, a
// sampler above its target and one within.
Scene makeScene() {
    return test::SceneBuilder()
        .name("<b>Tom & Jerry's \"room\"</b>")
        .material("m", test::diffuse(0.5))
        .room({0, 0, 0}, {6, 4, 3}, "m", "m", "m")
        .entity("table", {2, 2, 0}).region({1, 1}, {5, 3}).part({1, 1, 0.75}, "m").end()
        .entity("sofa", {2.5, 2, 0}).region({1, 1}, {5, 3}).part({1, 1, 0.75}, "m").end()
        .sampler("<script>alert(1)</script>", planarSampler({3, 2, 0.8}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 300, 500)
        .sampler("ambient", planarSampler({1, 1, 0.8}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {4, 4}), 100)
        .constraint(distanceConstraint({1, 2, std::nullopt}), "table", "sofa")
        .build();
}

// Every href and src value (scanned by hand: std::regex recurses per character, and a
// picture's data: URI is longer than its stack allows).
std::vector<std::string> links(const std::string& html) {
    std::vector<std::string> out;
    for (const char* attr : {"href=\"", "src=\""})
        for (size_t at = html.find(attr); at != std::string::npos; at = html.find(attr, at + 1)) {
            const size_t begin = at + std::strlen(attr), end = html.find('"', begin);
            out.push_back(html.substr(begin, end - begin));
        }
    return out;
}

TEST(ReportHtml, EscapesText) {
    EXPECT_EQ(escapeHtml("<a href=\"x\">Tom & Jerry's</a>"),
              "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
    EXPECT_EQ(escapeHtml("plain"), "plain");
}

TEST(ReportHtml, SamplersConstraintsAndOnlyExistingLinks) {
    test::TempDir dir;
    Scene scene = makeScene();
    dir.write("plan.png", "png");
    dir.write("scene.glb", "glb");
    ReportData data;
    data.layoutLabel = "layout.json";
    data.samplers.resize(2);
    data.samplers[0].value = 620;  // above [300, 500]
    data.samplers[1].value = 150;  // in [100, inf)
    GeometryEvaluator geometry(scene);
    data.geometry = geometry.evaluate(worldTransforms(scene, initialLayout(scene)), true);
    data.timings = {{"render.png", 1.5}};
    writeReportHtml(dir.path(), scene, nullptr, data);

    std::ifstream in(dir.path() / "report.html");
    std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("<b>Tom"), std::string::npos);
    EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
    EXPECT_NE(html.find("Tom &amp; Jerry&#39;s &quot;room&quot;"), std::string::npos);
    EXPECT_NE(html.find("1 of 2 samplers meet their targets"), std::string::npos) << html;
    EXPECT_NE(html.find("class=\"missed\">missed"), std::string::npos);
    EXPECT_NE(html.find("class=\"met\">met"), std::string::npos);
    EXPECT_NE(html.find("&infin;"), std::string::npos);
    // The distance constraint (table and sofa 0.5 m apart, asked for 1 to 2 m) and their overlap.
    EXPECT_NE(html.find("<td>distance</td><td>table</td><td>sofa</td>"), std::string::npos) << html;
    EXPECT_NE(html.find("<th>shared volume (m&sup3;)</th>"), std::string::npos);
    EXPECT_NE(html.find("render.png</td>"), std::string::npos);  // the timing row, not a picture

    std::vector<std::string> refs = links(html);
    EXPECT_NE(std::find(refs.begin(), refs.end(), "plan.png"), refs.end());
    EXPECT_NE(std::find(refs.begin(), refs.end(), "scene.glb"), refs.end());
    // The pictures are in the page (data: URIs); every other link is to a file there.
    EXPECT_NE(std::find(refs.begin(), refs.end(), "data:image/png;base64,cG5n"), refs.end());  // "png"
    for (const std::string& ref : refs) {
        if (ref.rfind("data:", 0) != 0) {
            EXPECT_TRUE(std::filesystem::exists(dir.path() / ref)) << ref;
        }
    }
    EXPECT_EQ(html.find("src=\"plan.png\""), std::string::npos);
    EXPECT_EQ(html.find("src=\"render.png\""), std::string::npos);
    EXPECT_EQ(html.find("http"), std::string::npos);  // nothing from the network
}

namespace reporttest {

std::string between(const std::string& html, const std::string& from, const std::string& to) {
    const size_t a = html.find(from);
    if (a == std::string::npos) return "";
    const size_t b = html.find(to, a);
    return html.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

}  // namespace reporttest

// Results first: per task area Em, Emin and U0 against their targets in words a client
// reads, glare samplers as rows of their own, C, L and G explained; the engineer's
// tables after them, in the appendix; a print stylesheet for A4.
TEST(ReportHtml, ResultsFirstAndTheEngineersTablesInTheAppendix) {
    Scene scene = test::SceneBuilder()
                      .name("office")
                      .material("m", test::diffuse(0.5))
                      .room({0, 0, 0}, {6, 4, 3}, "m", "m", "m")
                      .entity("desk", {2, 2, 0}).region({1, 1}, {5, 3}).part({1, 1, 0.75}, "m").end()
                      .sampler("desk area", planarSampler({3, 2, 0.8}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2}), 500)
                      .statistic(Statistic::U0, 0.6)
                      .sampler("reading", planarSampler({1, 1, 0.8}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2}), 300, 750)
                      .sampler("seat view", ugrSampler({2, 2, 1.2}, {1, 0, 0}), 0, 19)
                      .sampler("screen", directionalSampler({2, 2, 1.2}, {0, 1, 0}, {0, 0, 1}, 60, 4), 0, 1000)
                      .build();
    ReportData data;
    data.layoutLabel = "layout.json";
    data.samplers.resize(4);
    // desk area: Em 510 (>= 500), U0 = 300 / 510 = 0.59 against 0.6 with an error of 0.05: within noise.
    data.samplers[0].value = 510, data.samplers[0].standardError = 5;
    data.samplers[0].points = {300, 600, 570, 570};
    data.samplers[0].pointErrors = {30, 30, 30, 30};
    data.samplers[1].value = 200, data.samplers[1].standardError = 5;  // below 300 by 20 errors: fails
    data.samplers[1].points = {150, 250, 200, 200};
    data.samplers[1].pointErrors = {5, 5, 5, 5};
    data.samplers[2].value = 16.2;  // UGR <= 19: passes
    data.samplers[3].value = 1500, data.samplers[3].standardError = 20;  // fails
    GeometryEvaluator geometry(scene);
    data.geometry = geometry.evaluate(worldTransforms(scene, initialLayout(scene)), true);
    data.timings = {{"render.png", 1.5}};
    test::TempDir dir;
    const std::string html = reportHtml(dir.path(), scene, nullptr, data);

    // The order: results, then the appendix with the engineer's tables.
    const size_t results = html.find("<h2 id=\"results\">Results</h2>"), appendix = html.find("id=\"appendix\"");
    ASSERT_NE(results, std::string::npos) << html;
    ASSERT_NE(appendix, std::string::npos) << html;
    EXPECT_LT(results, appendix);
    EXPECT_LT(results, html.find("<h2>Scene</h2>"));
    for (const char* part : {"<h2>Light samplers</h2>", "<h2>Constraints</h2>", "<h2>Timings</h2>", "<h3>Statistics goals</h3>"}) {
        EXPECT_GT(html.find(part), appendix) << part;
    }
    const std::string areas = reporttest::between(html, "<h3>Task areas</h3>", "</table>");
    ASSERT_FALSE(areas.empty()) << html;
    // desk area: Em passes, Emin has no target, U0 within noise of its bound.
    EXPECT_NE(areas.find("<td rowspan=\"3\"><b>desk area</b></td><td>E<sub>m</sub> (mean)</td>"
                         "<td class=\"num\">510&nbsp;lx</td><td>&ge; 500&nbsp;lx</td><td class=\"result met\">pass</td>"),
              std::string::npos)
        << areas;
    EXPECT_NE(areas.find("<td>E<sub>min</sub></td><td class=\"num\">300&nbsp;lx</td><td>&ndash;</td>"
                         "<td class=\"result muted\">no target</td>"),
              std::string::npos)
        << areas;
    EXPECT_NE(areas.find("<td class=\"num\">0.59</td><td>&ge; 0.60</td><td class=\"result warn\">at bound (within noise)</td>"),
              std::string::npos)
        << areas;
    // reading: Em fails, 300 to 750 lx.
    EXPECT_NE(areas.find("<td class=\"num\">200&nbsp;lx</td><td>300 to 750&nbsp;lx</td><td class=\"result missed\">fail</td>"),
              std::string::npos)
        << areas;
    EXPECT_EQ(areas.find("seat view"), std::string::npos);
    // Glare: the UGR and the directional sampler, each a row of its own.
    // With a maintenance factor the mean is a maintained one, and says so.
    Scene maintained = scene;
    maintained.maintenanceFactor = 0.8;
    EXPECT_NE(reportHtml(dir.path(), maintained, nullptr, data).find("E<sub>m</sub> (maintained mean)"), std::string::npos);
    EXPECT_EQ(html.find("maintained mean"), std::string::npos);
    const std::string glare = reporttest::between(html, "<h3>Glare</h3>", "</table>");
    EXPECT_NE(glare.find("<td><b>seat view</b></td><td>UGR (unified glare rating)</td><td class=\"num\">16.2</td>"
                         "<td>&le; 19.0</td><td class=\"result met\">pass</td>"),
              std::string::npos)
        << glare;
    EXPECT_NE(glare.find("<td><b>screen</b></td>"), std::string::npos) << glare;
    EXPECT_NE(glare.find("<td class=\"result missed\">fail</td>"), std::string::npos) << glare;
    // The goals sentence and C, L and G explained.
    // The UGR met; the desk area's U0 within noise; the reading area and the screen missed.
    EXPECT_NE(html.find("1 of 4 lighting goals met (1 more at its bound within noise), "), std::string::npos) << html;
    EXPECT_NE(html.find("C = w&middot;L + (1 &minus; w)&middot;G"), std::string::npos);
    EXPECT_NE(html.find("the lighting penalty: 0 when every lighting goal is met"), std::string::npos);
    EXPECT_NE(html.find("the design-rule penalty: 0 when every design rule"), std::string::npos);
    // Never "fail" or "missed" for the value within noise.
    EXPECT_EQ(reporttest::between(areas, "U<sub>0</sub> = ", "</tr>").find("fail"), std::string::npos);
    // Print: A4, tables and rows kept whole, pictures to the page's width, no 3D view.
    for (const char* rule : {"@media print", "size: A4", "break-inside: avoid", "figure img { max-width: 100%",
                             ".screen-only, canvas { display: none"})
        EXPECT_NE(html.find(rule), std::string::npos) << rule;
}

// 500.4 +- 16.7 lx against a 500 lx maximum: "at bound (within noise)", never missed.
TEST(ReportHtml, AValueWithinNoiseOfItsBoundIsNotCalledMissed) {
    test::TempDir dir;
    Scene scene = makeScene();  // sampler 0: 300-500 lx
    ReportData data;
    data.layoutLabel = "layout.json";
    data.samplers.resize(2);
    data.samplers[0].value = 500.4, data.samplers[0].standardError = 16.7;
    data.samplers[1].value = 150;
    GeometryEvaluator geometry(scene);
    data.geometry = geometry.evaluate(worldTransforms(scene, initialLayout(scene)), true);
    writeReportHtml(dir.path(), scene, nullptr, data);
    std::ifstream in(dir.path() / "report.html");
    std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("class=\"warn\">at bound (within noise)"), std::string::npos) << html;
    EXPECT_EQ(html.find("class=\"missed\">missed"), std::string::npos) << html;
}

TEST(ReportHtml, OptimizerResultSections) {
    test::TempDir dir;
    Scene scene = makeScene();
    OptimizerOptions options;
    options.iterations = 40;
    Optimizer optimizer(scene, options);
    OptimizerResult result = optimizer.run();
    std::string html = reportHtml(dir.path(), scene, &result);
    for (const char* part : {"<h2>Optimization</h2>", "<h2>Moves</h2>", "<h2>Constraints</h2>", "Not measured"})
        EXPECT_NE(html.find(part), std::string::npos) << part;
    // A row per move a level made; none for a move it never proposed.
    for (const LevelStats& level : result.levels)
        for (MoveType t : kMoveTypes) {
            const std::string row = "<td>" + std::string(moveName(t)) + "</td><td class=\"num\">" +
                                    std::to_string(level.moves[int(t)].proposed) + "</td>";
            if (level.moves[int(t)].proposed > 0) {
                EXPECT_NE(html.find(row), std::string::npos) << row << "\n" << html;
            }
        }
    EXPECT_EQ(html.find("<td>guided</td>"), std::string::npos);  // no light, no map
    EXPECT_TRUE(links(html).empty());  // nothing written to the folder yet
}

TEST(ReportHtml, MissAdviceFollowsTheLightBudget) {
    Scene scene = makeScene();  // sampler 0: 300-500 lx
    scene.emitters.push_back(Emitter{});
    scene.emitters.back().name = "pendant";
    const LightSamplerSpec& s = scene.samplers[0];
    SamplerBudget daylit;
    daylit.sun = 0.6, daylit.sky = 0.2, daylit.interreflected = 0.2, daylit.emitters = {0};
    EXPECT_EQ(missAdvice(scene, s, 400, daylit), "");  // met
    EXPECT_EQ(missAdvice(scene, s, 900, daylit),
              "above its target; 80% of its light is daylight (sun 60%, sky 20%): out of the sun patch, or a blind");
    EXPECT_EQ(missAdvice(scene, s, 100, daylit),
              "below its target; 80% of its light is daylight (sun 60%, sky 20%): nearer the window, or more light from a luminaire");
    SamplerBudget lamp;
    lamp.interreflected = 0.3, lamp.emitters = {0.7};
    EXPECT_EQ(missAdvice(scene, s, 100, lamp), "below its target; 70% of its light is from pendant: nearer it, or more flux");
    SamplerBudget reflected;
    reflected.interreflected = 0.9, reflected.emitters = {0.1};
    EXPECT_EQ(missAdvice(scene, s, 100, reflected),
              "below its target; 90% of its light is reflected: lighter surfaces around it, or a direct source");
    EXPECT_EQ(missAdvice(scene, s, 100, SamplerBudget{}), "below its target; no light reaches it");

    // In the page: the budget column and the list of misses.
    ReportData data;
    data.samplers = {SamplerResult{}, SamplerResult{}};
    data.samplers[0].value = 900, data.samplers[1].value = 150;
    data.budgets = {daylit, lamp};
    test::TempDir dir;
    const std::string html = reportHtml(dir.path(), scene, nullptr, data);
    EXPECT_NE(html.find("<th>light from</th>"), std::string::npos);
    EXPECT_NE(html.find("sun 60%, sky 20%, interreflection 20%"), std::string::npos);
    EXPECT_NE(html.find("Why samplers miss"), std::string::npos);
    EXPECT_NE(html.find("out of the sun patch, or a blind (one layout measured"), std::string::npos);
}

TEST(ReportViewer, MissingPackageIsSaidAndTheSectionLeftOut) {
    test::TempDir dir;
    ::setenv("LUXPLAN_WEB_DIR", (dir.path() / "nowhere").c_str(), 1);
    const std::string why = copyViewerScripts(dir.path());
    ::unsetenv("LUXPLAN_WEB_DIR");
    EXPECT_NE(why.find("three.min.js is missing (run scripts/install-deps.sh"), std::string::npos) << why;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "viewer"));
    EXPECT_EQ(viewerSection(dir.path()), "");
    // With the installed package: the scripts are copied, and the section embeds the glb.
    ASSERT_EQ(copyViewerScripts(dir.path()), "") << "run scripts/install-deps.sh";
    for (const char* script : kViewerScripts) EXPECT_TRUE(std::filesystem::is_regular_file(dir.path() / script)) << script;
    EXPECT_EQ(viewerSection(dir.path()), "");  // no scene.glb yet
    std::ofstream(dir.path() / "scene.glb", std::ios::binary) << "glTF";
    const std::string html = viewerSection(dir.path());
    EXPECT_NE(html.find("<canvas id=\"viewer-canvas\""), std::string::npos);
    EXPECT_NE(html.find("Z2xURg=="), std::string::npos);  // "glTF" in base64
    EXPECT_NE(html.find("<script src=\"viewer/three.min.js\"></script>"), std::string::npos);
}

TEST(ReportHtml, HourByHourTableColoursEachHour) {
    Scene scene = makeScene();  // 300-500 lx, and at least 100 lx
    ReportData data;
    data.hours.push_back({"2026-06-21T09:00+01:00", {SamplerResult{}, SamplerResult{}}});
    data.hours[0].samplers[0].value = 420, data.hours[0].samplers[1].value = 50;
    test::TempDir dir;
    const std::string html = reportHtml(dir.path(), scene, nullptr, data);
    EXPECT_NE(html.find("<h2>The daylight hour by hour</h2>"), std::string::npos);
    EXPECT_NE(html.find("<td>2026-06-21T09:00+01:00</td><td class=\"num met\">420.0</td><td class=\"num missed\">50.0</td>"
                        "<td class=\"num\">1 of 2</td>"),
              std::string::npos)
        << html;
    EXPECT_EQ(reportHtml(dir.path(), scene, nullptr, {}).find("hour by hour"), std::string::npos);
}

}  // namespace
}  // namespace luxplan
