// The bundled open-plan office (six workstations from one template) through the
// command line: every output names samplers and constraints by their scoped names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

const std::string kOpenPlan = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/open-plan.json";

TEST(TemplatesCli, MeasureNamesEachCopysSamplersByTheirPath) {
    test::CliResult r = test::runCli("measure " + kOpenPlan + " --json --paths 4 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto measured = nlohmann::json::parse(r.output);
    std::set<std::string> names;
    for (const auto& s : measured["samplers"]) names.insert(s["name"].get<std::string>());
    std::set<std::string> expected;
    for (int i = 1; i <= 6; ++i) {
        expected.insert("ws" + std::to_string(i) + ".desk.task");
        expected.insert("ws" + std::to_string(i) + ".monitor.glare");
    }
    EXPECT_EQ(names, expected);
}

TEST(TemplatesCli, TheReportNamesEachCopysConstraint) {
    test::TempDir dir;
    // Its report at 64 paths per point, not the default's 32000: the names are the test.
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(kOpenPlan));
    scene["optimizer"]["report_paths_per_point"] = 64;
    const std::string file = dir.write("open-plan.json", scene.dump(2)).string();
    test::CliResult r = test::runCli("optimize " + file + " -o " + (dir.path() / "out").string() +
                                     " --iterations 20 --paths 4 --no-pictures --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto report = nlohmann::json::parse(std::ifstream(dir.path() / "out" / "report.json"));
    std::set<std::string> names;
    for (const auto& c : report["constraints"])
        if (c.contains("name")) names.insert(c["name"].get<std::string>());
    EXPECT_EQ(names, (std::set<std::string>{"ws1.seat", "ws2.seat", "ws3.seat", "ws4.seat", "ws5.seat", "ws6.seat"}));
    for (const auto& c : report["constraints"])
        if (c.value("name", "") == "ws4.seat") {
            EXPECT_EQ(c["a"], "ws4.chair");
            EXPECT_EQ(c["b"], "ws4.desk");
            EXPECT_EQ(c["json_path"], "/templates/workstation/constraints/0");
        }
}

}  // namespace
}  // namespace luxplan
