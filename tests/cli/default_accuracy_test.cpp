// Issue 58: "Default accuracy just short". A window-lit room under the CIE overcast sky
// (scenes/checks/window-lit-room.json), measured at the default count
// (optimizer.report_paths_per_point: `measure` without --paths, and the optimizer's
// report), must read every point within 1% of the converged value: three times its
// seed-to-seed spread at most 1% (docs/light-transport.md, "How accurate a default
// measurement is").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <luxplan/daylight/daylight.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/rt/embree_scene.h>

#include "run_cli.h"
#include "support/small_room.h"
#include "support/temp_files.h"

namespace luxplan {
namespace default_accuracy {

const std::filesystem::path kRoom = std::filesystem::path(LUXPLAN_SOURCE_DIR) / "scenes" / "checks" / "window-lit-room.json";

// Each point's worst relative error at `paths` per point, predicted as three times its
// seed-to-seed standard deviation at `shortPaths` (over `seeds` seeds) times
// sqrt(shortPaths / paths). The scaling holds on this room from 1000 to 64000 paths
// (the count it asks for came out at 22-23 thousand from runs of 1000, 4000, 16000 and
// 24000 paths alike). The spread, not each run's own standard errors: those treat the
// low-discrepancy paths as independent and read about twice the true error here (up to
// ten times near the window), which would ask for far more paths than are needed.
struct Prediction {
    double worst = 0;  // max over the points of 3 sd_i / E_i at `paths`
    int point = -1;
};

Prediction predictWorst(const std::vector<std::vector<double>>& runs, int shortPaths, int paths) {
    Prediction p;
    const size_t n = runs.size();
    for (size_t i = 0; i < runs[0].size(); ++i) {
        double mean = 0;
        for (const auto& r : runs) mean += r[i];
        mean /= double(n);
        double var = 0;
        for (const auto& r : runs) var += (r[i] - mean) * (r[i] - mean);
        const double sd = std::sqrt(var / double(n - 1));
        const double worst = 3 * sd * std::sqrt(double(shortPaths) / double(paths)) / mean;
        if (worst > p.worst) p = {worst, int(i)};
    }
    return p;
}

TEST(DefaultAccuracy, TheDefaultCountMeetsOnePercentAtEveryPointOfAWindowLitRoom) {
    const Scene scene = io::loadScene(kRoom);
    ASSERT_TRUE(scene.daylight);
    ASSERT_EQ(scene.samplers.size(), 1u);
    // The room sets no count: measure's and the report's default.
    const int defaultPaths = scene.optimizer.reportPathsPerPoint;
    EXPECT_EQ(defaultPaths, kDefaultReportPaths);
    const DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    EmbreeScene rt(scene, initialLayout(scene));
    PathTracer tracer(rt, &daylight, PathTracerOptions{});  // measure's: sun patches and exterior sun on
    // 48 seeds of 500 paths per point: about 2 s on 2 cores.
    constexpr int kShortPaths = 500, kSeeds = 48;
    std::vector<std::vector<double>> runs;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        MeasureOptions options;  // measure's: fixed, low-discrepancy
        options.pathsPerPoint = kShortPaths;
        options.seed = uint64_t(seed);
        const MeasureResult m = measureSamplers(tracer, options);
        ASSERT_EQ(m.samplers.size(), 1u);
        ASSERT_EQ(m.samplers[0].points.size(), 40u);
        for (double e : m.samplers[0].points) ASSERT_GT(e, 0);
        runs.push_back(m.samplers[0].points);
    }
    const Prediction atDefault = predictWorst(runs, kShortPaths, defaultPaths);
    EXPECT_LE(atDefault.worst, 0.01) << "point " << atDefault.point << ": " << 100 * atDefault.worst << "% at "
                                     << defaultPaths << " paths per point";
    // The old default, 1000 paths, did not (the room read 1.34-1.54% off at its
    // worst point; this one, the corners by the window wall, 2-3%): the test has teeth.
    const Prediction atOld = predictWorst(runs, kShortPaths, 1000);
    EXPECT_GT(atOld.worst, 0.02) << "point " << atOld.point;
}

// `measure` without --paths and the optimizer's report take the same default count and
// give the same numbers: `measure --layout layout.json --seed S` repeats report.json.
// The search's own independent measurements keep their own, lower count
// (selection_paths_per_point), which `info` prints.
TEST(DefaultAccuracy, MeasureRepeatsTheReportAtTheDefaultCount) {
    test::TempDir dir;
    const auto scene = dir.write("room.json", test::smallRoomScene("", 4));
    const auto out = dir.path() / "out";
    test::CliResult r =
        test::runCli("optimize " + scene.string() + " -o " + out.string() + " --iterations 20 --threads 2 -q --no-pictures");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = nlohmann::json::parse(std::ifstream(out / "report.json"));
    ASSERT_EQ(report["report_measurement"]["paths_per_point"], kDefaultReportPaths) << report["report_measurement"];
    const std::string seed = std::to_string(report["report_measurement"]["seed"].get<uint64_t>());
    test::CliResult m =
        test::runCli("measure " + scene.string() + " --layout " + (out / "layout.json").string() + " --json --threads 2 --seed " + seed);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    const auto measured = nlohmann::json::parse(m.output.substr(m.output.find('{')));
    EXPECT_EQ(measured["paths_per_point"], kDefaultReportPaths);
    ASSERT_EQ(measured["samplers"].size(), report["samplers"].size());
    for (size_t k = 0; k < measured["samplers"].size(); ++k) {
        const double a = measured["samplers"][k]["value"].get<double>(), b = report["samplers"][k]["value"].get<double>();
        EXPECT_NEAR(a, b, 1e-9 * std::abs(b)) << k;
        EXPECT_EQ(measured["samplers"][k]["points"].size(), report["samplers"][k]["points"].size()) << k;
        // Each point's standard error beside it.
        EXPECT_EQ(measured["samplers"][k]["point_std_errors"].size(), measured["samplers"][k]["points"].size()) << k;
    }
    test::CliResult info = test::runCli("info " + scene.string());
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("paths per point: 4 in the search, 1000 for its confirmations and re-measures, " +
                               std::to_string(kDefaultReportPaths) + " for the report and measure"),
              std::string::npos)
        << info.output;
}

}  // namespace default_accuracy
}  // namespace luxplan
