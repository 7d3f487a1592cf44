// `luxplan validate` warns about what loads but cannot be what was meant, as
// FILE: /json/path: warning: message lines, and still accepts the scene.
#include <gtest/gtest.h>

#include <filesystem>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

TEST(ValidateWarnings, PrintedWithTheirPathAndTheSceneStillValid) {
    test::TempDir dir;
    // A lamp in a closed opaque shade, and a luminaire beyond the east wall.
    auto file = dir.write("lamp.json", R"({"luxplan": 1,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                    "materials": {"floor": "m", "walls": "m", "ceiling": "m"}}],
      "luminaires": [{"name": "street", "shape": "sphere", "center": [7, 2, 2], "radius": 0.1, "flux_lm": 1000}],
      "entities": [{"name": "lamp", "position": [3, 2],
                    "placement": {"regions": [{"min": [1,1], "max": [5,3]}]},
                    "parts": [{"box": {"size": [0.35, 0.35, 0.32], "center": [0, 0, 1.44]}, "material": "m"}],
                    "emitters": [{"name": "bulb", "shape": "sphere", "center": [0, 0, 1.45], "radius": 0.12,
                                  "flux_lm": 3500}]}]})");
    test::CliResult r = test::runCli("validate " + file.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /entities/0/emitters/0: warning: emitter \"lamp.bulb\" is enclosed by opaque "
                                            "geometry of \"lamp\""),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /luminaires/0: warning: luminaire \"street\" is outside the room"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(file.string() + ": valid"), std::string::npos) << r.output;
    // measure and optimize say the same before their work.
    for (const std::string& command :
         {"measure " + file.string() + " --paths 1", "optimize " + file.string() + " -o " + (dir.path() / "out").string() +
                                                        " --iterations 2 --paths 1 -q --no-pictures"}) {
        test::CliResult c = test::runCli(command);
        EXPECT_EQ(c.exitCode, 0) << command << "\n" << c.output;
        EXPECT_NE(c.output.find(file.string() + ": /entities/0/emitters/0: warning: emitter \"lamp.bulb\" is enclosed"),
                  std::string::npos)
            << command << "\n" << c.output;
    }
}

TEST(ValidateWarnings, NoneForTheBundledScenes) {
    namespace fs = std::filesystem;
    std::vector<fs::path> scenes = {fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / "demo" / "office.json"};
    for (const auto& entry : fs::directory_iterator(fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / "paper"))
        if (entry.path().extension() == ".json") scenes.push_back(entry.path());
    for (const fs::path& scene : scenes) {
        test::CliResult r = test::runCli("validate " + scene.string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    }
}

}  // namespace
}  // namespace luxplan
