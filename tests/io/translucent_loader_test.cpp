// The loader's translucent material: its keys, and what it refuses.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/io/scene_loader.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

json scene(const json& material) {
    json j = {{"luxplan", 1}, {"materials", {{"shade", material}}}};
    return j;
}

using test::problems;

TEST(TranslucentLoader, ReadsReflectanceAndTransmittance) {
    test::TempDir dir;
    Scene s = io::loadScene(dir.write("scene.json", scene({{"type", "translucent"}, {"reflectance", {0.5, 0.4, 0.3}},
                                                           {"transmittance", 0.35}})
                                                        .dump()));
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.type, MaterialType::Translucent);
    EXPECT_EQ(m.reflectance, Vec3(0.5, 0.4, 0.3));
    EXPECT_EQ(m.diffuseTransmittance, Vec3(0.35, 0.35, 0.35));
}

TEST(TranslucentLoader, RefusesMoreLightOutThanIn) {
    EXPECT_EQ(problems(scene({{"type", "translucent"}, {"reflectance", {0.5, 0.7, 0.3}}, {"transmittance", 0.4}})),
              std::vector<std::string>{"/materials/shade/transmittance: reflectance + transmittance must be at most 1, got "
                                       "0.7 + 0.4 in the green channel"});
    EXPECT_EQ(problems(scene({{"type", "translucent"}, {"reflectance", 0.5}})),
              std::vector<std::string>{"/materials/shade: missing required key \"transmittance\""});
    EXPECT_EQ(problems(scene({{"type", "translucent"}, {"transmittance", 0.5}})),
              std::vector<std::string>{"/materials/shade: missing required key \"reflectance\""});
    EXPECT_EQ(problems(scene({{"type", "translucent"}, {"reflectance", 0.5}, {"transmittance", 1.5}})),
              std::vector<std::string>{"/materials/shade/transmittance: value 1.5 outside [0, 1]"});
    std::vector<std::string> p =
        problems(scene({{"type", "translucent"}, {"reflectance", 0.5}, {"transmittance", 0.2}, {"roughness", 0.1}}));
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/materials/shade/roughness: ", 0), 0u) << p[0];
}

}  // namespace
}  // namespace luxplan
