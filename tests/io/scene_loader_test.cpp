// The scene loader's error paths: each problem is reported as FILE: /json/path: message,
// all of them in one run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/core/error.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/io/scene_loader.h>
#include "support/load_problems.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

using nlohmann::json;

// A small valid scene; tests break one thing at a time.
json validScene() {
    return json::parse(R"({
      "luxplan": 1, "name": "t",
      "site": {"latitude": 37.98, "longitude": 23.73, "north_deg": 0},
      "materials": {"wall": {"type": "diffuse", "reflectance": 0.6},
                    "glass": {"type": "glass", "transmittance": 0.8},
                    "screen": {"type": "glossy", "reflectance": 0.05, "roughness": 0.1, "base": 0.02}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                    "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"},
                    "openings": [{"wall": "south", "offset": 1.5, "width": 2.0, "sill": 0.9, "height": 1.5, "material": "glass"}]}],
      "luminaires": [{"name": "panel", "shape": "rect", "center": [3,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 3200}],
      "entities": [{"name": "desk1", "position": [2, 2], "rotation": 0,
                    "placement": {"regions": [{"min": [1,1], "max": [5,3], "rotations": [0, 90]}]},
                    "parts": [{"preset": "desk", "material": "wall"}],
                    "samplers": [{"name": "top", "type": "planar", "center": [0,0,0.76], "size": [1.2,0.6], "target": [300,500]}],
                    "children": [{"name": "monitor", "position": [0, 0.2, 0.75],
                                  "parts": [{"preset": "monitor", "materials": {"body": "wall", "screen": "screen"}}]}]},
                   {"name": "shelf", "position": [1, 3.7],
                    "placement": {"regions": [{"min": [0.5,3.7], "max": [5.5,3.7], "rotation_range": [0, 0]}]},
                    "parts": [{"box": {"size": [0.8,0.3,1.8]}, "material": "wall"}]}],
      "samplers": [{"name": "glare", "type": "directional", "origin": [3,1,1.2], "direction": [0,1,0], "target": [0,100]}],
      "constraints": [{"type": "distance", "a": "desk1", "b": "shelf", "min": 0.5, "max": 3},
                      {"type": "focus", "a": "desk1.monitor", "b": "shelf"}],
      "objective": {"lighting_weight": 0.5},
      "optimizer": {"iterations": 100, "seed": 3, "paths_per_point": 64}
    })");
}

std::vector<std::string> problems(const json& scene, test::TempDir& dir) { return test::loadProblems(scene.dump(2), dir); }

using test::onlyProblem;

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST(SceneLoader, ValidSceneLoads) {
    test::TempDir dir;
    auto file = dir.write("scene.json", validScene().dump());
    Scene s = io::loadScene(file);
    EXPECT_EQ(s.entities.size(), 3u);
    EXPECT_EQ(s.entities[1].path, "desk1.monitor");
    EXPECT_EQ(s.entities[1].parent, 0);
    EXPECT_EQ(s.samplers.size(), 2u);
    EXPECT_EQ(s.samplers[0].entity, 0);
    EXPECT_EQ(s.constraints[1].a, 1);
    EXPECT_EQ(s.optimizer.seed, 3u);
    EXPECT_NEAR(emitterLuminance(s.emitters[0]), 3200 / (kPi * 0.36), 1e-9);
    EXPECT_EQ(s.materials[s.materialIndex.at("screen")].type, MaterialType::Glossy);
}

TEST(SceneLoader, MalformedJsonGivesLineAndColumn) {
    test::TempDir dir;
    auto p = test::loadProblems("{\n  \"luxplan\": 1,\n  \"name\": oops\n}", dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_TRUE(startsWith(p[0], "/: malformed JSON at line 3, column")) << p[0];
}

TEST(SceneLoader, UnreadableFile) {
    try {
        io::loadScene("/nonexistent/scene.json");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.diagnostics().at(0).str(), "/nonexistent/scene.json: /: cannot open the file");
    }
}

