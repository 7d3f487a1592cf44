// Embree scene costs on the bundled office: a full layout update (every instance
// transform + top-level commit) against raw ray throughput on the same scene.
#include <benchmark/benchmark.h>

#include <luxplan/core/rng.h>
#include <luxplan/core/warp.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/rt/embree_scene.h>

namespace luxplan {
namespace {

const Scene& officeScene() {
    static const Scene scene = io::loadScene(std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json");
    return scene;
}

// Moves every movable entity a little, as an optimizer step over all of them would:
// their vertices rewritten and the top level rebuilt (rt/embree_scene.h).
void BM_FullLayoutUpdate(benchmark::State& state) {
    const Scene& scene = officeScene();
    Layout layout = initialLayout(scene);
    EmbreeScene rt(scene, layout);
    Rng rng(1);
    for (auto _ : state) {
        for (size_t i = 0; i < scene.entities.size(); ++i)
            if (scene.entities[i].movable()) layout.placements[i].position.x += 0.01 * (rng.uniform() - 0.5);
        rt.setLayout(layout);
    }
    state.counters["entities"] = double(rt.entityCount());
    state.counters["updates/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FullLayoutUpdate)->Unit(benchmark::kMicrosecond);

// Cosine-distributed rays from random points inside the room: the distribution a
// path tracer's bounces have.
void BM_RawIntersect(benchmark::State& state) {
    const Scene& scene = officeScene();
    EmbreeScene rt(scene, initialLayout(scene));
    Bounds3 room = scene.room()->box;
    Rng rng(2);
    int64_t rays = 0;
    for (auto _ : state) {
        Vec3 o = room.lo + room.size() * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
        Vec3 d = sampleUniformSphere({rng.uniform(), rng.uniform()});
        benchmark::DoNotOptimize(rt.intersect({o, d}));
        ++rays;
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RawIntersect);

void BM_RawOccluded(benchmark::State& state) {
    const Scene& scene = officeScene();
    EmbreeScene rt(scene, initialLayout(scene));
    Bounds3 room = scene.room()->box;
    Rng rng(3);
    int64_t rays = 0;
    for (auto _ : state) {
        Vec3 a = room.lo + room.size() * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
        Vec3 b = room.lo + room.size() * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
        benchmark::DoNotOptimize(rt.occluded({a, b - a, 1e-4, 1 - 1e-4}));
        ++rays;
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RawOccluded);

}  // namespace
}  // namespace luxplan
