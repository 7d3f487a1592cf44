// The path cache's first test of kept segments against a move (SegmentBoxFilter): one
// segment per call, as a check asked before the twenty-sixth sitting, against a path's
// worth of segments per call, two to a vector (docs/performance.md).
#include <benchmark/benchmark.h>

#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/incremental/footprint_geometry.h>

namespace luxplan {
namespace {

// Segments between random points of an 8 m room (in the core's cache: the arithmetic,
// not the memory), against a desk-sized box.
void BM_SegmentBoxFilter(benchmark::State& state) {
    const uint32_t perCall = uint32_t(state.range(0));
    Rng rng(1);
    std::vector<Segment> segments(1 << 16);
    for (Segment& s : segments)
        for (int k = 0; k < 3; ++k) s.from[k] = float(8 * rng.uniform()), s.to[k] = float(8 * rng.uniform());
    const SegmentBoxFilter filter(Bounds3(Vec3(2, 2, 0), Vec3(3.6, 2.8, 1.2)));
    for (auto _ : state) {
        uint32_t mayMeet = 0;
        for (size_t i = 0; i + perCall <= segments.size(); i += perCall)
            mayMeet += uint32_t(__builtin_popcount(filter.mayMeet(&segments[i], perCall)));
        benchmark::DoNotOptimize(mayMeet);
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(segments.size()));
}
BENCHMARK(BM_SegmentBoxFilter)->Arg(1)->Arg(8)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace luxplan