TEST(SceneLoader, UnknownKeys) {
    json s = validScene();
    s["colour"] = 1;
    EXPECT_TRUE(startsWith(onlyProblem(s), "/colour: unknown key \"colour\"")) << onlyProblem(s);
    s = validScene();
    s["materials"]["wall"]["reflektance"] = 0.5;
    EXPECT_TRUE(startsWith(onlyProblem(s), "/materials/wall/reflektance: unknown key"));
    s = validScene();
    s["entities"][0]["children"][0]["parts"][0]["colour"] = "red";
    EXPECT_TRUE(startsWith(onlyProblem(s), "/entities/0/children/0/parts/0/colour: unknown key"));
}

TEST(SceneLoader, DuplicateJsonKey) {
    std::string text = validScene().dump();
    text.insert(text.find("\"name\": \"t\"") != std::string::npos ? 1 : 1, "\"name\": \"again\", ");
    test::TempDir dir;
    auto p = test::loadProblems(text, dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0], "/name: duplicate key (JSON objects need unique keys)");
}

TEST(SceneLoader, WrongTypes) {
    json s = validScene();
    s["site"]["latitude"] = "north";
    EXPECT_EQ(onlyProblem(s), "/site/latitude: expected a number, got a string");
    s = validScene();
    s["entities"] = json::object();
    EXPECT_EQ(onlyProblem(s), "/entities: expected an array, got an object");
    s = validScene();
    s["luminaires"][0]["center"] = {1, 2};
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/center: expected an array of 3 numbers, got an array of 2");
}

TEST(SceneLoader, OutOfRangeValues) {
    json s = validScene();
    s["luminaires"][0]["flux_lm"] = -5;
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/flux_lm: value -5 outside >= 0");
    s = validScene();
    s["materials"]["wall"]["reflectance"] = 1.2;
    EXPECT_EQ(onlyProblem(s), "/materials/wall/reflectance: value 1.2 outside [0, 1]");
    s = validScene();
    s["materials"]["wall"]["reflectance"] = {0.5, 1.5, 0.5};
    EXPECT_EQ(onlyProblem(s), "/materials/wall/reflectance/1: value 1.5 outside [0, 1]");
    s = validScene();
    s["site"]["latitude"] = 95;
    EXPECT_EQ(onlyProblem(s), "/site/latitude: value 95 outside [-90, 90] deg");
    s = validScene();
    s["objective"]["lighting_weight"] = 2;
    EXPECT_EQ(onlyProblem(s), "/objective/lighting_weight: value 2 outside [0, 1]");
}

TEST(SceneLoader, EmptyOrInvertedRegion) {
    json s = validScene();
    s["entities"][0]["placement"]["regions"][0]["max"] = {0.5, 3};
    EXPECT_EQ(onlyProblem(s), "/entities/0/placement/regions/0/max: region is inverted: max x 0.5 < min 1");
    s = validScene();
    s["entities"][0]["placement"]["regions"][0]["rotations"] = json::array();
    EXPECT_EQ(onlyProblem(s), "/entities/0/placement/regions/0/rotations: the set of rotations is empty");
    s = validScene();
    s["entities"][0]["placement"]["regions"] = json::array();
    EXPECT_EQ(onlyProblem(s), "/entities/0/placement/regions: placement has no regions");
    s = validScene();
    s["entities"][1]["placement"]["regions"][0]["rotation_range"] = {90, 0};
    EXPECT_EQ(onlyProblem(s), "/entities/1/placement/regions/0/rotation_range: rotation range is inverted: 0 < 90");
    s = validScene();
    s["geometry"][0]["room"]["max"] = {6, 0, 3};
    EXPECT_EQ(onlyProblem(s), "/geometry/0/room/max: room is empty or inverted: max y 0 <= min 0");
}

