// The RGB8 image: PNG round trip, drawing primitives, the bitmap font, and the
// false-colour scale with its legend.
#include <gtest/gtest.h>

#include <cstring>

#include <stb_image.h>

#include <luxplan/core/error.h>
#include <luxplan/core/format.h>
#include <luxplan/output/false_color.h>
#include <luxplan/output/image.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

int countPixels(const Image& image, Rgb color) {
    return int(std::count(image.pixels().begin(), image.pixels().end(), color));
}

TEST(Image, PngRoundTripKeepsEveryPixel) {
    Image image(37, 23);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) image.at(x, y) = {uint8_t(x * 7), uint8_t(y * 11), uint8_t((x * y) % 256)};
    test::TempDir dir;
    auto file = dir.path() / "round.png";
    writePng(image, file);

    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(file.string().c_str(), &w, &h, &n, 3);
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(w, 37);
    EXPECT_EQ(h, 23);
    EXPECT_EQ(0, std::memcmp(data, image.pixels().data(), size_t(w) * size_t(h) * 3));
    stbi_image_free(data);

    Image back = readPng(file);
    EXPECT_EQ(back.pixels(), image.pixels());
    EXPECT_EQ(encodePng(image).size(), std::filesystem::file_size(file));
}

TEST(Image, WriteAndReadFailuresThrowIoError) {
    test::TempDir dir;
    EXPECT_THROW(writePng(Image(4, 4), dir.path() / "missing" / "x.png"), IoError);
    EXPECT_THROW(readPng(dir.path() / "absent.png"), IoError);
    EXPECT_THROW(encodePng(Image()), IoError);
}

TEST(Image, RectanglesCoverThePixelsWhoseCentresTheyHold) {
    Image image(10, 10, kWhite);
    image.fillRect(2, 3, 5, 7, kBlack);
    EXPECT_EQ(countPixels(image, kBlack), 3 * 4);
    EXPECT_EQ(image.at(2, 3), kBlack);
    EXPECT_EQ(image.at(4, 6), kBlack);
    EXPECT_EQ(image.at(5, 6), kWhite);
    // Clipping: a rectangle far outside draws nothing and does not crash.
    image.fillRect(-100, -100, -50, -50, kBlack);
    image.fillRect(8, 8, 100, 100, Rgb{1, 2, 3});
    EXPECT_EQ(countPixels(image, Rgb{1, 2, 3}), 4);
}

TEST(Image, BlendingMixesByAlpha) {
    Image image(1, 1, kBlack);
    image.blendPixel(0, 0, kWhite, 0.5);
    EXPECT_NEAR(image.at(0, 0).r, 128, 1);
    EXPECT_EQ(mix(kBlack, Rgb{200, 100, 50}, 1), (Rgb{200, 100, 50}));
}

TEST(Image, LinesPolygonsAndCirclesHaveTheirArea) {
    Image image(200, 200, kWhite);
    image.drawLine({20, 50}, {180, 50}, kBlack, 4);
    // 160 x 4 body plus round caps (pi r^2 = 12.6).
    EXPECT_NEAR(countPixels(image, kBlack), 160 * 4 + 12.6, 20);

    image.fill(kWhite);
    image.drawLine({10, 10}, {150, 120}, kBlack, 1);
    // A thin diagonal line is connected: every column between its ends has a pixel.
    for (int x = 11; x < 149; ++x) {
        bool any = false;
        for (int y = 0; y < 200; ++y) any = any || image.at(x, y) == kBlack;
        EXPECT_TRUE(any) << x;
    }

    image.fill(kWhite);
    image.fillPolygon({{20, 20}, {120, 20}, {20, 120}}, kBlack);
    EXPECT_NEAR(countPixels(image, kBlack), 5000, 150);
    // Translucent overlapping outline corners are blended once.
    image.fill(kWhite);
    image.drawPolygon({{20, 20}, {120, 20}, {120, 120}, {20, 120}}, kBlack, 3, 0.5);
    for (const Rgb& p : image.pixels()) EXPECT_TRUE(p == kWhite || std::abs(int(p.r) - 128) <= 1);

    image.fill(kWhite);
    image.fillCircle({100, 100}, 30, kBlack);
    EXPECT_NEAR(countPixels(image, kBlack), kPi * 900, 60);
    image.fill(kWhite);
    image.drawCircle({100, 100}, 30, kBlack, 2);
    EXPECT_NEAR(countPixels(image, kBlack), 2 * kPi * 30 * 2, 40);
    EXPECT_EQ(image.at(100, 100), kWhite);
}

