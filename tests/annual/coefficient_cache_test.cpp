// The coefficient cache against the computation from scratch: over a chain of moves,
// accepted and refused, every hour of every point is the same bit for bit as
// DaylightCoefficients::measure of that layout, while the paths a move cannot change
// are read back.
#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include <luxplan/annual/coefficient_cache.h>
#include <luxplan/annual/scene_year.h>
#include <luxplan/core/rng.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/rt/embree_scene.h>
#include "support/temp_files.h"
#include "support/test_data.h"

namespace luxplan {
namespace coefficient_cache_test {

// tests/data/weather/office.json over three days of June, with a cabinet that moves
// and carries no sampler (its moves leave most floor paths as they were).
Scene office(test::TempDir& dir) {
    nlohmann::json s = nlohmann::json::parse(std::ifstream(std::string(LUXPLAN_TEST_DATA) + "/weather/office.json"));
    s["daylight"]["from"] = "2026-06-17T00:00-06:00";
    s["daylight"]["to"] = "2026-06-20T23:00-06:00";
    s["entities"].push_back(nlohmann::json::parse(R"({
        "name": "cabinet", "position": [1.2, 4.4],
        "placement": {"regions": [{"min": [0.5, 0.5], "max": [5.5, 4.5]}]},
        "parts": [{"box": {"size": [0.8, 0.4, 1.2]}, "material": "wood"}]})"));
    std::filesystem::copy_file(test::kChicagoEpw, dir.path() / "chicago.epw");
    return io::loadScene(dir.write("office.json", s.dump(1)));
}

// The scene in a ray tracer and a tracer under the year's basis, moved to a layout.
struct Placed {
    Placed(const Scene& s, const DaylightCoefficients& year)
        : scene(s), rt(s, initialLayout(s)), tracer(rt, &year.basis(), DaylightCoefficients::tracing()) {}
    void place(const Layout& layout) {
        const std::vector<Transform> world = worldTransforms(scene, layout);
        for (size_t i = 0; i < world.size(); ++i) rt.setEntityTransform(int(i), world[i]);
        rt.commit();
        tracer.updateLayout();
    }
    const Scene& scene;
    EmbreeScene rt;
    PathTracer tracer;
};

bool same(const AnnualSeries& a, const AnnualSeries& b) {
    if (a.samplers.size() != b.samplers.size()) return false;
    auto equal = [](const std::vector<double>& x, const std::vector<double>& y) {
        if (x.size() != y.size()) return false;
        for (size_t i = 0; i < x.size(); ++i)
            if (std::bit_cast<uint64_t>(x[i]) != std::bit_cast<uint64_t>(y[i])) return false;
        return true;
    };
    for (size_t s = 0; s < a.samplers.size(); ++s) {
        const AnnualSampler &x = a.samplers[s], &y = b.samplers[s];
        if (x.name != y.name || !equal(x.values, y.values) || x.points.size() != y.points.size()) return false;
        for (size_t p = 0; p < x.points.size(); ++p)
            if (!equal(x.points[p], y.points[p]) || !equal(x.directSun[p], y.directSun[p])) return false;
    }
    return true;
}

TEST(CoefficientCache, GivesTheNumbersFromScratchOverAChainOfMoves) {
    test::TempDir dir;
    const Scene scene = office(dir);
    const DaylightCoefficients year = sceneYear(scene);
    ASSERT_EQ(year.hours().size(), 20u);  // Monday 19 and Tuesday 20 June 2006, 8-18
    const std::vector<size_t> which = {0, 1};  // the desk's task plane, the floor grid
    constexpr int kPaths = 24;
    constexpr uint64_t kSeed = 7;
    CoefficientCache cache(scene, year, which, kPaths, kSeed);

    Layout layout = initialLayout(scene);
    Placed placed(scene, year);
    PathTracer& tracer = placed.tracer;
    auto place = [&](const Layout& l) { placed.place(l); };
    ASSERT_TRUE(same(cache.measure(tracer), year.measure(tracer, which, kPaths, kSeed)));
    EXPECT_EQ(cache.reusedPaths(), 0u);
    cache.commit();

    Rng rng(3);
    uint64_t reusedWhenTheCabinetMoved = 0, movesOfTheCabinet = 0;
    for (int step = 0; step < 12; ++step) {
        Layout next = layout;
        const size_t entity = step % 3 == 0 ? 0 : 1;  // the desk, or the cabinet
        Placement& p = next.placements[entity];
        p.position.x = std::clamp(p.position.x + 1.2 * (rng.uniform() - 0.5), 1.0, 5.0);
        p.position.y = std::clamp(p.position.y + 1.2 * (rng.uniform() - 0.5), 1.0, 4.2);
        place(next);
        const AnnualSeries cached = cache.measure(tracer);
        EXPECT_TRUE(same(cached, year.measure(tracer, which, kPaths, kSeed))) << "step " << step;
        if (entity == 1) reusedWhenTheCabinetMoved += cache.reusedPaths(), ++movesOfTheCabinet;
        if (entity == 1) {
            // The desk's points: none of their paths... most of them miss a cabinet.
            EXPECT_GT(cache.reusedPaths(), cache.tracedPaths()) << "step " << step;
        }
        if (rng.uniform() < 0.6) {
            cache.commit();
            layout = next;
        } else {
            cache.discard();
            place(layout);
        }
    }
    EXPECT_GT(movesOfTheCabinet, 0u);
    EXPECT_GT(reusedWhenTheCabinetMoved, 0u);
}

// A point the layout covers is not measured; when it is uncovered again, it is traced
// afresh (what it kept may be stale), and still gives the numbers from scratch.
TEST(CoefficientCache, AFloorPointCoveredAndUncoveredIsTracedAgain) {
    test::TempDir dir;
    const Scene scene = office(dir);
    const DaylightCoefficients year = sceneYear(scene);
    const std::vector<size_t> which = {1};
    CoefficientCache cache(scene, year, which, 16, 3);
    Layout layout = initialLayout(scene);
    Placed placed(scene, year);
    PathTracer& tracer = placed.tracer;
    auto place = [&](const Layout& l) { placed.place(l); };
    for (const auto& [x, y] : {std::pair{1.2, 4.4}, {3.0, 2.5}, {1.2, 1.0}, {3.0, 2.5}, {4.5, 4.0}}) {
        Layout next = layout;
        next.placements[1].position.x = x, next.placements[1].position.y = y;
        place(next);
        EXPECT_TRUE(same(cache.measure(tracer), year.measure(tracer, which, 16, 3))) << x << ", " << y;
        cache.commit();
        layout = next;
    }
}

}  // namespace coefficient_cache_test
}  // namespace luxplan
