// The table of constraint types: every registered type reads its keys, evaluates
// and describes itself; the loader learns each type's keys from its reader; the
// overlap rule is the scene's, set by its own "constraints" entry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/relational.h>
#include <luxplan/core/error.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/scene/layout.h>
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

std::vector<std::string> problems(const json& scene) {
    test::TempDir dir;
    try {
        io::loadScene(dir.write("scene.json", scene.dump()));
    } catch (const SceneError& e) {
        std::vector<std::string> out;
        for (const auto& d : e.diagnostics()) out.push_back(d.jsonPath + ": " + d.message);
        return out;
    }
    return {};
}

std::string article(const std::string& noun) { return (std::string("aeiou").find(noun[0]) != std::string::npos ? "an " : "a ") + noun; }

TEST(ConstraintRegistry, EveryTypeReadsEvaluatesAndDescribes) {
    ASSERT_FALSE(constraintKinds().empty());
    for (const ConstraintKindEntry& k : constraintKinds()) {
        SCOPED_TRACE(k.name);
        EXPECT_EQ(findConstraintKind(k.name), &k);
        json c = {{"type", k.name}, {"a", "desk"}, {"b", "chair"}, {"weight", 2}};
        for (const std::string& key : readerKeys(k)) c[key] = key == "max" ? 3 : 0.5;
        test::TempDir dir;
        Scene scene = io::loadScene(dir.write("scene.json", sceneWith(c).dump()));
        ASSERT_EQ(scene.constraints.size(), 1u);
        const ConstraintSpec& spec = scene.constraints[0];
        EXPECT_STREQ(spec.kind->name(), k.name);
        EXPECT_EQ(spec.weight, 2);

        EntityInfo info(scene);
        PenaltyTerm t = evaluateRelational(scene, info, worldTransforms(scene, initialLayout(scene)), 0);
        EXPECT_EQ(t.kind, spec.kind.get());
        EXPECT_STREQ(termName(t), k.name);
        EXPECT_TRUE(std::isfinite(t.penalty));
        EXPECT_GE(t.penalty, 0);
        EXPECT_EQ(t.weight, 2);

        EXPECT_FALSE(spec.kind->describe().empty());
        std::string text = describe(scene, t);
        EXPECT_EQ(text.rfind(std::string(k.name) + " \"desk\" / \"chair\" (/constraints/0): ", 0), 0u) << text;
        nlohmann::ordered_json j;
        spec.kind->report(t, j);
        EXPECT_TRUE(j.contains("value")) << j.dump();
        EXPECT_EQ(j["unit"], spec.kind->measuresAngle() ? "deg" : "m");
        EXPECT_TRUE(spec.kind->toleranceDeg() || spec.kind->distanceRange());
    }
}

// The loader's family of constraint keys is what the readers read: a key one type
// reads is reported on another as not applying to it.
TEST(ConstraintRegistry, FamilyKeysComeFromTheReaders) {
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

TEST(ConstraintRegistry, UnknownTypeListsTheRegisteredOnesAndTheOverlapRule) {
    std::vector<std::string> names = constraintTypeNames();
    EXPECT_EQ(names.size(), constraintKinds().size() + 1);
    EXPECT_EQ(names.back(), kOverlapRuleName);
    EXPECT_EQ(problems(sceneWith({{"type", "focsu"}, {"a", "desk"}, {"b", "chair"}})),
              std::vector<std::string>{"/constraints/0/type: unknown constraint type \"focsu\" (did you mean \"focus\"?) "
                                       "(alignment, distance, focus, conversation or overlap)"});
}

TEST(ConstraintRegistry, TheOverlapRuleIsTheScenes) {
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

// Built in C++ (flattenScene's cohesion), a type measures what its scene-file twin does.
TEST(ConstraintRegistry, FactoriesMatchTheReaders) {
    const std::pair<json, std::shared_ptr<const ConstraintKind>> cases[] = {
        {{{"type", "alignment"}, {"tolerance_deg", 12}}, alignmentConstraint(12)},
        {{{"type", "distance"}, {"min", 0.5}, {"max", 0.8}, {"tolerance", 0.2}}, distanceConstraint({0.5, 0.8, 0.2})},
        {{{"type", "focus"}, {"tolerance_deg", 12}}, focusConstraint(12)},
        {{{"type", "conversation"}, {"min", 0.2}, {"max", 0.6}, {"tolerance_deg", 12}},
         conversationConstraint({0.2, 0.6, std::nullopt}, 12)},
    };
    for (const auto& [file, kind] : cases) {
        json c = file;
        c["a"] = "desk", c["b"] = "chair";
        test::TempDir dir;
        Scene scene = io::loadScene(dir.write("scene.json", sceneWith(c).dump()));
        scene.entities[1].position.x += 0.3;  // off axis: every angle and distance counts
        Layout layout = initialLayout(scene);
        layout.placements[1].rotationDeg = 165;
        EntityInfo info(scene);
        const auto world = worldTransforms(scene, layout);
        PenaltyTerm read = evaluateRelational(scene, info, world, 0);
        scene.constraints[0].kind = kind;
        PenaltyTerm built = evaluateRelational(scene, info, world, 0);
        EXPECT_STREQ(kind->name(), file["type"].get<std::string>().c_str());
        EXPECT_EQ(read.penalty, built.penalty) << kind->name();
        EXPECT_GT(read.penalty, 0) << kind->name();
        EXPECT_EQ(read.parts, built.parts);
        EXPECT_EQ(scene.constraints[0].kind->describe(), kind->describe());
    }
}

}  // namespace
}  // namespace luxplan