TEST(SceneLoader, TargetsAndSamplers) {
    json s = validScene();
    s["samplers"][0]["target"] = {100, 0};
    EXPECT_EQ(onlyProblem(s), "/samplers/0/target: target range is reversed: max 0 < min 100 cd/m2");
    s = validScene();
    s["samplers"][0]["target"] = {-20, -10};
    EXPECT_EQ(onlyProblem(s),
              "/samplers/0/target: impossible target: max -10 cd/m2 is below 0 and no light level can meet it");
    s = validScene();
    s["entities"][0]["samplers"][0]["size"] = {0, 0.6};
    EXPECT_EQ(onlyProblem(s), "/entities/0/samplers/0/size: sampler has zero area: size 0 x 0.6");
    s = validScene();
    s["entities"][0]["samplers"][0]["up"] = {0, 0, 2};
    EXPECT_EQ(onlyProblem(s), "/entities/0/samplers/0/up: \"up\" is parallel to \"normal\"");
    s = validScene();
    s["luminaires"][0]["up"] = {0, 0, 1};
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/up: \"up\" is parallel to \"normal\"");
    s = validScene();
    s["samplers"][0]["fov_deg"] = 0;
    EXPECT_EQ(onlyProblem(s), "/samplers/0/fov_deg: value 0 outside (0, 180) deg");
    s = validScene();
    s["samplers"].push_back({{"name", "vol"}, {"type", "volume"}, {"center", {1, 1, 1}},
                             {"axes", {{1, 0, 0}, {2, 0, 0}, {0, 0, 1}}}, {"target", {10, 50}}});
    EXPECT_EQ(onlyProblem(s), "/samplers/1/axes: the box has zero volume (side vectors are degenerate)");
    s = validScene();
    s["samplers"][0]["grid"] = {4, 4};
    EXPECT_EQ(onlyProblem(s), "/samplers/0/grid: \"grid\" does not apply to a directional sampler");
}

// The loader keeps no list of keys: what a kind's reader reads is what it knows, and
// a key another kind of the same family reads "does not apply" to this one.
TEST(SceneLoader, KeysThatDoNotApplyToTheKindBeingRead) {
    json s = validScene();
    s["luminaires"][0]["radius"] = 0.2;
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/radius: \"radius\" does not apply to a rect emitter");
    s = validScene();
    s["luminaires"][0] = {{"name", "bulb"}, {"shape", "sphere"}, {"center", {3, 2, 2}}, {"radius", 0.05},
                          {"normal", {0, 0, -1}}, {"flux_lm", 800}};
    EXPECT_EQ(onlyProblem(s), "/luminaires/0/normal: \"normal\" does not apply to a sphere emitter");
    s = validScene();
    s["constraints"][1]["min"] = 1;
    EXPECT_EQ(onlyProblem(s), "/constraints/1/min: \"min\" does not apply to a focus constraint");
    s = validScene();
    s["constraints"].push_back({{"type", "alignment"}, {"a", "desk1"}, {"b", "room"}, {"max", 2}});
    EXPECT_EQ(onlyProblem(s), "/constraints/2/max: \"max\" does not apply to an alignment constraint");
    s = validScene();
    s["geometry"][0]["material"] = "wall";
    EXPECT_EQ(onlyProblem(s), "/geometry/0/material: \"material\" does not apply to a room");
    s = validScene();
    s["geometry"].push_back({{"name", "pillar"}, {"box", {{"min", {1, 1, 0}}, {"max", {1.2, 1.2, 3}}}}, {"material", "wall"},
                             {"transform", {{"rotate_deg", 45}}}});
    EXPECT_EQ(onlyProblem(s), "/geometry/1/transform: \"transform\" does not apply to a box");
    s = validScene();
    s["geometry"][0]["openings"][0]["center"] = {1, 1};
    EXPECT_EQ(onlyProblem(s), "/geometry/0/openings/0/center: \"center\" does not apply to a wall opening");
    s = validScene();
    s["entities"][0]["parts"][0]["transform"] = {{"rotate_deg", 90}};
    EXPECT_EQ(onlyProblem(s), "/entities/0/parts/0/transform: \"transform\" does not apply to a preset part");
    s = validScene();
    s["materials"]["wall"]["roughness"] = 0.3;
    EXPECT_EQ(onlyProblem(s), "/materials/wall/roughness: \"roughness\" does not apply to a diffuse material");
}

