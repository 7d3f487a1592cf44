// `luxplan measure --json` of every bundled scene against the stored reference of
// tests/reference/measure/ (scripts/measure-reference.sh, seed 1). The fresh run uses
// another seed at the same path count, so the two are independent estimates of one
// value: each sampler's difference must lie within 5 combined standard errors. A
// change of the light transport, the loader or the sampler placement that moves a
// value by more than its noise fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run_cli.h"

namespace luxplan {
namespace {

namespace fs = std::filesystem;

const fs::path kReference = fs::path(LUXPLAN_SOURCE_DIR) / "tests" / "reference" / "measure";

std::vector<std::string> referenceScenes() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kReference))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

fs::path sceneFile(const std::string& name) {
    fs::path paper = fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / "paper" / (name + ".json");
    return fs::exists(paper) ? paper : fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / "demo" / (name + ".json");
}

class MeasureReference : public ::testing::TestWithParam<std::string> {};

TEST_P(MeasureReference, AgreesWithTheStoredMeansWithinTheirErrors) {
    nlohmann::json reference = nlohmann::json::parse(std::ifstream(kReference / (GetParam() + ".json")));
    const int paths = reference["paths_per_point"].get<int>();
    test::CliResult r = test::runCli("measure " + sceneFile(GetParam()).string() + " --json --seed 2 --threads 2 --paths " +
                                     std::to_string(paths));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json fresh = nlohmann::json::parse(r.output);
    const auto& a = reference["samplers"];
    const auto& b = fresh["samplers"];
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) {
        const std::string name = a[k]["name"].get<std::string>();
        ASSERT_EQ(b[k]["name"].get<std::string>(), name);
        EXPECT_EQ(b[k]["type"], a[k]["type"]) << name;
        EXPECT_EQ(b[k]["target"], a[k]["target"]) << name;
        EXPECT_EQ(b[k]["points"].size(), a[k]["points"].size()) << name;
        double va = a[k]["value"].get<double>(), vb = b[k]["value"].get<double>();
        double ea = a[k]["std_error"].get<double>(), eb = b[k]["std_error"].get<double>();
        double sigma = std::sqrt(ea * ea + eb * eb);
        // A sampler that sees no light at all reads exactly 0 in both runs.
        if (sigma == 0) EXPECT_EQ(va, vb) << name;
        else EXPECT_LT(std::abs(va - vb) / sigma, 5.0) << name << ": reference " << va << " +- " << ea << ", now " << vb
                                                       << " +- " << eb;
    }
}

INSTANTIATE_TEST_SUITE_P(Bundled, MeasureReference, ::testing::ValuesIn(referenceScenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(MeasureReferenceFiles, CoverEveryBundledScene) {
    // The paper's twelve scenes (not the lab's stored layout) and the demo office.
    EXPECT_EQ(referenceScenes().size(), 13u);
}

}  // namespace
}  // namespace luxplan
