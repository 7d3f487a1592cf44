// core/sin_cos.h against libm's sine and cosine, on the same random angles of a few
// turns (the samplers' range): the figure behind its use in the warps
// (docs/performance.md, "Sine and cosine without libm").
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include <luxplan/core/rng.h>
#include <luxplan/core/sin_cos.h>

namespace {

using namespace luxplan;

const std::vector<double>& angles() {
    static const std::vector<double> a = [] {
        std::vector<double> v(4096);
        Rng rng(5);
        for (double& x : v) x = (rng.uniform() - 0.25) * 4 * kPi;
        return v;
    }();
    return a;
}

void BM_SinCos(benchmark::State& state) {
    const std::vector<double>& a = angles();
    for (auto _ : state)
        for (double x : a) {
            const SinCos t = sinCos(x);
            benchmark::DoNotOptimize(t);
        }
    state.SetItemsProcessed(state.iterations() * int64_t(a.size()));
}
BENCHMARK(BM_SinCos);

void BM_LibmSinCos(benchmark::State& state) {
    const std::vector<double>& a = angles();
    for (auto _ : state)
        for (double x : a) {
            const SinCos t{std::sin(x), std::cos(x)};
            benchmark::DoNotOptimize(t);
        }
    state.SetItemsProcessed(state.iterations() * int64_t(a.size()));
}
BENCHMARK(BM_LibmSinCos);

}  // namespace
