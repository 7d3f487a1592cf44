// Perspective renders: a lit room gives a non-black, deterministic picture; the tone
// curve and the automatic exposure behave; side-by-side keeps both images.
#include <gtest/gtest.h>

#include <luxplan/output/render.h>
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
    Camera camera = defaultCamera(lab.scene);
    Image image = test::withThreads(2, [&] { return renderPerspective(*lab.tracer, camera, options); });
    ASSERT_EQ(image.width(), 48);
    ASSERT_EQ(image.height(), 36);
    int lit = 0;
    for (const Rgb& p : image.pixels()) {
        EXPECT_TRUE(p.r == p.g && p.g == p.b);  // luminance only: grey
        lit += p.r > 10;
    }
    EXPECT_GT(lit, 48 * 36 * 9 / 10);
    EXPECT_EQ(test::withThreads(1, [&] { return renderPerspective(*lab.tracer, camera, options); }).pixels(),
              image.pixels());
    options.seed = 8;
    EXPECT_NE(renderPerspective(*lab.tracer, camera, options).pixels(), image.pixels());
}

TEST(Render, ExposureAndToneCurve) {
    LuminanceImage flat{4, 2, std::vector<double>(8, 50.0), {}, {}};
    EXPECT_NEAR(autoExposure(flat), 0.18 / 50, 1e-6);
    LuminanceImage black{2, 2, std::vector<double>(4, 0.0), {}, {}};
    EXPECT_EQ(autoExposure(black), 1);
    EXPECT_EQ(toneMap(black, 1).at(1, 1), kBlack);
    LuminanceImage ramp{5, 1, {0, 1, 10, 100, 1e6}, {}, {}};
    Image t = toneMap(ramp, 0.01);
    for (int x = 1; x < 5; ++x) EXPECT_GT(t.at(x, 0).r, t.at(x - 1, 0).r);
    EXPECT_EQ(t.at(4, 0), kWhite);
    // Middle grey maps to the sRGB code of Reinhard's 0.18 -> ~0.16.
    LuminanceImage grey{1, 1, {0.18}, {}, {}};
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

}  // namespace
}  // namespace luxplan
