// The fast path tracer against its simple twin (pathtracer/reference_path_tracer.h) on
// every bundled scene: at the scene's own layout, one point of up to three of its light
// samplers each, illuminance (a cosine sensor facing up) or mean luminance (a sphere),
// the two estimates must agree within four standard errors of their difference, plus
// 2% of the larger for what the reference's fixed depth leaves out. The fast one's
// strategies (portals, sunlit patches, open sun disks, the exterior sun, sealed boxes,
// roulette, the per-thread caches) all must give the reference's answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <luxplan/core/rng.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/pathtracer/reference_path_tracer.h>
#include <luxplan/rt/embree_scene.h>
#include <luxplan/scene/layout.h>

namespace luxplan {
namespace reference_test {

namespace fs = std::filesystem;

// Every bundled scene file (a JSON object with a "luxplan" key), by path under scenes/.
std::vector<std::string> bundledScenes() {
    std::vector<std::string> files;
    const fs::path root = fs::path(LUXPLAN_SOURCE_DIR) / "scenes";
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".json") continue;
        std::ifstream in(entry.path());
        const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
        if (j.is_object() && j.contains("luxplan")) files.push_back(fs::relative(entry.path(), root).string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

struct Estimate {
    double mean = 0, error = 0;
};

template <class Trace>
Estimate estimate(int paths, Trace&& trace) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < paths; ++i) {
        const double x = trace(i);
        sum += x, sum2 += x * x;
    }
    const double mean = sum / paths;
    return {mean, std::sqrt(std::max(0.0, sum2 / paths - mean * mean) / (paths - 1))};
}

class ReferenceTracer : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceTracer, FastTracerAgreesAtTheScenesSamplers) {
    const fs::path file = fs::path(LUXPLAN_SOURCE_DIR) / "scenes" / GetParam();
    const Scene scene = io::loadScene(file);
    const Layout layout = initialLayout(scene);
    std::optional<DaylightEnvironment> daylight;
    if (scene.daylight) daylight = buildDaylight(*scene.daylight, scene.site);
    const DaylightEnvironment* day = daylight ? &*daylight : nullptr;
    const EmbreeScene rt(scene, layout);
    const PathTracer fast(rt, day);
    const ReferencePathTracer reference(rt, day);
    // Up to three samplers, spread over the scene's list.
    const size_t count = scene.samplers.size(), used = std::min<size_t>(3, count);
    constexpr int kFastPaths = 4000, kReferencePaths = 4000;
    for (size_t n = 0; n < used; ++n) {
        const size_t k = n * count / used;
        const std::unique_ptr<PlacedSampler> placed = placeSampler(scene.samplers[k], fast);
        const std::vector<Vec3> dots = placed->drawing().dots;
        if (dots.empty()) continue;
        const Vec3 p = dots[dots.size() / 2];
        const CosineSensor up(p, Vec3(0, 0, 1));
        const SphereSensor sphere(p);
        const Sensor& sensor = n % 2 == 0 ? static_cast<const Sensor&>(up) : sphere;
        const Estimate a = estimate(kFastPaths, [&](int i) {
            Rng rng(0x5eed0000u + uint64_t(k) * 100003u + uint64_t(i));
            RayStats stats;
            return fast.sample(sensor, rng, stats);
        });
        const Estimate b = estimate(kReferencePaths, [&](int i) {
            Rng rng(0xbeef0000u + uint64_t(k) * 100003u + uint64_t(i));
            return reference.sample(sensor, rng);
        });
        const double tolerance = 4 * std::hypot(a.error, b.error) + 0.02 * std::max(std::abs(a.mean), std::abs(b.mean));
        EXPECT_LE(std::abs(a.mean - b.mean), tolerance)
            << GetParam() << ", sampler " << scene.samplers[k].name << " at (" << p.x << ", " << p.y << ", " << p.z
            << "), " << (n % 2 == 0 ? "illuminance" : "sphere") << ": fast " << a.mean << " ± " << a.error << ", reference "
            << b.mean << " ± " << b.error;
    }
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, ReferenceTracer, ::testing::ValuesIn(bundledScenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(0, info.param.size() - 5);
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace reference_test
}  // namespace luxplan