TEST(SceneLoader, SuggestsTheClosestName) {
    json s = validScene();
    s["materials"]["wall"]["reflectence"] = 0.5;
    s["materials"]["wall"].erase("reflectance");
    auto all = [&] {
        test::TempDir dir;
        return problems(s, dir);
    };
    auto list = all();
    ASSERT_EQ(list.size(), 2u);  // the misspelt key, and the required one it was meant to be
    EXPECT_TRUE(startsWith(list[1], "/materials/wall/reflectence: unknown key \"reflectence\" (did you mean \"reflectance\"?)"))
        << list[1];
    s = validScene();
    s["samplers"][0]["type"] = "directonal";
    EXPECT_TRUE(startsWith(onlyProblem(s), "/samplers/0/type: unknown sampler type \"directonal\" (did you mean \"directional\"?) "
                                           "(planar, directional, volume, cylindrical, ugr or dgp)"))
        << onlyProblem(s);
    s = validScene();
    s["entities"][0]["parts"][0]["preset"] = "dsk";
    EXPECT_TRUE(startsWith(onlyProblem(s), "/entities/0/parts/0/preset: unknown preset \"dsk\" (did you mean \"desk\"?)"))
        << onlyProblem(s);
    s = validScene();
    s["geometry"][0]["materials"]["floor"] = "wal";
    EXPECT_EQ(onlyProblem(s), "/geometry/0/materials/floor: unknown material \"wal\" (did you mean \"wall\"?)");
    s = validScene();
    s["geometry"][0]["openings"][0]["wall"] = "sout";
    EXPECT_EQ(onlyProblem(s), "/geometry/0/openings/0/wall: unknown wall \"sout\" (did you mean \"south\"?) "
                              "(north, south, east, west or ceiling)");
}

TEST(SceneLoader, IntegersBeyondTheirTypeAreRefused) {
    json s = validScene();
    s["optimizer"]["iterations"] = 3000000000LL;
    EXPECT_EQ(onlyProblem(s), "/optimizer/iterations: value 3000000000 exceeds the limit of 2147483647");
}

TEST(SceneLoader, NamesThatDoNotResolve) {
    json s = validScene();
    s["geometry"][0]["materials"]["floor"] = "marble";
    EXPECT_EQ(onlyProblem(s), "/geometry/0/materials/floor: unknown material \"marble\"");
    s = validScene();
    s["constraints"][0]["a"] = "desk2";
    EXPECT_EQ(onlyProblem(s), "/constraints/0/a: unknown entity \"desk2\" (did you mean \"desk1\"?)");
    s = validScene();
    s["constraints"][1]["a"] = "desk1.screen";
    EXPECT_EQ(onlyProblem(s), "/constraints/1/a: unknown entity \"desk1.screen\"");
    s = validScene();
    s["constraints"][1]["a"] = "monitor";  // a unique bare name resolves to the nested entity
    test::TempDir dir;
    EXPECT_TRUE(problems(s, dir).empty());
    s = validScene();
    s["entities"][0]["parts"][0]["preset"] = "throne";
    EXPECT_TRUE(startsWith(onlyProblem(s), "/entities/0/parts/0/preset: unknown preset \"throne\""));
}

TEST(SceneLoader, MissingMeshFile) {
    json s = validScene();
    s["geometry"].push_back({{"name", "bar"}, {"mesh", "models/bar.obj"}, {"material", "wall"}});
    test::TempDir dir;
    auto p = problems(s, dir);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0], "/geometry/1/mesh: cannot read mesh \"" + (dir.path() / "models/bar.obj").string() + "\": no such file");
}

TEST(SceneLoader, DuplicateNames) {
    json s = validScene();
    s["entities"][1]["name"] = "desk1";
    s["constraints"] = json::array();
    EXPECT_EQ(onlyProblem(s), "/entities/1/name: duplicate entity name \"desk1\" (also at /entities/0)");
    // Sampler names are scoped by their entity: "top" of desk1 is "desk1.top", so a
    // world sampler may be called "top" too; twice in one entity is an error.
    s = validScene();
    s["samplers"][0]["name"] = "top";
    {
        test::TempDir dir;
        EXPECT_TRUE(problems(s, dir).empty());
    }
    s = validScene();
    s["entities"][0]["samplers"].push_back(s["entities"][0]["samplers"][0]);
    EXPECT_EQ(onlyProblem(s), "/entities/0/samplers/1/name: duplicate sampler name \"desk1.top\" (also at /entities/0/samplers/0)");
    s = validScene();
    s["samplers"][0]["name"] = "desk1.top";
    EXPECT_EQ(onlyProblem(s),
              "/samplers/0/name: names must be non-empty and must not contain '.' (it separates an entity's path from the name)");
    // An empty entity name once gave its sampler the name ".top" and the layout a key "".
    s = validScene();
    s["geometry"][0]["name"] = "";
    EXPECT_EQ(onlyProblem(s), "/geometry/0/name: geometry names must be non-empty");
    s = validScene();
    s["entities"][0]["name"] = "";
    EXPECT_EQ(onlyProblem(s),
              "/entities/0/name: entity names must be non-empty and must not contain '.' (it separates levels in dotted paths)");
}

