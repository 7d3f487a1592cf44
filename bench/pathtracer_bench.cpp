// Path tracer throughput on the furnished office (daylight + 6 panels), next to raw
// Embree throughput on the same scene (embree_bench.cpp), single-threaded so that the
// two compare as a ratio on a shared machine.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <luxplan/daylight/daylight.h>
#include <luxplan/incremental/path_cache.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/light_samplers.h>

namespace luxplan {
namespace {

// `measure`'s estimator by default; the search's (no sunlit patches) for the moves.
struct TracedOffice {
    explicit TracedOffice(const PathTracerOptions& tracing = {}) : tracer(rt, &daylight, tracing) {}
    Scene scene = io::loadScene(std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json");
    DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    EmbreeScene rt{scene, initialLayout(scene)};
    PathTracer tracer;
};

PathTracerOptions searchTracing() {
    PathTracerOptions o;
    o.sunPatches = false;  // optimize --sun-patches report: the search without them
    return o;
}

TracedOffice& tracedOffice() {
    static TracedOffice o;
    return o;
}

// The same measurement (same seed: the same rays) every iteration, so that
// BM_ReplayOfficeRays replays exactly its rays.
void BM_MeasureOffice(benchmark::State& state) {
    TracedOffice& o = tracedOffice();
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    MeasureOptions options;
    options.pathsPerPoint = int(state.range(0));
    uint64_t paths = 0, rays = 0, shadow = 0;
    for (auto _ : state) {
        MeasureResult r = measureSamplers(o.tracer, options);
        paths += r.paths;
        rays += r.rays.closest + r.rays.shadow;
        shadow += r.rays.shadow;
    }
    state.counters["paths/s"] = benchmark::Counter(double(paths), benchmark::Counter::kIsRate);
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["rays/path"] = double(rays) / double(paths);
    state.counters["shadow_share"] = double(shadow) / double(rays);
}
BENCHMARK(BM_MeasureOffice)->Arg(64)->Unit(benchmark::kMillisecond);

// Every ray of one BM_MeasureOffice iteration (recorded once), traced again through
// Embree alone: the time the path tracer would take if rays were all it cost. The
// ratio of the two benchmarks' times is the tracer's overhead on the same rays.
void BM_ReplayOfficeRays(benchmark::State& state) {
    TracedOffice& o = tracedOffice();
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    static RayLog log = [&] {
        RayLog l;
        MeasureOptions options;
        options.pathsPerPoint = 64;
        o.rt.record(&l);
        measureSamplers(o.tracer, options);
        o.rt.record(nullptr);
        return l;
    }();
    uint64_t rays = 0;
    for (auto _ : state) {
        for (const Ray& r : log.closest) benchmark::DoNotOptimize(o.rt.intersect(r));
        for (const Ray& r : log.shadow) benchmark::DoNotOptimize(o.rt.occluded(r));
        rays += log.closest.size() + log.shadow.size();
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["rays"] = double(log.closest.size() + log.shadow.size());
}
BENCHMARK(BM_ReplayOfficeRays)->Unit(benchmark::kMillisecond);

// One workstation of the office moved by 20 cm, measured against the layout before
// the move: from scratch (0) or with the path cache (1, exact incremental
// re-evaluation: only the paths the move can change are traced). Both give the same
// numbers (tests/incremental/path_cache_test.cpp); the ratio of their times is
// what incremental re-evaluation saves on the paper's kind of move. The range's
// second argument is the paths per point.
void BM_OfficeWorkstationMove(benchmark::State& state) {
    static TracedOffice o(searchTracing());  // its own: the layout changes
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    const bool incremental = state.range(0) != 0;
    MeasureOptions options;
    options.pathsPerPoint = int(state.range(1));
    const Layout before = initialLayout(o.scene);
    Layout after = before;
    int workstation = -1;
    for (size_t i = 0; i < o.scene.entities.size() && workstation < 0; ++i)
        if (o.scene.entities[i].parent < 0 && o.scene.entities[i].movable() && o.scene.entities[i].isGroup())
            workstation = int(i);
    after.placements[size_t(workstation)].position.x += 0.2;
    PathCache cache(o.scene);
    o.rt.setLayout(before);
    o.tracer.updateLayout();
    measureSamplers(o.tracer, options, &cache);
    cache.commit();
    o.rt.setLayout(after);
    o.tracer.updateLayout();
    uint64_t traced = 0, reused = 0;
    for (auto _ : state) {
        MeasureResult r = measureSamplers(o.tracer, options, incremental ? &cache : nullptr);
        cache.discard();
        traced += r.paths - r.reusedPaths, reused += r.reusedPaths;
    }
    state.counters["traced_share"] = double(traced) / double(traced + reused);
    o.rt.setLayout(before);
    o.tracer.updateLayout();
}
BENCHMARK(BM_OfficeWorkstationMove)->Args({0, 256})->Args({1, 256})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace luxplan