TEST(Image, TextUsesTheBitmapFont) {
    EXPECT_EQ(textWidth("abc"), 17);
    EXPECT_EQ(textWidth("ab\nabcd", 2), 2 * 23);
    EXPECT_EQ(textHeight("x"), 7);
    EXPECT_EQ(textHeight("x\ny", 3), 3 * 16);
    Image image(120, 20, kWhite);
    image.drawText(2, 2, "0123 lx", kBlack);
    int inked = countPixels(image, kBlack);
    EXPECT_GT(inked, 40);
    // Every ink pixel lies in the text's box.
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (image.at(x, y) == kBlack) {
                EXPECT_GE(x, 2);
                EXPECT_LT(x, 2 + textWidth("0123 lx"));
                EXPECT_GE(y, 2);
                EXPECT_LT(y, 9);
            }
    // Different glyphs differ; unknown characters draw as '?'.
    Image a(10, 10, kWhite), b(10, 10, kWhite), c(10, 10, kWhite), q(10, 10, kWhite);
    a.drawText(0, 0, "8", kBlack);
    b.drawText(0, 0, "B", kBlack);
    c.drawText(0, 0, "\x01", kBlack);
    q.drawText(0, 0, "?", kBlack);
    EXPECT_NE(a.pixels(), b.pixels());
    EXPECT_EQ(c.pixels(), q.pixels());
    // Right alignment ends at x.
    Image r(60, 10, kWhite);
    r.drawText(50, 0, "ab", kBlack, 1, TextAlign::Right);
    for (int y = 0; y < 10; ++y)
        for (int x = 50; x < 60; ++x) EXPECT_EQ(r.at(x, y), kWhite);
}

FalseColor scaleOf(ColorScale scale, double maxValue, double decades = 3) {
    FalseColor f;
    f.scale = scale, f.maxValue = maxValue, f.decades = decades;
    return f;
}

TEST(FalseColor, ScaleIsMonotoneAndSaturates) {
    FalseColor linear = scaleOf(ColorScale::Linear, 500);
    FalseColor log = scaleOf(ColorScale::Log, 1000, 3);
    double previous = -1, previousLog = -1;
    for (double v = 0; v <= 600; v += 5) {
        double f = linear.fraction(v), g = log.fraction(v);
        EXPECT_GE(f, previous);
        EXPECT_GE(g, previousLog);
        previous = f, previousLog = g;
    }
    EXPECT_EQ(linear.fraction(0), 0);
    EXPECT_EQ(linear.fraction(500), 1);
    EXPECT_EQ(linear.fraction(1e9), 1);
    EXPECT_EQ(log.minValue(), 1);
    EXPECT_NEAR(log.fraction(10), 1.0 / 3, 1e-12);
    EXPECT_NEAR(log.fraction(100), 2.0 / 3, 1e-12);
    EXPECT_EQ(log.fraction(0), 0);
    // The palette runs from blue to red and every step of the scale changes colour.
    EXPECT_GT(falseColorRamp(0).b, falseColorRamp(0).r);
    EXPECT_GT(falseColorRamp(1).r, falseColorRamp(1).b);
    for (int i = 0; i < 20; ++i) EXPECT_NE(linear.color(i * 25.0), linear.color((i + 1) * 25.0)) << i;
}

TEST(FalseColor, AutomaticMaximumIsARoundNumberAboveThePercentile) {
    EXPECT_EQ(niceCeil(1), 1);
    EXPECT_EQ(niceCeil(1.2), 2);
    EXPECT_EQ(niceCeil(2.1), 2.5);
    EXPECT_EQ(niceCeil(430), 500);
    EXPECT_EQ(niceCeil(501), 1000);
    EXPECT_EQ(niceCeil(0), 1);
    std::vector<double> values;
    for (int i = 0; i < 100; ++i) values.push_back(4.0 * i);  // 0 .. 396; 95th percentile 376
    values.push_back(1e6);                                    // one sun patch
    EXPECT_EQ(autoFalseColor(values).maxValue, 500);
    EXPECT_EQ(autoFalseColor({}).maxValue, 1);
    EXPECT_EQ(autoFalseColor({0, 0}).maxValue, 1);
    EXPECT_EQ(compactNumber(0), "0");
    EXPECT_EQ(compactNumber(250), "250");
    EXPECT_EQ(compactNumber(2.5), "2.5");
    EXPECT_EQ(compactNumber(25000), "25k");
}

