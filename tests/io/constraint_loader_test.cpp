// What the loader makes of the constraint types' readers: its family of keys is what
// the readers read, unknown types list the registered ones, and the overlap rule is
// set by its own "constraints" entry (moved from tests/constraints/, which builds its
// scenes in C++).
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/core/error.h>
#include <luxplan/io/scene_loader.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

// Two boxes 1 m apart, facing each other; `constraint` between them.
json sceneWith(const json& constraint) {
    json s = json::parse(R"({
      "luxplan": 1,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "entities": [
        {"name": "desk", "position": [2, 2], "parts": [{"box": {"size": [1.0, 0.5, 0.75]}, "material": "m"}]},
        {"name": "chair", "position": [2, 1], "rotation": 180, "parts": [{"box": {"size": [0.4, 0.4, 0.75]}, "material": "m"}]}
      ]})");
    s["constraints"] = json::array({constraint});
    return s;
}

std::vector<std::string> readerKeys(const ConstraintKindEntry& k) {
    return luxplan::json::probeKeys([&](const luxplan::json::Fields& f) { k.read(f); });
}

using test::problems;

std::string article(const std::string& noun) { return (std::string("aeiou").find(noun[0]) != std::string::npos ? "an " : "a ") + noun; }

// The loader's family of constraint keys is what the readers read: a key one type
// reads is reported on another as not applying to it.
TEST(ConstraintLoader, FamilyKeysComeFromTheReaders) {
    for (const ConstraintKindEntry& k : constraintKinds()) {
        std::vector<std::string> own = readerKeys(k);
        for (const ConstraintKindEntry& other : constraintKinds()) {
            for (const std::string& key : readerKeys(other)) {
                if (std::find(own.begin(), own.end(), key) != own.end()) continue;
                json c = {{"type", k.name}, {"a", "desk"}, {"b", "chair"}};
                for (const std::string& mine : own) c[mine] = mine == "max" ? 3 : 0.5;
                c[key] = 1;
                EXPECT_EQ(problems(sceneWith(c)),
                          std::vector<std::string>{"/constraints/0/" + key + ": \"" + key + "\" does not apply to " +
                                                   article(std::string(k.name) + " constraint")});
            }
        }
    }
}

TEST(ConstraintLoader, UnknownTypeListsTheRegisteredOnesAndTheOverlapRule) {
    EXPECT_EQ(problems(sceneWith({{"type", "focsu"}, {"a", "desk"}, {"b", "chair"}})),
              std::vector<std::string>{"/constraints/0/type: unknown constraint type \"focsu\" (did you mean \"focus\"?) "
                                       "(alignment, distance, focus, conversation or overlap)"});
}

TEST(ConstraintLoader, TheOverlapRuleIsTheScenes) {
    json s = sceneWith({{"type", "distance"}, {"a", "desk"}, {"b", "chair"}, {"min", 0.5}, {"max", 2}});
    s["constraints"].push_back({{"type", "overlap"}, {"tolerance", 0.1}, {"weight", 3}});
    test::TempDir dir;
    Scene scene = io::loadScene(dir.write("scene.json", s.dump()));
    EXPECT_EQ(scene.constraints.size(), 1u);
    EXPECT_EQ(scene.overlap.tolerance, 0.1);
    EXPECT_EQ(scene.overlap.weight, 3);
    EXPECT_EQ(scene.overlap.jsonPath, "/constraints/1");
    s["constraints"][1]["a"] = "desk";
    EXPECT_EQ(problems(s), std::vector<std::string>{"/constraints/1/a: \"a\" does not apply to an overlap constraint"});
    s["constraints"].erase(1);
    scene = io::loadScene(dir.write("scene.json", s.dump()));
    EXPECT_EQ(scene.overlap.tolerance, 0.05);
    EXPECT_EQ(scene.overlap.weight, 1);
    EXPECT_TRUE(scene.overlap.jsonPath.empty());
}

}  // namespace
}  // namespace luxplan
