// Issue 58: a measurement of very many paths (points x paths per point) said nothing for
// minutes. measure and optimize warn of its size before they start.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/small_room.h"
#include "support/temp_files.h"

namespace luxplan {
namespace measurement_size_cli {

// The small room with one sampler of 256 x 256 points inside the desk's box, the desk
// held where it is (a region of one point): each point is covered (the furniture on
// it) in every layout, so that none is traced and the runs are quick whatever their size.
std::string largeSamplerScene(test::TempDir& dir) {
    nlohmann::json s = nlohmann::json::parse(test::smallRoomScene("", 0));
    s["entities"][0]["placement"] = {{"regions", {{{"min", {2, 2}}, {"max", {2, 2}}, {"rotations", {0}}}}}};
    s["samplers"] = {{{"name", "inside"}, {"type", "planar"}, {"center", {2, 2, 0.4}}, {"size", {0.4, 0.2}},
                      {"grid", {256, 256}}, {"target", {0, 100}}}};
    return dir.write("large.json", s.dump(2)).string();
}

TEST(MeasurementSizeCli, MeasureWarnsOfALargeMeasurement) {
    test::TempDir dir;
    const std::string scene = largeSamplerScene(dir);
    test::CliResult r = test::runCli("measure " + scene + " --paths 400 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(scene + ": warning: measuring 65536 points (1 sampler) x 400 paths per point = 2.62e+07 paths, "
                                    "more than 2e+07: it may run for minutes (fewer paths per point or coarser grids take "
                                    "less)\n"),
              std::string::npos)
        << r.output;
    // 65536 x 300 = 1.97e7: quiet.
    r = test::runCli("measure " + scene + " --paths 300 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("warning: measuring"), std::string::npos) << r.output;
}

TEST(MeasurementSizeCli, OptimizeWarnsOfTheSearchsAndTheReportsMeasurements) {
    test::TempDir dir;
    const std::string scene = largeSamplerScene(dir);
    test::CliResult r = test::runCli("optimize " + scene + " -o " + (dir.path() / "out").string() +
                                     " --paths 400 --iterations 0 -q --no-pictures --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(scene + ": warning: the search measures each layout at 65536 points (1 sampler) x 400 paths "
                                    "per point = 2.62e+07 paths, more than 2e+07"),
              std::string::npos)
        << r.output;
    // The report's paths: max(report_paths_per_point (32000 by default), --paths).
    EXPECT_NE(r.output.find(scene + ": warning: the report measures the final layout at 65536 points (1 sampler) x 32000 "
                                    "paths per point = 2.1e+09 paths"),
              std::string::npos)
        << r.output;
}

}  // namespace measurement_size_cli
}  // namespace luxplan
