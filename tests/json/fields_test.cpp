// Fields learns an object's keys from what its reader reads: finish() reports the
// rest, as unknown or as not applying to the kind, and probeKeys() finds what a
// reader reads without a list kept by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <luxplan/core/names.h>
#include <luxplan/json/fields.h>

namespace luxplan::json {
namespace {

std::vector<std::string> messages(const DiagnosticSink& sink) {
    std::vector<std::string> out;
    for (const auto& d : sink.diagnostics) out.push_back(d.jsonPath + ": " + d.message);
    return out;
}

TEST(Fields, ReportsWhatNoAccessorRead) {
    DiagnosticSink sink;
    Json j = Json::parse(R"({"width": 2, "hieght": 3, "depth": 1})");
    Fields f(sink, j, "/box");
    EXPECT_EQ(f.number("width", 0.0), 2);
    EXPECT_FALSE(f.number("height").has_value());
    f.finish();
    EXPECT_EQ(messages(sink), (std::vector<std::string>{
                                  "/box/depth: unknown key \"depth\" (known keys: width, height)",
                                  "/box/hieght: unknown key \"hieght\" (did you mean \"height\"?) (known keys: width, height)"}));
}

TEST(Fields, AWrongTypeIsReportedOnceNotAlsoAsUnknown) {
    DiagnosticSink sink;
    Json j = Json::parse(R"({"width": "wide"})");
    Fields f(sink, j, "");
    EXPECT_FALSE(f.number("width").has_value());
    f.finish();
    EXPECT_EQ(messages(sink), std::vector<std::string>{"/width: expected a number, got a string"});
}

TEST(Fields, AKeyOfAnotherKindDoesNotApply) {
    auto disk = [](const Fields& f) { f.number("radius"); };
    auto rect = [](const Fields& f) {
        f.vec2("size");
        if (f.has("up")) f.direction("up");
    };
    std::vector<std::string> family = unionKeys({probeKeys(disk), probeKeys(rect)});
    EXPECT_EQ(family, (std::vector<std::string>{"radius", "size", "up"}));

    DiagnosticSink sink;
    Json j = Json::parse(R"({"radius": 1, "up": [0, 1, 0], "colour": 1})");
    Fields f(sink, j, "/e");
    disk(f);
    f.finish("a disk", family);
    EXPECT_EQ(messages(sink), (std::vector<std::string>{"/e/colour: unknown key \"colour\" (known keys: radius, size, up)",
                                                        "/e/up: \"up\" does not apply to a disk"}));
}

TEST(Fields, AnUnknownKindLeavesTheFamilysKeysUnjudged) {
    DiagnosticSink sink;
    Json j = Json::parse(R"({"shape": "blob", "radius": 1, "colour": 1})");
    Fields f(sink, j, "/e");
    f.string("shape");
    f.finish("", {"radius", "size"});
    EXPECT_EQ(messages(sink),
              std::vector<std::string>{"/e/colour: unknown key \"colour\" (known keys: shape, radius, size)"});
}

TEST(Fields, NotAnObject) {
    DiagnosticSink sink;
    Json j = Json::parse("[1, 2]");
    Fields f(sink, j, "/site", "a site object");
    EXPECT_FALSE(f.valid());
    f.finish();
    EXPECT_EQ(messages(sink), std::vector<std::string>{"/site: expected a site object, got an array"});
}

TEST(Names, ClosestNameOnlyForLikelyTypos) {
    std::vector<std::string> known{"reflectance", "roughness", "base"};
    EXPECT_EQ(closestName("reflectence", known), "reflectance");
    EXPECT_EQ(closestName("bse", known), "base");
    EXPECT_FALSE(closestName("colour", known).has_value());
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("rigth", "right"), 1u);
    EXPECT_EQ(listNames({"a", "b", "c"}), "a, b or c");
    EXPECT_EQ(listNames({"a"}), "a");
}

TEST(Names, OneTableParsesPrintsAndLists) {
    enum class Side { Left, Right };
    EnumNames<Side> sides{{{Side::Left, "left"}, {Side::Right, "right"}}};
    EXPECT_EQ(sides.parse("right"), Side::Right);
    EXPECT_FALSE(sides.parse("up").has_value());
    EXPECT_STREQ(sides.name(Side::Left), "left");
    EXPECT_EQ(sides.unknown("side", "rigth"), "unknown side \"rigth\" (did you mean \"right\"?) (left or right)");
}

}  // namespace
}  // namespace luxplan::json
