// The render's denoiser: noise goes, edges between surfaces and strong shadow edges on
// one surface stay, and a denoised low-sample render is closer to a high-sample one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <luxplan/output/denoise.h>
#include <luxplan/output/render.h>
#include "support/scene_lab.h"
#include "support/shared_scenes.h"

namespace luxplan {
namespace {

// A floor seen from above at 2 m: two halves with luminances `left` and `right`
// (surface ids `leftSurface`, 1), Gaussian noise of standard deviation `sd`.
struct Synthetic {
    Synthetic(double left, double right, int leftSurface, double sd) {
        guide.width = kW, guide.height = kH;
        std::mt19937 gen(5);
        std::normal_distribution<double> noise(0, sd);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                bool isLeft = x < kW / 2;
                guide.position.push_back(Vec3(0.01 * x, 0.01 * y, 0));
                guide.normal.push_back(Vec3(0, 0, 1));
                guide.surface.push_back(isLeft ? leftSurface : 1);
                truth.push_back(isLeft ? left : right);
                values.push_back(truth.back() + noise(gen));
                variance.push_back(sd * sd);
            }
    }
    double rmse(const std::vector<double>& v, int x0, int x1) const {
        double sum = 0;
        int count = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = x0; x < x1; ++x, ++count) sum += std::pow(v[size_t(y) * kW + x] - truth[size_t(y) * kW + x], 2);
        return std::sqrt(sum / count);
    }
    double columnMean(const std::vector<double>& v, int x) const {
        double sum = 0;
        for (int y = 0; y < kH; ++y) sum += v[size_t(y) * kW + x];
        return sum / kH;
    }
    static constexpr int kW = 64, kH = 32;
    GuideBuffer guide;
    std::vector<double> truth, values, variance;
    const Vec3 camera{0.32, 0.16, 2};
};

TEST(Denoise, RemovesNoiseAndKeepsTheEdgeBetweenSurfaces) {
    Synthetic s(100, 300, 0, 20);
    std::vector<double> out = s.values;
    denoiseLuminance(out, s.variance, s.guide, s.camera);
    EXPECT_LT(s.rmse(out, 0, Synthetic::kW), s.rmse(s.values, 0, Synthetic::kW) / 4);
    // The columns either side of the edge keep their own level.
    EXPECT_NEAR(s.columnMean(out, Synthetic::kW / 2 - 1), 100, 5);
    EXPECT_NEAR(s.columnMean(out, Synthetic::kW / 2), 300, 5);
}

TEST(Denoise, KeepsAShadowEdgeWellAboveTheNoise) {
    Synthetic s(100, 1000, 1, 10);  // one surface: only the luminance weight separates them
    std::vector<double> out = s.values;
    denoiseLuminance(out, s.variance, s.guide, s.camera);
    EXPECT_NEAR(s.columnMean(out, Synthetic::kW / 2 - 1), 100, 10);
    EXPECT_NEAR(s.columnMean(out, Synthetic::kW / 2), 1000, 100);
    EXPECT_LT(s.rmse(out, 0, Synthetic::kW), s.rmse(s.values, 0, Synthetic::kW) / 2);
}

TEST(Denoise, PixelsThatSeeNothingStayAndSizesMustAgree) {
    Synthetic s(100, 300, -1, 20);  // the left half sees no surface
    std::vector<double> out = s.values;
    denoiseLuminance(out, s.variance, s.guide, s.camera);
    for (int x = 0; x < Synthetic::kW / 2; ++x) EXPECT_EQ(out[size_t(x)], s.values[size_t(x)]);
    std::vector<double> shorter(10);
    EXPECT_THROW(denoiseLuminance(shorter, s.variance, s.guide, s.camera), std::invalid_argument);
}

TEST(Denoise, ALowSampleRenderComesCloserToAHighSampleOne) {
    test::SceneLab lab(test::litRoom());
    Camera camera = defaultCamera(lab.scene);
    RenderOptions o;
    o.width = 48, o.height = 36;
    o.samplesPerPixel = 256;
    LuminanceImage reference = renderLuminance(*lab.tracer, camera, o);
    o.samplesPerPixel = 8, o.seed = 2;
    LuminanceImage noisy = renderLuminance(*lab.tracer, camera, o);
    std::vector<double> denoised(noisy.values.size());
    for (size_t i = 0; i < denoised.size(); ++i) denoised[i] = noisy.values[i] - noisy.emitters[i];
    denoiseLuminance(denoised, noisy.variance, cameraGuide(lab.tracer->rayTracer(), camera, o.width, o.height),
                     camera.position);
    for (size_t i = 0; i < denoised.size(); ++i) denoised[i] += noisy.emitters[i];
    // Compared as the picture shows them: tone mapped with the reference's exposure; by
    // the mean absolute error, as the few pixels on the lamp's rim differ by sampling
    // (how much of the pixel the lamp covers) in both pictures alike.
    const double exposure = autoExposure(reference);
    const Image truth = toneMap(reference, exposure);
    auto meanError = [&](const std::vector<double>& v) {
        Image image = toneMap(LuminanceImage{o.width, o.height, v, {}, {}, {}}, exposure);
        double sum = 0;
        for (size_t i = 0; i < image.pixels().size(); ++i) sum += std::abs(double(image.pixels()[i].r) - truth.pixels()[i].r);
        return sum / double(image.pixels().size());
    };
    EXPECT_LT(meanError(denoised), 0.6 * meanError(noisy.values)) << "raw " << meanError(noisy.values);
}

}  // namespace
}  // namespace luxplan
