// Optimizer speed on the bundled office: iterations per second with and without the
// path-traced lighting term, the share of proposals the geometric test rejects before
// any light is measured, and the cost of one geometric evaluation.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <luxplan/daylight/daylight.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/optimizer/optimizer.h>
#include <luxplan/optimizer/path_traced_lighting.h>

namespace luxplan {
namespace {

struct DaylitOffice {
    Scene scene = io::loadScene(std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json");
    DaylightEnvironment daylight = buildDaylight(*scene.daylight, scene.site);
};

DaylitOffice& daylitOffice() {
    static DaylitOffice o;
    return o;
}

void report(benchmark::State& state, const OptimizerResult& r, int64_t iterations, uint64_t lightingEvaluations) {
    int64_t proposed = 0, outside = 0, rejected = 0;
    for (const LevelStats& level : r.levels)
        for (const MoveStats& m : level.moves) proposed += m.proposed, outside += m.outside, rejected += m.rejectedGeometry;
    state.counters["iterations/s"] = benchmark::Counter(double(iterations), benchmark::Counter::kIsRate);
    state.counters["rejected_by_geometry"] = proposed ? double(rejected) / double(proposed) : 0.0;
    state.counters["refused_outside"] = proposed ? double(outside) / double(proposed) : 0.0;
    if (lightingEvaluations) state.counters["lighting_evals/iter"] = double(lightingEvaluations) / double(iterations);
}

void BM_OptimizeGeometryOnly(benchmark::State& state) {
    DaylitOffice& o = daylitOffice();
    OptimizerOptions options = optimizerOptions(o.scene);
    options.iterations = 5000;
    options.stopAtZeroCost = false;
    int64_t iterations = 0;
    OptimizerResult last;
    for (auto _ : state) {
        Optimizer optimizer(o.scene, options);
        last = optimizer.run();
        iterations += last.iterations;
    }
    report(state, last, iterations, 0);
}
BENCHMARK(BM_OptimizeGeometryOnly)->Unit(benchmark::kMillisecond);

void BM_OptimizeWithLighting(benchmark::State& state) {
    DaylitOffice& o = daylitOffice();
    OptimizerOptions options = optimizerOptions(o.scene);
    options.iterations = 200;
    // The argument is the thread count, limited as luxplan's main() does for --threads.
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    MeasureOptions measure;
    measure.pathsPerPoint = o.scene.optimizer.searchPathsPerPoint;
    int64_t iterations = 0;
    uint64_t evaluations = 0;
    OptimizerResult last;
    for (auto _ : state) {
        PathTracedLighting lighting(o.scene, &o.daylight, measure);
        Optimizer optimizer(o.scene, options, &lighting);
        last = optimizer.run();
        iterations += last.iterations;
        evaluations += lighting.evaluations();
    }
    report(state, last, iterations, evaluations);
}
BENCHMARK(BM_OptimizeWithLighting)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// One geometric evaluation (all constraints and the overlap of the moved entities)
// after moving one workstation.
void BM_GeometricEvaluation(benchmark::State& state) {
    DaylitOffice& o = daylitOffice();
    GeometryEvaluator geometry(o.scene);
    Layout layout = initialLayout(o.scene);
    geometry.evaluate(worldTransforms(o.scene, layout));
    geometry.commit();
    int moved = o.scene.findEntity("ws3");
    double dx = 0.01;
    for (auto _ : state) {
        layout.placements[moved].position.x += dx;
        dx = -dx;
        benchmark::DoNotOptimize(geometry.evaluate(worldTransforms(o.scene, layout)));
        geometry.commit();
    }
}
BENCHMARK(BM_GeometricEvaluation)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace luxplan
