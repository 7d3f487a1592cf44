// What validate warns about (checks/scene_warnings.h): each warning on a scene that
// earns it, with its JSON path and message, and none on the same scene put right.
#include <gtest/gtest.h>

#include <luxplan/checks/scene_warnings.h>
#include <luxplan/daylight/datetime.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/glare_sources.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include "support/scene_builder.h"

namespace luxplan {
namespace {

using test::SceneBuilder;

SceneBuilder room() {
    SceneBuilder b;
    b.material("wall", test::diffuse(0.6))
        .material("shade", test::translucent(0.45, 0.4))
        .material("glass", test::glass(0.8))
        .room({0, 0, 0}, {6, 4, 3}, "wall", "wall", "wall");
    return b;
}

std::string messages(const std::vector<Diagnostic>& d) {
    std::string s;
    for (const Diagnostic& x : d) s += x.jsonPath + ": " + x.message + "\n";
    return s;
}

TEST(EnclosedEmitters, AClosedOpaqueShadeLightsNothing) {
    // The old stand lamp: a sphere inside a closed diffuse box at the top of a pole.
    Scene s = room()
                  .entity("lamp", {3, 2, 0}).region({1, 1}, {5, 3})
                  .part({0.03, 0.03, 1.3}, "wall")
                  .part({0.35, 0.35, 0.32}, "wall", Vec3(0, 0, 1.44))
                  .emitter("bulb", sphereEmitter({0, 0, 1.45}, 0.12), 3500)
                  .end()
                  .build();
    std::vector<Diagnostic> w = enclosedEmitters(s);
    ASSERT_EQ(w.size(), 1u) << messages(w);
    EXPECT_EQ(w[0].file, s.file.string());
    EXPECT_EQ(w[0].jsonPath, "/entities/0/emitters/0");
    EXPECT_EQ(w[0].message, "emitter \"lamp.bulb\" is enclosed by opaque geometry of \"lamp\" (every ray from it meets an opaque "
                            "surface of it): it lights nothing; open it or give it a translucent material");
}

TEST(EnclosedEmitters, ATranslucentOrAnOpenShadeLetsTheLightOut) {
    // The same box in a translucent material.
    Scene s = room()
                  .entity("lamp", {3, 2, 0}).region({1, 1}, {5, 3})
                  .part({0.35, 0.35, 0.32}, "shade", Vec3(0, 0, 1.44))
                  .emitter("bulb", sphereEmitter({0, 0, 1.45}, 0.12), 3500)
                  .end()
                  .build();
    EXPECT_TRUE(enclosedEmitters(s).empty()) << messages(enclosedEmitters(s));
    // The stand_lamp preset, all of it opaque: its shade is open at top and bottom.
    s = room()
            .entity("lamp", {3, 2, 0}).region({1, 1}, {5, 3})
            .preset("stand_lamp", "wall")
            .emitter("bulb", sphereEmitter({0, 0, 1.45}, 0.12), 3500)
            .end()
            .build();
    EXPECT_TRUE(enclosedEmitters(s).empty()) << messages(enclosedEmitters(s));
    // A room alone encloses every lamp in it: that does not count.
    s = room().emitter("panel", rectEmitter({3, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000).build();
    EXPECT_TRUE(enclosedEmitters(s).empty()) << messages(enclosedEmitters(s));
}

TEST(EnclosedEmitters, AFixedLuminaireInsideStaticGeometry) {
    Scene s = room()
                  .box("soffit", {2, 1, 2.5}, {4, 3, 3}, "wall")
                  .emitter("panel", rectEmitter({3, 2, 2.8}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
                  .build();
    std::vector<Diagnostic> w = enclosedEmitters(s);
    ASSERT_EQ(w.size(), 1u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/luminaires/0");
    EXPECT_NE(w[0].message.find("enclosed by opaque geometry of \"soffit\""), std::string::npos) << w[0].message;
    // Behind glass it shines through.
    s = room()
            .box("cover", {2, 1, 2.5}, {4, 3, 3}, "glass")
            .emitter("panel", rectEmitter({3, 2, 2.8}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)
            .build();
    EXPECT_TRUE(enclosedEmitters(s).empty()) << messages(enclosedEmitters(s));
}

TEST(OutsideTheRoom, LuminairesAndSamplers) {
    Scene s = room()
                  .emitter("street", sphereEmitter({7, 2, 2}, 0.1), 1000)
                  .emitter("panel", rectEmitter({3, 2, 3}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 3000)  // flush: inside
                  .sampler("desk", planarSampler({3, 2, 0.75}, {0, 0, 1}, {0, 1, 0}, {1, 1}, {2, 2}), 300, 500)
                  .sampler("porch", planarSampler({5.9, 2, 0.75}, {0, 0, 1}, {0, 1, 0}, {0.6, 1}, {2, 2}), 300, 500)
                  .entity("cart", {5.5, 2, 0}).region({0, 0}, {6, 4})
                  .part({0.5, 0.5, 0.5}, "wall")
                  .emitter("lamp", sphereEmitter({1, 0, 1}, 0.05), 500)
                  .end()
                  .build();
    std::vector<Diagnostic> w = outsideTheRoom(s);
    ASSERT_EQ(w.size(), 3u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/luminaires/0");
    EXPECT_EQ(w[0].message, "luminaire \"street\" is outside the room, at (7, 2, 2): it lights the room only through its openings");
    EXPECT_EQ(w[1].jsonPath, "/entities/0/emitters/0");
    EXPECT_EQ(w[1].message, "luminaire \"cart.lamp\" is outside the room, at (6.5, 2, 1) (where \"cart\" stands): it lights the room "
                            "only through its openings");
    EXPECT_EQ(w[2].jsonPath, "/samplers/1");
    EXPECT_EQ(w[2].message, "sampler \"porch\" measures outside the room: 2 of its 4 points, e.g. (6.05, 1.75, 0.75)");
    // No room: nothing is outside it.
    Scene open = SceneBuilder().emitter("street", sphereEmitter({7, 2, 2}, 0.1), 1000).build();
    EXPECT_TRUE(outsideTheRoom(open).empty());
}

// A sampler on the shell sees past it: facing out, it measures the light outside (a
// planar sampler on the east wall whose normal points east read 4964 lx of the
// overcast sky in scenes/checks/window-lit-wall.json's room, 140 lx facing in).
TEST(OutsideTheRoom, SamplersOnTheShellThatFaceOutThroughIt) {
    Scene s = room()
                  .window(Wall::South, 1, 2, 0.9, 1.2, "glass")
                  .sampler("east out", planarSampler({6, 2, 1.5}, {1, 0, 0}, {0, 0, 1}, {1, 1}, {2, 2}), 0, 1000)
                  .sampler("east in", planarSampler({6, 2, 1.5}, {-1, 0, 0}, {0, 0, 1}, {1, 1}, {2, 2}), 0, 1000)
                  .sampler("floor grid", planarSampler({3, 2, 0}, {0, 0, 1}, {0, 1, 0}, {4, 2}, {4, 2}), 0, 1000)
                  .sampler("under the floor", planarSampler({3, 2, 0}, {0, 0, -1}, {0, 1, 0}, {4, 2}, {4, 2}), 0, 1000)
                  .sampler("eye", directionalSampler({3, 4, 1.2}, {0.3, 1, 0}, {0, 0, 1}, 60, 2), 0, 100)
                  .sampler("in the window", planarSampler({2, 0, 1.5}, {0, -1, 0}, {0, 0, 1}, {0.4, 0.4}, {2, 2}), 0, 1e6)
                  .sampler("near the wall", planarSampler({5.9, 2, 1.5}, {1, 0, 0}, {0, 0, 1}, {1, 1}, {2, 2}), 0, 1000)
                  .build();
    std::vector<Diagnostic> w = outsideTheRoom(s);
    ASSERT_EQ(w.size(), 3u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/samplers/0");
    EXPECT_EQ(w[0].message, "sampler \"east out\" lies on the room's east wall and faces out through it, at (6, 1.75, 1.25): it "
                            "measures the light outside the room");
    EXPECT_EQ(w[1].jsonPath, "/samplers/3");
    EXPECT_NE(w[1].message.find("\"under the floor\" lies on the room's floor and faces out through it"), std::string::npos);
    EXPECT_EQ(w[2].jsonPath, "/samplers/4");
    EXPECT_NE(w[2].message.find("\"eye\" lies on the room's north wall and faces out through it, at (3, 4, 1.2)"), std::string::npos);
}

// A sampler that gathers light from every direction sees out from anywhere on the shell
// (a cylindrical sampler on window-lit-wall's east wall read 2545 lx, 109 lx 10 cm in),
// and a glare eye looking out through the shell measures the outside.
TEST(OutsideTheRoom, AllRoundSamplersOnTheShellAndGlareEyesFacingOut) {
    Scene s = room()
                  .window(Wall::South, 1, 2, 0.9, 1.2, "glass")
                  .sampler("cylinder on the wall", cylindricalSampler({6, 2, 1.5}), 0, 1000)
                  .sampler("cylinder in the room", cylindricalSampler({5.9, 2, 1.5}), 0, 1000)
                  .sampler("cylinder in the window", cylindricalSampler({2, 0, 1.5}), 0, 1000)
                  .sampler("ugr out", ugrSampler({3, 4, 1.2}, {0, 1, 0}), 0, 19)
                  .sampler("ugr in", ugrSampler({3, 4, 1.2}, {0, -1, 0}), 0, 19)
                  .sampler("dgp out", dgpSampler({0, 2, 1.2}, {-1, 0.2, 0}), 0, 0.35)
                  .build();
    std::vector<Diagnostic> w = outsideTheRoom(s);
    ASSERT_EQ(w.size(), 3u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/samplers/0");
    EXPECT_EQ(w[0].message, "sampler \"cylinder on the wall\" lies on the room's east wall and looks all round, at (6, 2, 1.5): "
                            "half of its directions see outside the room");
    EXPECT_EQ(w[1].jsonPath, "/samplers/3");
    EXPECT_NE(w[1].message.find("\"ugr out\" lies on the room's north wall and faces out through it"), std::string::npos);
    EXPECT_EQ(w[2].jsonPath, "/samplers/5");
    EXPECT_NE(w[2].message.find("\"dgp out\" lies on the room's west wall and faces out through it"), std::string::npos);
}

TEST(SealedSamplers, PointsInAClosedOpaqueBox) {
    // A desk's plane at 0.76 m, a monitor's foot (2 cm high, on the desk) over one of
    // its four points, and a plane in a glass case, which light enters.
    Scene s = room()
                  .box("case", {4, 0.5, 0}, {5, 1.5, 1}, "glass")
                  .sampler("shelf", planarSampler({4.5, 1, 0.5}, {0, 0, 1}, {0, 1, 0}, {0.4, 0.4}, {2, 2}), 100)
                  .entity("desk", {2, 2, 0}).region({0, 0}, {6, 4})
                  .part({1.2, 0.6, 0.75}, "wall")
                  .sampler("task", planarSampler({0, 0, 0.76}, {0, 0, 1}, {0, 1, 0}, {1, 0.5}, {2, 2}), 300, 500)
                  .entity("monitor", {0.25, 0.125, 0.75}).region({-0.5, -0.25}, {0.5, 0.25}).preset("monitor", "wall").end()
                  .end()
                  .build();
    std::vector<Diagnostic> w = sealedSamplers(s);
    ASSERT_EQ(w.size(), 1u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/entities/0/samplers/0");
    EXPECT_EQ(w[0].message, "sampler \"desk.task\" measures inside a closed opaque box (where \"desk\" stands): 1 of its 4 "
                            "points, e.g. (2.25, 2.12, 0.76), where no light reaches (they read 0)");
    // The monitor moved off the points: no warning.
    s.entities[1].position = {0, 0.2, 0.75};
    EXPECT_TRUE(sealedSamplers(s).empty()) << messages(sealedSamplers(s));
}

// A sampler on a closed opaque box's face sees past it: looking into the box, it reads
// its dark inside (in a lit room, a plane on a desk's top facing down read 0 lx, facing
// up 663 lx; a cylindrical sampler on the top 321 lx, 10 cm above it 443 lx). A desk turned 30 degrees (its top from 0 to 0.75 m), planes on its top
// facing down and up, one 0.5 mm above it facing down (its rays start outside), a
// cylindrical sampler on the top, and an eye on a static box's side looking into it.
TEST(SealedSamplers, SamplersOnABoxThatLookIntoIt) {
    const double c = std::cos(kPi / 6), s30 = std::sin(kPi / 6);
    Scene s = room()
                  .box("cabinet", {4, 0.5, 0}, {5, 1.5, 1}, "wall")
                  .sampler("eye", directionalSampler({4, 1, 0.5}, {1, 0, 0}, {0, 0, 1}, 40, 2), 0, 100)
                  .sampler("eye away", directionalSampler({4, 1, 0.5}, {-1, 0, 0}, {0, 0, 1}, 40, 2), 0, 100)
                  .entity("desk", {2, 2, 0}, 30).region({0, 0}, {6, 4})
                  .part({1.2, 0.6, 0.75}, "wall")
                  .sampler("down", planarSampler({0, 0, 0.75}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 0, 500)
                  .sampler("up", planarSampler({0, 0, 0.75}, {0, 0, 1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 300, 500)
                  .sampler("above", planarSampler({0, 0, 0.7505}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 0, 500)
                  .sampler("cylinder", cylindricalSampler({0, 0, 0.75}), 0, 500)
                  .sampler("side", planarSampler({0.6, 0, 0.4}, {-1, 0, 0}, {0, 0, 1}, {0.2, 0.2}, {1, 1}), 0, 500)
                  .end()
                  .build();
    std::vector<Diagnostic> w = sealedSamplers(s);
    ASSERT_EQ(w.size(), 4u) << messages(w);  // the entities' samplers first
    EXPECT_EQ(w[0].jsonPath, "/entities/0/samplers/0");
    EXPECT_EQ(w[0].message.rfind("sampler \"desk.down\" lies on a closed opaque box (where \"desk\" stands) and faces into it: 4 "
                                 "of its 4 points", 0), 0u) << w[0].message;
    EXPECT_EQ(w[1].jsonPath, "/entities/0/samplers/3");
    EXPECT_NE(w[1].message.find("\"desk.cylinder\" lies on a closed opaque box (where \"desk\" stands) and looks all round: "
                                "1 of its 1 points, e.g. (2, 2, 0.75), where half of its directions see"), std::string::npos) << w[1].message;
    // On the turned desk's end face (local x = 0.6), facing back into it.
    EXPECT_EQ(w[2].jsonPath, "/entities/0/samplers/4");
    EXPECT_NE(w[2].message.find(pointText({2 + 0.6 * c, 2 + 0.6 * s30, 0.4})), std::string::npos) << w[2].message;
    EXPECT_EQ(w[3].jsonPath, "/samplers/0");
    EXPECT_EQ(w[3].message, "sampler \"eye\" lies on a closed opaque box and faces into it: 1 of its 1 points, e.g. (4, 1, 0.5), "
                            "where it measures the box's dark inside (they read 0)");
}

// A plane just under a face it looks out of: its rays start 0.1 mm along themselves, so
// the grazing ones start inside the box (on a lit desk, 650 lx at 1 cm above its top, 440
// at 0.05 mm under it, 206 at 0.08 mm and 0 from 0.12 mm down). The desk is turned 30
// degrees; a plane on its top, or 0.005 mm under it (1% of its light is lost at
// 0.01 mm), is not warned about. A plane under the top looking down into the desk gets
// the other warning; an eye 0.3 mm inside a static box, looking out, this one.
TEST(SealedSamplers, SamplersJustUnderAFaceTheyLookOutOf) {
    Scene s = room()
                  .box("cabinet", {4, 0.5, 0}, {5, 1.5, 1}, "wall")
                  .sampler("eye out", directionalSampler({4.0003, 1, 0.5}, {-1, 0, 0}, {0, 0, 1}, 40, 2), 0, 100)
                  .entity("desk", {2, 2, 0}, 30).region({0, 0}, {6, 4})
                  .part({1.2, 0.6, 0.75}, "wall")
                  .sampler("on", planarSampler({0, 0, 0.75}, {0, 0, 1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 300, 500)
                  .sampler("hair under", planarSampler({0, 0, 0.749995}, {0, 0, 1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 300, 500)
                  .sampler("under", planarSampler({0, 0, 0.7495}, {0, 0, 1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 300, 500)
                  .sampler("shallow", planarSampler({0, 0, 0.74995}, {0, 0, 1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 300, 500)
                  .sampler("down", planarSampler({0, 0, 0.7495}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.3}, {2, 2}), 0, 500)
                  .end()
                  .build();
    std::vector<Diagnostic> w = sealedSamplers(s);
    ASSERT_EQ(w.size(), 4u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/entities/0/samplers/2");
    EXPECT_EQ(w[0].message.rfind("sampler \"desk.under\" lies just inside a closed opaque box (where \"desk\" stands), under the "
                                 "face it looks out of: 4 of its 4 points, e.g. (", 0), 0u) << w[0].message;
    EXPECT_NE(w[0].message.find("), 0.5 mm deep, where its rays start inside the box"), std::string::npos) << w[0].message;
    EXPECT_EQ(w[1].jsonPath, "/entities/0/samplers/3");
    EXPECT_NE(w[1].message.find(", 0.05 mm deep,"), std::string::npos) << w[1].message;
    // Looking down into the desk from under its top: the dark inside, however deep.
    EXPECT_EQ(w[2].jsonPath, "/entities/0/samplers/4");
    EXPECT_NE(w[2].message.find("\"desk.down\" lies on a closed opaque box (where \"desk\" stands) and faces into it"),
              std::string::npos) << w[2].message;
    EXPECT_EQ(w[3].jsonPath, "/samplers/0");
    EXPECT_EQ(w[3].message, "sampler \"eye out\" lies just inside a closed opaque box, under the face it looks out of: 1 of its 1 "
                            "points, e.g. (4, 1, 0.5), 0.3 mm deep, where its rays start inside the box (they read low, and 0 "
                            "from 0.1 mm down): place it on the face");
}

DaylightParams preetham(const char* from, const char* to) {
    DaylightParams d;
    d.model = SkyModelType::Preetham;
    d.from = parseIso8601(from);
    if (to) d.to = parseIso8601(to);
    d.stepMinutes = 30;
    return d;
}

Scene athens(const DaylightParams& d) {
    Scene s = room().daylight(d).build();
    s.site.latitudeDeg = 37.98, s.site.longitudeDeg = 23.73;
    return s;
}

TEST(DarkDaylight, AfterSunsetAndPartly) {
    // Athens, 15 October: sunset about 18:45 local time (+03:00).
    std::vector<Diagnostic> w = darkDaylight(athens(preetham("2026-10-15T21:00+03:00", "2026-10-15T23:00+03:00")));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].jsonPath, "/daylight/from");
    EXPECT_EQ(w[0].message, "the sun is below the horizon throughout 2026-10-15T21:00+03:00 to 2026-10-15T23:00+03:00 (after "
                            "sunset or before sunrise): the daylight adds no light; leave \"daylight\" out for a night scene");
    w = darkDaylight(athens(preetham("2026-10-15T22:00+03:00", nullptr)));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].message.rfind("the sun is below the horizon at 2026-10-15T22:00+03:00 (after sunset", 0), 0u) << w[0].message;
    w = darkDaylight(athens(preetham("2026-10-15T17:00+03:00", "2026-10-15T20:00+03:00")));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].message, "the sun is below the horizon at 3 of the 7 steps of 2026-10-15T17:00+03:00 to "
                            "2026-10-15T20:00+03:00 (from 2026-10-15T19:00+03:00): they add no light but count in the average");
    EXPECT_TRUE(darkDaylight(athens(preetham("2026-10-15T15:30+03:00", "2026-10-15T18:00+03:00"))).empty());
    // Skies that do not follow the sun, a fixed sun, no daylight: nothing to say.
    DaylightParams uniform;
    uniform.model = SkyModelType::Uniform;
    uniform.luminanceNits = 1000;
    uniform.from = parseIso8601("2026-10-15T23:00+03:00");
    EXPECT_TRUE(darkDaylight(athens(uniform)).empty());
    DaylightParams fixed = preetham("2026-10-15T23:00+03:00", nullptr);
    fixed.from.reset();
    fixed.sunOverride = SunOverride{};
    EXPECT_TRUE(darkDaylight(athens(fixed)).empty());
    EXPECT_TRUE(darkDaylight(room().build()).empty());
}

TEST(StartPlacement, InAWallABlockerOrOutOfTheRoom) {
    Scene s = room()
                  .blocker("door_free", {0, 0, 0}, {1, 1, 2})
                  .entity("sofa", {3, 3.7, 0}).region({0, 0}, {6, 4}).part({2, 0.9, 0.85}, "wall").end()
                  .entity("desk", {1.2, 1.2, 0}).region({0, 0}, {6, 4}).part({1, 0.6, 0.75}, "wall").end()
                  .entity("table", {3, 2, 0}).region({0, 0}, {6, 4}).part({1.2, 0.8, 0.75}, "wall").end()
                  .build();
    std::vector<Diagnostic> w = startPlacement(s);
    ASSERT_EQ(w.size(), 3u) << messages(w);
    // The sofa's back is 15 cm through the north wall: its voxels and its footprint say so.
    EXPECT_EQ(w[0].jsonPath, "/entities/0");
    EXPECT_EQ(w[0].message.rfind("the scene places \"sofa\" past a hard limit: overlap \"sofa\" / the north wall: ", 0), 0u)
        << w[0].message;
    EXPECT_EQ(w[1].jsonPath, "/entities/1");
    EXPECT_EQ(w[1].message.rfind("the scene places \"desk\" past a hard limit: overlap \"desk\" / geometry \"door_free\": ", 0),
              0u)
        << w[1].message;
    EXPECT_EQ(w[2].jsonPath, "/entities/0");
    EXPECT_EQ(w[2].message, "the scene places \"sofa\" past a hard limit: footprint \"sofa\" / room \"room\": 0.15 m outside, "
                            "P = 226");
    // All three on the floor, clear of the door: nothing.
    s.entities[0].position = Vec3(3, 3.5, 0), s.entities[1].position = Vec3(1.6, 1.6, 0);
    EXPECT_TRUE(startPlacement(s).empty()) << messages(startPlacement(s));
    EXPECT_TRUE(sceneWarnings(s).empty()) << messages(sceneWarnings(s));
}

TEST(SceneWarnings, EveryCheckInOrder) {
    Scene s = room()
                  .emitter("street", sphereEmitter({7, 2, 2}, 0.1), 1000)
                  .entity("sofa", {3, 3.7, 0}).region({0, 0}, {6, 4}).part({2, 0.9, 0.85}, "wall").end()
                  .daylight(preetham("2026-10-15T21:00+03:00", nullptr))
                  .build();
    std::vector<Diagnostic> w = sceneWarnings(s);
    ASSERT_EQ(w.size(), 4u) << messages(w);
    EXPECT_EQ(w[0].jsonPath, "/luminaires/0");  // outside the room
    EXPECT_EQ(w[1].jsonPath, "/daylight/from");
    EXPECT_EQ(w[2].jsonPath, "/entities/0");    // in the wall, then outside the room
    EXPECT_EQ(w[3].jsonPath, "/entities/0");
}

}  // namespace
}  // namespace luxplan
