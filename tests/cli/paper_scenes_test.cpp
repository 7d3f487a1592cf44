// Every bundled scene of scenes/paper/ validates, optimizes (a few iterations, few
// paths) and leaves every output: pictures that decode, a .glb that parses, a layout
// that reads back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <tiny_gltf.h>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

namespace fs = std::filesystem;

const fs::path kPaperScenes = fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / "paper";

std::vector<std::string> paperScenes() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kPaperScenes)) {
        std::string name = entry.path().filename().string();
        // Hidden files are scratch (scripts/adaptive-stops.py writes its scenes there).
        if (entry.path().extension() == ".json" && name[0] != '.')
            names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

class PaperScene : public ::testing::TestWithParam<std::string> {};

TEST_P(PaperScene, ValidatesOptimizesAndWritesEveryOutput) {
    const fs::path scene = kPaperScenes / (GetParam() + ".json");
    test::CliResult v = test::runCli("validate " + scene.string());
    ASSERT_EQ(v.exitCode, 0) << v.output;

    test::TempDir dir;
    const fs::path out = dir.path() / "out";
    test::CliResult r = test::runCli("optimize " + scene.string() + " -o " + out.string() +
                                     " --iterations 8 --paths 2 --threads 2 -q --spp 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"layout.json", "report.json", "trace.csv", "report.html"})
        EXPECT_TRUE(fs::is_regular_file(out / f)) << f;
    for (const char* png : {"plan.png", "render.png", "convergence.png"}) {
        int w = 0, h = 0, n = 0;
        EXPECT_TRUE(stbi_info((out / png).c_str(), &w, &h, &n) && w > 0 && h > 0) << png;
    }
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, (out / "scene.glb").string())) << err;
    EXPECT_GT(model.nodes.size(), 1u);

    test::CliResult back = test::runCli("validate " + scene.string() + " --layout " + (out / "layout.json").string());
    EXPECT_EQ(back.exitCode, 0) << back.output;
}

INSTANTIATE_TEST_SUITE_P(Bundled, PaperScene, ::testing::ValuesIn(paperScenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(PaperScenes, AllTwelveAreBundledAndTheLabLayoutReadsBack) {
    EXPECT_EQ(paperScenes().size(), 12u);
    test::CliResult r = test::runCli("validate " + (kPaperScenes / "fig8-lab.json").string() + " --layout " +
                                     (kPaperScenes / "layouts" / "fig8-lab-symmetric.json").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// The C that report.json gives is the result's, not the search's luck: an independent
// measurement of layout.json (another seed, the same paths) agrees with it within its
// noise, on a daylit scene with a glare sampler aimed near the sun, for every seed.
TEST(PaperScenes, TheReportedCostAgreesWithAnIndependentMeasure) {
    const fs::path scene = kPaperScenes / "fig4-glare.json";
    for (int seed : {1, 2, 3}) {
        test::TempDir dir;
        const fs::path out = dir.path() / "out";
        test::CliResult r = test::runCli("optimize " + scene.string() + " -o " + out.string() + " --iterations 300 --paths 16" +
                                         " --seed " + std::to_string(seed) + " --threads 2 -q --no-pictures");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto report = nlohmann::json::parse(std::ifstream(out / "report.json"));
        const int paths = report["report_measurement"]["paths_per_point"].get<int>();
        EXPECT_EQ(paths, 512);
        test::CliResult m = test::runCli("measure " + scene.string() + " --layout " + (out / "layout.json").string() +
                                         " --paths " + std::to_string(paths) + " --seed " + std::to_string(1000 + seed) +
                                         " --threads 2 --json");
        ASSERT_EQ(m.exitCode, 0) << m.output;
        const auto measured = nlohmann::json::parse(m.output.substr(m.output.find('{')));
        const double c = report["C"].get<double>(), se = report["C_std_error"].get<double>();
        const double c2 = measured["C"].get<double>(), se2 = measured["C_std_error"].get<double>();
        EXPECT_GT(se, 0);
        EXPECT_LT(std::abs(c - c2), 4 * std::hypot(se, se2) + 1e-9)
            << "seed " << seed << ": reported " << c << " +- " << se << ", measured " << c2 << " +- " << se2;
        EXPECT_DOUBLE_EQ(measured["G"].get<double>(), report["G"].get<double>());
    }
}

}  // namespace
}  // namespace luxplan
