// The emitter registry: every shape reads its keys, is found by name, and knows
// what it asks for; shapes placed by a transform keep their area.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "shape_chi2.h"

namespace luxplan::test {

std::shared_ptr<const EmitterShape> readShape(const std::string& name, const std::string& jsonText,
                                              std::vector<std::string>* problems) {
    json::DiagnosticSink sink;
    json::Json j = json::Json::parse(jsonText);
    json::Fields f(sink, j, "/e");
    auto shape = findEmitterShape(name)->read(f);
    f.finish();
    if (problems)
        for (const auto& d : sink.diagnostics) problems->push_back(d.jsonPath + ": " + d.message);
    return shape;
}

namespace {

TEST(EmitterRegistry, ListsEveryShapeOnce) {
    EXPECT_EQ(emitterShapeNames(), (std::vector<std::string>{"rect", "disk", "sphere"}));
    for (const auto& entry : emitterShapes()) {
        EXPECT_EQ(findEmitterShape(entry.name), &entry);
        // The probe the loader uses: each reader asks for "center".
        auto keys = json::probeKeys([&](const json::Fields& f) { entry.read(f); });
        EXPECT_NE(std::find(keys.begin(), keys.end(), "center"), keys.end()) << entry.name;
    }
    EXPECT_EQ(findEmitterShape("blob"), nullptr);
}

TEST(EmitterRegistry, ShapesKeepTheirAreaWhenPlaced) {
    Transform t = Transform::placement({1, 2, 0}, 30);
    for (auto shape : {rectEmitter({0, 0, 2}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.3}), diskEmitter({0, 0, 2}, {0, 0, -1}, 0.2),
                       sphereEmitter({0, 0, 2}, 0.1)}) {
        auto placed = shape->transformed(t);
        EXPECT_NEAR(placed->area(), shape->area(), 1e-12) << shape->name();
        EXPECT_NEAR(length(placed->center() - t.applyPoint(shape->center())), 0, 1e-12) << shape->name();
        EXPECT_FALSE(shape->describe().empty());
    }
}

TEST(EmitterRegistry, LuminanceIsFluxOverPiArea) {
    Emitter e;
    e.shape = diskEmitter({0, 0, 2}, {0, 0, -1}, 0.5);
    e.fluxLm = 1000;
    EXPECT_NEAR(emitterLuminance(e), 1000 / (kPi * kPi * 0.25), 1e-9);
}

}  // namespace
}  // namespace luxplan::test