TEST(SceneLoader, OpeningsMustFitAndNotOverlap) {
    json s = validScene();
    s["geometry"][0]["openings"][0]["offset"] = 5;
    EXPECT_EQ(onlyProblem(s), "/geometry/0/openings/0: opening [5, 7] x [0.9, 2.4] does not fit in the south wall (6 x 3 m)");
    s = validScene();
    s["geometry"][0]["openings"].push_back({{"wall", "south"}, {"offset", 3}, {"width", 1}, {"height", 1}});
    EXPECT_EQ(onlyProblem(s), "/geometry/0/openings/1: overlaps opening 0 on the same wall");
}

TEST(SceneLoader, DaylightChecks) {
    json s = validScene();
    s["daylight"] = {{"sky", {{"model", "preetham"}}}, {"from", "2026-06-21T09:00"}};
    EXPECT_TRUE(startsWith(onlyProblem(s), "/daylight/from: ")) << onlyProblem(s);
    s["daylight"] = {{"sky", {{"model", "preetham"}}}};
    EXPECT_TRUE(startsWith(onlyProblem(s), "/daylight: sky model \"preetham\" needs a time")) << onlyProblem(s);
    s["daylight"] = {{"sky", {{"model", "cie_overcast"}}}, {"sun", false}};
    EXPECT_EQ(onlyProblem(s), "/daylight/sky: sky model \"cie_overcast\" needs \"horizontal_illuminance_lx\"");
    s["daylight"] = {{"sky", {{"model", "preetham"}}}, {"from", "2026-06-21T12:00+03:00"}, {"to", "2026-06-21T09:00+03:00"}};
    EXPECT_EQ(onlyProblem(s), "/daylight/to: \"to\" 2026-06-21T09:00+03:00 is before \"from\" 2026-06-21T12:00+03:00");
    s["daylight"] = {{"sky", {{"model", "uniform"}, {"luminance_nits", 1000}, {"turbidity", 3}}}, {"sun", false}};
    EXPECT_EQ(onlyProblem(s), "/daylight/sky/turbidity: \"turbidity\" does not apply to the uniform sky");
    s["daylight"] = {{"sky", {{"model", "preetham"}}}, {"sun", {{"altitude_deg", 40}, {"azimuth_deg", 180}}}};
    test::TempDir dir;
    EXPECT_TRUE(problems(s, dir).empty());
}

TEST(SceneLoader, EveryProblemInOneRun) {
    json s = validScene();
    s["luminaires"][0]["flux_lm"] = -1;
    s["materials"]["wall"]["reflectance"] = 3;
    s["constraints"][0]["b"] = "nothing";
    s["extra"] = true;
    test::TempDir dir;
    auto p = problems(s, dir);
    EXPECT_EQ(p.size(), 4u);
}

TEST(SceneLoader, ConstraintChecks) {
    json s = validScene();
    s["constraints"][0]["min"] = 4;
    EXPECT_EQ(onlyProblem(s), "/constraints/0/max: distance range is reversed: max 3 < min 4 m");
    s = validScene();
    s["constraints"][0]["b"] = "desk1";
    EXPECT_EQ(onlyProblem(s), "/constraints/0/b: a constraint needs two different entities");
    s = validScene();
    s["constraints"][0]["a"] = "room";
    EXPECT_EQ(onlyProblem(s), "/constraints/0/a: \"room\" is only valid as \"b\" of an alignment constraint");
    s = validScene();
    s["constraints"].push_back({{"type", "alignment"}, {"a", "shelf"}, {"b", "room"}, {"tolerance_deg", 10}});
    s["constraints"].push_back({{"type", "overlap"}, {"tolerance", 0.1}});
    test::TempDir dir;
    EXPECT_TRUE(problems(s, dir).empty());
}

}  // namespace
}  // namespace luxplan
