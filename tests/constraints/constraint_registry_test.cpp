// The table of constraint types: every registered type reads its keys, evaluates
// and describes itself; the overlap rule is the scene's. What the loader makes of
// the readers (family keys, messages, the overlap entry) is tests/io/constraint_loader_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/constraints/entity_info.h>
#include <luxplan/constraints/relational.h>
#include <luxplan/scene/layout.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using nlohmann::json;

// Two boxes 1 m apart, facing each other; `kind` between them.
Scene sceneWith(std::shared_ptr<const ConstraintKind> kind, double weight = 1) {
    return test::SceneBuilder()
        .material("m", test::diffuse(0.5))
        .entity("desk", {2, 2, 0}).part({1.0, 0.5, 0.75}, "m").end()
        .entity("chair", {2, 1, 0}, 180).part({0.4, 0.4, 0.75}, "m").end()
        .constraint(std::move(kind), "desk", "chair", weight)
        .build();
}

std::vector<std::string> readerKeys(const ConstraintKindEntry& k) {
    return luxplan::json::probeKeys([&](const luxplan::json::Fields& f) { k.read(f); });
}

// A type's own keys read by its registered reader, as the loader reads the entry
// /constraints/0; what it reports goes to `problems`.
std::shared_ptr<const ConstraintKind> readKind(const ConstraintKindEntry& k, const json& keys, std::vector<std::string>& problems) {
    luxplan::json::DiagnosticSink sink;
    luxplan::json::Fields f(sink, keys, "/constraints/0");
    auto kind = k.read(f);
    f.finish();
    for (const auto& d : sink.diagnostics) problems.push_back(d.jsonPath + ": " + d.message);
    return kind;
}

TEST(ConstraintRegistry, EveryTypeReadsEvaluatesAndDescribes) {
    ASSERT_FALSE(constraintKinds().empty());
    for (const ConstraintKindEntry& k : constraintKinds()) {
        SCOPED_TRACE(k.name);
        EXPECT_EQ(findConstraintKind(k.name), &k);
        json c = json::object();
        for (const std::string& key : readerKeys(k)) c[key] = key == "max" ? 3 : 0.5;
        std::vector<std::string> problems;
        Scene scene = sceneWith(readKind(k, c, problems), 2);
        EXPECT_EQ(problems, std::vector<std::string>{});
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

TEST(ConstraintRegistry, TypeNamesAreTheRegisteredOnesAndTheOverlapRule) {
    std::vector<std::string> names = constraintTypeNames();
    EXPECT_EQ(names.size(), constraintKinds().size() + 1);
    EXPECT_EQ(names.back(), kOverlapRuleName);
    EXPECT_EQ(findConstraintKind(kOverlapRuleName), nullptr);  // a rule of the scene, not a type
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
        c.erase("type");
        std::vector<std::string> problems;
        Scene scene = sceneWith(readKind(*findConstraintKind(file["type"].get<std::string>()), c, problems));
        EXPECT_EQ(problems, std::vector<std::string>{});
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