TEST(FalseColor, LegendDrawsTheBarAndItsLabels) {
    Image image(200, 260, kWhite);
    FalseColor scale = scaleOf(ColorScale::Linear, 1000);
    int used = drawLegend(image, scale, 20, 30, 16, 200, "lx");
    EXPECT_GT(used, 16 + textWidth("1000"));
    // Top of the bar is the top colour, bottom the bottom colour.
    EXPECT_EQ(image.at(28, 31), falseColorRamp(1 - 1.5 / 200));
    EXPECT_EQ(image.at(28, 228), falseColorRamp(1 - 198.5 / 200));
    // Labels to the right of the bar.
    int ink = 0;
    for (int y = 0; y < 260; ++y)
        for (int x = 44; x < 200; ++x) ink += image.at(x, y) == kBlack;
    EXPECT_GT(ink, 60);
    // Log legend: one tick per decade.
    Image logImage(200, 260, kWhite);
    drawLegend(logImage, scaleOf(ColorScale::Log, 1000, 3), 20, 30, 16, 200, "lx");
    EXPECT_NE(logImage.pixels(), image.pixels());
}

TEST(FalseColor, TargetScaleIsCentredOnTheBand) {
    // 300-500 lx: 30 to 5000 lx, the band's geometric mean in the middle.
    FalseColor f = targetFalseColor(300, 500);
    EXPECT_EQ(f.scale, ColorScale::Log);
    EXPECT_NEAR(f.minValue(), 30, 1e-9);
    EXPECT_NEAR(f.maxValue, 5000, 1e-9);
    EXPECT_NEAR(f.fraction(std::sqrt(300.0 * 500.0)), 0.5, 1e-12);
    ASSERT_TRUE(f.band);
    EXPECT_EQ((*f.band)[0], 300);
    EXPECT_EQ((*f.band)[1], 500);
    // "At least 500": 50 to 50000, the band open to the top.
    FalseColor atLeast = targetFalseColor(500, kInf);
    EXPECT_NEAR(atLeast.minValue(), 50, 1e-9);
    EXPECT_NEAR(atLeast.maxValue, 50000, 1e-9);
    EXPECT_NEAR(atLeast.fraction(500), 1.0 / 3, 1e-12);
    EXPECT_EQ((*atLeast.band)[1], atLeast.maxValue);
    // "At most 2000 cd/m2": 20 to 20000.
    FalseColor atMost = targetFalseColor(0, 2000);
    EXPECT_NEAR(atMost.minValue(), 20, 1e-9);
    EXPECT_NEAR(atMost.maxValue, 20000, 1e-9);
    // No band at all: a plain three-decade scale, nothing marked.
    FalseColor none = targetFalseColor(0, kInf);
    EXPECT_FALSE(none.band);
    EXPECT_NEAR(none.decades, 3, 1e-12);
}

TEST(FalseColor, LogTicksAreTheOneTwoFiveValuesAndTheEnds) {
    std::vector<double> ticks = legendTicks(targetFalseColor(300, 500));
    std::vector<double> expected{30, 50, 100, 200, 500, 1000, 2000, 5000};
    ASSERT_EQ(ticks.size(), expected.size());
    for (size_t i = 0; i < ticks.size(); ++i) EXPECT_NEAR(ticks[i], expected[i], 1e-9 * expected[i]) << i;
    std::vector<double> linear = legendTicks(scaleOf(ColorScale::Linear, 1000), 4);
    EXPECT_EQ(linear, (std::vector<double>{0, 250, 500, 750, 1000}));
}

TEST(FalseColor, LegendBracketsTheTargetBand) {
    Image plain(260, 260, kWhite), marked(260, 260, kWhite);
    FalseColor f = targetFalseColor(300, 500);
    FalseColor unmarked = f;
    unmarked.band.reset();
    drawLegend(plain, unmarked, 80, 30, 16, 200, "lx");
    drawLegend(marked, f, 80, 30, 16, 200, "lx");
    // The bracket is left of the bar, between the band's ends and nowhere else.
    auto rowOf = [&](double v) { return int(30 + (1 - f.fraction(v)) * 200); };
    int inside = 0, outside = 0;
    for (int y = 0; y < 260; ++y)
        for (int x = 0; x < 80; ++x)
            if (marked.at(x, y) != plain.at(x, y)) (y >= rowOf(500) - 2 && y <= rowOf(300) + 2 ? inside : outside) += 1;
    EXPECT_GT(inside, 40);
    EXPECT_EQ(outside, 0);
}

}  // namespace
}  // namespace luxplan
