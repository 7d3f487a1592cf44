// Perspective renders: a lit room gives a non-black, deterministic picture; colour
// comes from what each pixel sees; the tone curve and the automatic exposure behave;
// the false-colour view has its legend; side-by-side keeps both images.
#include <gtest/gtest.h>

#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/output/black_body.h>
#include <luxplan/output/render.h>
#include "support/scene_builder.h"
#include "support/scene_lab.h"
#include "support/shared_scenes.h"
#include "support/threads.h"

namespace luxplan {
namespace {

TEST(Render, DefaultCameraLooksAcrossTheRoom) {
    test::SceneLab lab(test::litRoom());
    Camera camera = defaultCamera(lab.scene);
    const Bounds3& room = lab.scene.room()->box;
    EXPECT_TRUE(room.contains(camera.position));
    EXPECT_GE(camera.position.z, 1.7);
    EXPECT_LE(camera.position.z, 2.2);
    Vec3 d = camera.lookAt - camera.position;
    EXPECT_GT(std::abs(d.x), 3);
    EXPECT_GT(std::abs(d.y), 2);
    EXPECT_LT(d.z, 0);
    EXPECT_GE(camera.fovDeg, 60);
    EXPECT_LE(camera.fovDeg, 70);
}

TEST(Render, LitRoomIsVisibleAndDeterministic) {
    test::SceneLab lab(test::litRoom());
    RenderOptions options;
    options.width = 48, options.height = 36, options.samplesPerPixel = 4, options.seed = 7;
    options.color = false;
    Camera camera = defaultCamera(lab.scene);
    Image image = test::withThreads(2, [&] { return renderPerspective(*lab.tracer, camera, options); });
    ASSERT_EQ(image.width(), 48);
    ASSERT_EQ(image.height(), 36);
    int lit = 0;
    for (const Rgb& p : image.pixels()) {
        EXPECT_TRUE(p.r == p.g && p.g == p.b);  // colour off: grey
        lit += p.r > 10;
    }
    EXPECT_GT(lit, 48 * 36 * 9 / 10);
    EXPECT_EQ(test::withThreads(1, [&] { return renderPerspective(*lab.tracer, camera, options); }).pixels(),
              image.pixels());
    options.seed = 8;
    EXPECT_NE(renderPerspective(*lab.tracer, camera, options).pixels(), image.pixels());
}

TEST(Render, ExposureAndToneCurve) {
    LuminanceImage flat{4, 2, std::vector<double>(8, 50.0), {}, {}, {}};
    EXPECT_NEAR(autoExposure(flat), 0.18 / 50, 1e-6);
    LuminanceImage black{2, 2, std::vector<double>(4, 0.0), {}, {}, {}};
    EXPECT_EQ(autoExposure(black), 1);
    EXPECT_EQ(toneMap(black, 1).at(1, 1), kBlack);
    LuminanceImage ramp{5, 1, {0, 1, 10, 100, 1e6}, {}, {}, {}};
    Image t = toneMap(ramp, 0.01);
    for (int x = 1; x < 5; ++x) EXPECT_GT(t.at(x, 0).r, t.at(x - 1, 0).r);
    EXPECT_EQ(t.at(4, 0), kWhite);
    // Middle grey maps to the sRGB code of Reinhard's 0.18 -> ~0.16.
    LuminanceImage grey{1, 1, {0.18}, {}, {}, {}};
    EXPECT_NEAR(toneMap(grey, 1).at(0, 0).r, 112, 4);
}

TEST(Render, SideBySideHoldsBothImages) {
    Image a(30, 20, Rgb{255, 0, 0}), b(40, 25, Rgb{0, 0, 255});
    Image both = sideBySide(a, b);
    EXPECT_EQ(both.width(), 30 + 40 + 30);
    EXPECT_GT(both.height(), 25);
    int red = 0, blue = 0;
    for (const Rgb& p : both.pixels()) red += p == Rgb{255, 0, 0}, blue += p == Rgb{0, 0, 255};
    EXPECT_EQ(red, 30 * 20);
    EXPECT_EQ(blue, 40 * 25);
}

// A 4 x 4 x 3 m room with red walls, a grey floor and ceiling, a warm (2700 K) ceiling
// panel and a glazed south window (to a uniform sky).
Scene redRoom() {
    Material red;
    red.reflectance = Vec3(0.6, 0.1, 0.1);
    Scene scene = test::SceneBuilder()
                      .material("red", red)
                      .material("grey", test::diffuse(0.5))
                      .material("glass", test::glass(0.8))
                      .room({0, 0, 0}, {4, 4, 3}, "grey", "red", "grey")
                      .window(Wall::South, 1, 2, 1, 1, "glass")
                      .emitter("lamp", rectEmitter({2, 2, 2.99}, {0, 0, -1}, {0, 1, 0}, {0.6, 0.6}), 4000)
                      .uniformSky(3000, 0)
                      .build();
    scene.emitters[0].cctK = 2700;
    return scene;
}

TEST(Render, ColourIsWhatThePixelSees) {
    test::SceneLab lab(redRoom());
    const Vec3 centre{2, 2, 1.5};
    // A red wall: red, scaled to luminance 1.
    Vec3 wall = seenColor(*lab.tracer, Ray{centre, {0, 1, 0}});
    EXPECT_NEAR(luminance(wall), 1, 1e-9);
    EXPECT_GT(wall.x, 3 * wall.y);
    // The grey floor: neutral.
    Vec3 floor = seenColor(*lab.tracer, Ray{centre, {0.3, 0.2, -1}});
    EXPECT_NEAR(floor.x, 1, 1e-9);
    EXPECT_NEAR(floor.z, 1, 1e-9);
    // The 2700 K panel: warm (the black body's colour at luminance 1).
    Vec3 lamp = seenColor(*lab.tracer, Ray{centre, {0, 0, 1}});
    Vec3 warm = blackBodyRgb(2700);
    EXPECT_NEAR(lamp.x, warm.x / luminance(warm), 1e-9);
    EXPECT_GT(lamp.x, lamp.z);
    // Through the window's glass: the sky (uniform, so neutral), not the pane.
    Vec3 sky = seenColor(*lab.tracer, Ray{centre, normalize(Vec3(0, -2, 0.1))});
    Vec3 expected = lab.daylight->Le(normalize(Vec3(0, -2, 0.1)));
    EXPECT_NEAR(sky.x, expected.x / luminance(expected), 1e-9);
    EXPECT_NEAR(sky.z, expected.z / luminance(expected), 1e-9);
    // At night a ray to nothing is white.
    test::SceneLab night(test::SceneBuilder().material("grey", test::diffuse(0.5)).build());
    Vec3 nothing = seenColor(*night.tracer, Ray{{0, 0, 0}, {0, 0, 1}});
    EXPECT_EQ(nothing.x, 1);
    EXPECT_EQ(nothing.z, 1);
}

TEST(Render, ColourRenderKeepsTheLuminanceAndCountsItsRows) {
    test::SceneLab lab(redRoom());
    RenderOptions options;
    options.width = 40, options.height = 30, options.samplesPerPixel = 4, options.denoise = false;
    std::atomic<int> rows{0};
    options.rowsDone = &rows;
    Camera camera = lookingAt({2, 0.5, 1.5}, {2, 4, 1.5}, 60);  // facing the north wall
    LuminanceImage colour = renderLuminance(*lab.tracer, camera, options);
    EXPECT_EQ(rows.load(), 30);
    options.color = false;
    options.rowsDone = nullptr;
    LuminanceImage grey = renderLuminance(*lab.tracer, camera, options);
    // Colour does not change the light: the same luminance, sample for sample.
    EXPECT_EQ(colour.values, grey.values);
    ASSERT_EQ(colour.chroma.size(), colour.values.size());
    EXPECT_TRUE(grey.chroma.empty());
    // The middle of the picture is the red wall.
    Image picture = toneMap(colour, autoExposure(colour));
    Rgb middle = picture.at(20, 15);
    EXPECT_GT(middle.r, middle.g + 40);
    for (const Vec3& c : colour.chroma) EXPECT_NEAR(luminance(c), 1, 1e-6);
}

TEST(Render, FalseColourViewHasALegendInCandelas) {
    LuminanceImage image{100, 80, std::vector<double>(8000, 50.0), {}, {}, {}};
    for (int i = 0; i < 10; ++i) image.values[size_t(i)] = 1e6;  // a lamp: above the 99.5th percentile
    FalseColor scale = luminanceFalseColor(image);
    EXPECT_EQ(scale.scale, ColorScale::Log);
    EXPECT_EQ(scale.maxValue, 50);  // the 99.5th percentile is 50: the lamp saturates
    EXPECT_NEAR(scale.minValue(), 0.005, 1e-12);
    Image view = falseColorView(image, scale);
    EXPECT_EQ(view.width(), 100 + 90);
    EXPECT_EQ(view.at(50, 40), scale.color(50));
    EXPECT_EQ(view.at(5, 0), scale.color(1e6));
    int ink = 0;
    for (int y = 0; y < view.height(); ++y)
        for (int x = 100; x < view.width(); ++x) ink += view.at(x, y) == kBlack;
    EXPECT_GT(ink, 80);  // the bar's frame, ticks and labels
}

}  // namespace
}  // namespace luxplan
