// Path tracer throughput on the furnished office (daylight + 6 panels), next to raw
// Embree throughput on the same scene (embree_bench.cpp), single-threaded so that the
// two compare as a ratio on a shared machine.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <luxplan/daylight/daylight.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/light_samplers.h>

namespace luxplan {
namespace {

struct Office {
    Scene scene = io::loadScene(std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json");
    DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
    EmbreeScene rt{scene, initialLayout(scene)};
    PathTracer tracer{rt, &daylight};
};

Office& office() {
    static Office o;
    return o;
}

void BM_MeasureOffice(benchmark::State& state) {
    Office& o = office();
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    MeasureOptions options;
    options.pathsPerPoint = int(state.range(0));
    uint64_t paths = 0, rays = 0, shadow = 0;
    for (auto _ : state) {
        MeasureResult r = measureSamplers(o.tracer, options);
        paths += r.paths;
        rays += r.rays.closest + r.rays.shadow;
        shadow += r.rays.shadow;
        ++options.seed;
    }
    state.counters["paths/s"] = benchmark::Counter(double(paths), benchmark::Counter::kIsRate);
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["rays/path"] = double(rays) / double(paths);
    state.counters["shadow_share"] = double(shadow) / double(rays);
}
BENCHMARK(BM_MeasureOffice)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace luxplan
