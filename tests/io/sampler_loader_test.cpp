// What the loader says about sampler keys a type does not read (moved from
// tests/lightsamplers/cylindrical_test.cpp, which builds its scenes in C++).
#include <gtest/gtest.h>

#include <luxplan/core/error.h>
#include <luxplan/io/scene_loader.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

TEST(SamplerLoader, CylindricalReadsOnlyItsCentre) {
    test::TempDir dir;
    auto file = dir.write("scene.json", R"({"luxplan": 1,
      "samplers": [{"name": "face", "type": "cylindrical", "center": [0, 0, 1.2], "normal": [0, 0, 1], "target": [150, null]}]})");
    try {
        io::loadScene(file);
        FAIL() << "a cylindrical sampler has no normal";
    } catch (const SceneError& e) {
        ASSERT_EQ(e.diagnostics().size(), 1u);
        EXPECT_EQ(e.diagnostics()[0].jsonPath + ": " + e.diagnostics()[0].message,
                  "/samplers/0/normal: \"normal\" does not apply to a cylindrical sampler");
    }
}

}  // namespace
}  // namespace luxplan
