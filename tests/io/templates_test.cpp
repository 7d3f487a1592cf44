// Templates ("templates" and an entity's "template") and names scoped by their
// entity: what the loader builds from them and how it refuses their mistakes.
#include <algorithm>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/io/scene_loader.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

// A room with a workstation template (a desk with its task area, a chair, the rule
// between them) and `copies` entities made from it.
json workstations(int copies) {
    json s = json::parse(R"({
      "luxplan": 1,
      "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
      "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [12, 8, 3]},
                    "materials": {"floor": "m", "walls": "m", "ceiling": "m"}}],
      "luminaires": [{"name": "panel", "shape": "rect", "center": [6, 4, 2.99], "normal": [0, 0, -1], "size": [0.6, 0.6], "flux_lm": 3200}],
      "templates": {
        "workstation": {
          "placement": {"regions": [{"min": [1, 1], "max": [11, 7], "rotations": [0, 90, 180, 270]}]},
          "children": [
            {"name": "desk", "parts": [{"preset": "desk", "material": "m"}],
             "samplers": [{"name": "task", "type": "planar", "center": [0, 0, 0.76], "size": [1.2, 0.6], "target": [500, null]}]},
            {"name": "chair", "position": [0, -0.6],
             "placement": {"regions": [{"min": [-0.5, -0.9], "max": [0.5, -0.5], "rotation_range": [-20, 20]}]},
             "parts": [{"preset": "office_chair", "material": "m"}]}],
          "samplers": [{"name": "area", "type": "planar", "center": [0, 0, 0.8], "size": [2, 2], "target": [300, null]}],
          "constraints": [{"name": "seat", "type": "distance", "a": "chair", "b": "desk", "min": 0.4, "max": 0.8}]
        }
      },
      "entities": []
    })");
    for (int i = 0; i < copies; ++i)
        s["entities"].push_back({{"name", "ws" + std::to_string(i + 1)}, {"template", "workstation"}, {"position", {2 + 1.5 * i, 2}}});
    return s;
}

Scene load(const json& scene, test::TempDir& dir) { return io::loadScene(dir.write("scene.json", scene.dump(2))); }

using test::onlyProblem;
using test::problems;

std::vector<std::string> samplerNames(const Scene& s) {
    std::vector<std::string> names;
    for (const auto& x : s.samplers) names.push_back(x.name);
    return names;
}

TEST(Templates, SixWorkstationsFromOneDefinition) {
    test::TempDir dir;
    Scene s = load(workstations(6), dir);
    // Each copy: the group, its desk and its chair; the panel is fixed.
    ASSERT_EQ(s.entities.size(), 18u);
    ASSERT_EQ(s.samplers.size(), 12u);
    ASSERT_EQ(s.constraints.size(), 6u);
    for (int i = 1; i <= 6; ++i) {
        const std::string ws = "ws" + std::to_string(i);
        int group = s.findEntity(ws), desk = s.findEntity(ws + ".desk"), chair = s.findEntity(ws + ".chair");
        ASSERT_GE(group, 0) << ws;
        ASSERT_GE(desk, 0) << ws;
        ASSERT_GE(chair, 0) << ws;
        EXPECT_EQ(s.entities[group].position, Vec3(2 + 1.5 * (i - 1), 2, 0));
        EXPECT_EQ(s.entities[group].regions.size(), 1u);  // the template's placement
        auto names = samplerNames(s);
        EXPECT_NE(std::find(names.begin(), names.end(), ws + ".desk.task"), names.end()) << ws;
        EXPECT_NE(std::find(names.begin(), names.end(), ws + ".area"), names.end()) << ws;
        // The template's rule names its members relatively: each copy's own chair and desk.
        const ConstraintSpec& c = s.constraints[size_t(i - 1)];
        EXPECT_EQ(c.name, ws + ".seat");
        EXPECT_STREQ(c.kind->name(), "distance");
        EXPECT_EQ(c.a, chair);
        EXPECT_EQ(c.b, desk);
    }
}

TEST(Templates, TheEntitysOwnKeysReplaceTheTemplates) {
    json scene = workstations(2);
    scene["entities"][1]["rotation"] = 90;
    scene["entities"][1]["placement"] = {{"regions", {{{"min", {3, 3}}, {"max", {4, 4}}}}}};
    scene["entities"][1]["fixed"] = true;
    test::TempDir dir;
    Scene s = load(scene, dir);
    const Entity& a = s.entities[size_t(s.findEntity("ws1"))];
    const Entity& b = s.entities[size_t(s.findEntity("ws2"))];
    EXPECT_EQ(a.rotationDeg, 0);
    EXPECT_EQ(b.rotationDeg, 90);
    ASSERT_EQ(a.regions.size(), 1u);
    EXPECT_EQ(a.regions[0].hi.x, 11);
    EXPECT_TRUE(b.regions.empty());  // fixed: its placement is not read
}

TEST(Templates, ATemplateMayUseAnotherAsAChild) {
    json scene = workstations(0);
    scene["templates"]["pair"] = json::parse(R"({"children": [{"name": "left", "template": "workstation"},
                                                              {"name": "right", "template": "workstation", "position": [1.5, 0]}]})");
    scene["entities"].push_back({{"name", "p"}, {"template", "pair"}, {"position", {4, 4}}});
    test::TempDir dir;
    Scene s = load(scene, dir);
    EXPECT_GE(s.findEntity("p.left.desk"), 0);
    EXPECT_GE(s.findEntity("p.right.chair"), 0);
    auto names = samplerNames(s);
    EXPECT_NE(std::find(names.begin(), names.end(), "p.right.desk.task"), names.end());
    ASSERT_EQ(s.constraints.size(), 2u);
    EXPECT_EQ(s.constraints[1].name, "p.right.seat");
    EXPECT_EQ(s.constraints[1].a, s.findEntity("p.right.chair"));
}

