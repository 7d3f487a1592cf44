// Fig. 9's stand lamps light the room: the apartment by night measured with its two
// 3500 lm lamps and with them taken out (their spheres sit in the stand_lamp's open,
// translucent shade). Before the shade was opened the lamps added nothing (146.9 lx
// on the dining table with them, 146.3 without).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

namespace fs = std::filesystem;

struct SamplerReading {
    double value = 0, error = 0;
};

SamplerReading sampler(const fs::path& scene, const std::string& name) {
    test::CliResult r = test::runCli("measure " + scene.string() + " --json --paths 2048 --seed 1 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json measured = nlohmann::json::parse(r.output);
    for (const auto& s : measured["samplers"])
        if (s["name"] == name) return {s["value"].get<double>(), s["std_error"].get<double>()};
    ADD_FAILURE() << "no sampler " << name;
    return {};
}

void dropEmitters(nlohmann::json& entity) {
    entity.erase("emitters");
    if (entity.contains("children"))
        for (auto& c : entity["children"]) dropEmitters(c);
}

TEST(Fig9Lamps, TheStandLampsLightTheRoom) {
    const fs::path night = fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / "paper" / "fig9-apartment-night.json";
    nlohmann::json scene = nlohmann::json::parse(std::ifstream(night));
    for (auto& e : scene["entities"]) dropEmitters(e);
    test::TempDir dir;
    const fs::path dark = dir.write("no-lamps.json", scene.dump());
    for (const char* name : {"dining.table", "reading.book"}) {
        SamplerReading with = sampler(night, name), without = sampler(dark, name);
        double sigma = std::hypot(with.error, without.error);
        EXPECT_GT(with.value - without.value, 5 * sigma) << name << ": " << with.value << " +- " << with.error << " lx with the lamps, "
                                                         << without.value << " +- " << without.error << " without";
    }
    // The reading lamp stands by the armchair: it gives most of the reader's light.
    EXPECT_GT(sampler(night, "reading.book").value, 4 * sampler(dark, "reading.book").value);
}

}  // namespace
}  // namespace luxplan