TEST(ScopedNames, TheSameNameInTwoEntitiesIsValidTwiceInOneAnError) {
    json scene = workstations(0);
    json desk = scene["templates"]["workstation"]["children"][0];
    scene.erase("templates");
    desk["placement"] = {{"regions", {{{"min", {1, 1}}, {"max", {11, 7}}}}}};
    desk["name"] = "d1";
    scene["entities"].push_back(desk);
    desk["name"] = "d2";
    scene["entities"].push_back(desk);
    scene["constraints"] = json::parse(R"([{"name": "apart", "type": "distance", "a": "d1", "b": "d2", "min": 1, "max": 5}])");
    {
        test::TempDir dir;
        Scene s = load(scene, dir);
        EXPECT_EQ(samplerNames(s), (std::vector<std::string>{"d1.task", "d2.task"}));
        EXPECT_EQ(s.constraints.at(0).name, "apart");  // a scene's constraint keeps its plain name
    }
    scene["entities"][1]["samplers"].push_back(scene["entities"][1]["samplers"][0]);
    EXPECT_EQ(onlyProblem(scene), "/entities/1/samplers/1/name: duplicate sampler name \"d2.task\" (also at /entities/1/samplers/0)");
    scene["entities"][1]["samplers"].erase(1);
    scene["constraints"].push_back(scene["constraints"][0]);
    EXPECT_EQ(onlyProblem(scene), "/constraints/1/name: duplicate constraint name \"apart\" (also at /constraints/0)");
}

TEST(Templates, AMistakeInATemplateIsReportedOnceWhereItIsWritten) {
    json scene = workstations(3);
    scene["templates"]["workstation"]["children"][0]["samplers"][0]["size"] = {1.2, -1};
    EXPECT_EQ(onlyProblem(scene), "/templates/workstation/children/0/samplers/0/size: sampler has zero area: size 1.2 x -1");
    scene = workstations(2);
    scene["templates"]["workstation"]["colour"] = "red";
    auto p = problems(scene);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("/templates/workstation/colour: unknown key \"colour\"", 0), 0u) << p[0];
    // A key the entity sets is reported at the entity.
    scene = workstations(2);
    scene["entities"][1]["rotation"] = "north";
    EXPECT_EQ(onlyProblem(scene), "/entities/1/rotation: expected a number, got a string");
}

TEST(Templates, RefusedWithTheirPath) {
    json scene = workstations(1);
    scene["entities"][0]["template"] = "workstaton";
    EXPECT_EQ(onlyProblem(scene), "/entities/0/template: unknown template \"workstaton\" (did you mean \"workstation\"?) (workstation)");
    scene["entities"][0]["template"] = 3;
    EXPECT_EQ(onlyProblem(scene), "/entities/0/template: expected a template name, got a number");
    scene = workstations(1);
    scene.erase("templates");
    EXPECT_EQ(onlyProblem(scene), "/entities/0/template: unknown template \"workstation\" (the scene has no \"templates\")");
    scene = workstations(1);
    scene["templates"]["workstation"]["name"] = "ws";
    EXPECT_EQ(onlyProblem(scene), "/templates/workstation/name: a template takes its name from the entity that uses it");
    scene = workstations(1);
    scene["templates"]["bad.name"] = json::object();
    EXPECT_EQ(onlyProblem(scene), "/templates/bad.name: template names must be non-empty and must not contain '.'");
    scene = workstations(1);
    scene["templates"]["x"] = json::array();
    EXPECT_EQ(onlyProblem(scene), "/templates/x: expected a template object (an entity without \"name\"), got an array");
    scene = workstations(1);
    scene["templates"] = json::array();
    EXPECT_EQ(onlyProblem(scene), "/templates: expected an object of templates by name, got an array");
}

TEST(Templates, ATemplateThatContainsItselfIsRefused) {
    json scene = workstations(1);
    scene["templates"]["workstation"]["children"].push_back({{"name", "again"}, {"template", "workstation"}});
    EXPECT_EQ(onlyProblem(scene), "/templates/workstation/children/2/template: template \"workstation\" contains itself");
}

TEST(Templates, AnEntitysConstraintsNameItsMembersOnly) {
    json scene = workstations(1);
    scene["templates"]["workstation"]["constraints"][0]["b"] = "desks";
    EXPECT_EQ(onlyProblem(scene), "/templates/workstation/constraints/0/b: \"ws1\" has no member \"desks\" (did you mean \"desk\"?) "
                                  "(desk or chair); an entity's constraints name its members relatively");
    scene = workstations(1);
    scene["templates"]["workstation"]["constraints"][0] = {{"type", "alignment"}, {"a", "desk"}, {"b", "room"}};
    {
        test::TempDir dir;
        Scene s = load(scene, dir);
        ASSERT_EQ(s.constraints.size(), 1u);
        EXPECT_EQ(s.constraints[0].b, kRoomEntity);
        EXPECT_EQ(s.constraints[0].name, "");
    }
    scene["templates"]["workstation"]["constraints"][0] = {{"type", "overlap"}, {"tolerance", 0.1}};
    EXPECT_EQ(onlyProblem(scene),
              "/templates/workstation/constraints/0/type: the overlap rule holds for the whole scene: set it in the top-level \"constraints\"");
}

}  // namespace
}  // namespace luxplan
