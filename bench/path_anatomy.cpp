// Where one sampler item's light comes from, path by path: the distribution of its
// per-path estimates (mean, spread, zeros, the share of the brightest 1%) and how the
// mean grows as paths may bounce more (each path cut after 1, 2, 3, ... surface
// vertices, the same random numbers, so each row adds the light of one more bounce).
// With --sources, the uncut paths' light split by kind (sun, sky, luminaires) and by
// the surfaces it scattered off, each part with its mean, its spread per path and its
// share of the variance (its covariance with the whole over the whole's variance; the
// shares add up to 100%): which light the noise comes from.
//
//   luxplan_path_anatomy SCENE LAYOUT SAMPLER ITEM [PATHS] [--sun-patches] [--sources] [--light-roulette A]
//
// --light-roulette: the light samples' roulette with the floors a search at share A
// would take on this layout (lightSampleFloors, MeasureOptions::lightFloors; default 0,
// every sample).
//
// SAMPLER is the sampler's name, ITEM its point or stratum (measure --json's `points`
// order). The paths are PCG-seeded, one thread. docs/performance.md quotes its output.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include <luxplan/daylight/daylight.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/pathtracer/path_tracer.h>

using namespace luxplan;

namespace {

struct Row {
    double mean = 0, sd = 0, zeros = 0, median = 0, p99 = 0, top1Share = 0, raysPerPath = 0;
};

// One path's share of its item's estimate, by kind and bounces (LightBudget::byBounce).
using Parts = std::array<std::array<double, LightBudget::kBounces>, LightBudget::kKinds>;

Row trace(const Scene& scene, const EmbreeScene& rt, const DaylightEnvironment* daylight, const PlacedSampler& sampler,
          int item, int paths, int maxDepth, bool sunPatches, double lightFloor, std::vector<Parts>* parts = nullptr) {
    PathTracerOptions options;
    options.sunPatches = sunPatches;
    options.maxDepth = maxDepth;
    PathTracer tracer(rt, daylight, options);
    std::vector<double> values;
    RayStats stats;
    for (int path = 0; path < paths; ++path) {
        Rng rng(hashValues({scene.optimizer.seed, uint64_t(item), uint64_t(path)}));
        PathSamples samples(rng);
        PathContributions c(item);
        LightBudget budget;
        PathParams params;
        params.lightFloor = lightFloor;
        params.budget = parts ? &budget : nullptr;
        sampler.sample(tracer, item, samples, stats, params, c);
        double own = 0;  // what the path adds to its item's estimate
        for (int k = 0; k < c.size(); ++k)
            if (c.itemAt(k) == item) own += c.valueAt(k);
        const double scale = sampler.sharesPaths() ? 1.0 / sampler.items() : 1.0;
        values.push_back(own * scale);
        if (parts) {
            // The budget holds the path's whole light once. Its item's share is all of it
            // but for a directional path's eye light samples (counted in the strata they
            // fall in): the parts are scaled to the item's share, which is exact where
            // the eye draws none (a glare frustum that sees no lamp, window or sun).
            Parts p = budget.byBounce;
            const double credited = budget.total();
            const double share = credited != 0 ? own * scale / credited : 0;
            for (auto& kind : p)
                for (double& x : kind) x *= share;
            parts->push_back(p);
        }
    }
    Row r;
    double sumSquares = 0;
    for (double v : values) r.mean += v, sumSquares += v * v, r.zeros += v == 0;
    r.mean /= paths;
    r.sd = std::sqrt(std::max(0.0, sumSquares / paths - r.mean * r.mean));
    r.zeros /= paths;
    std::sort(values.begin(), values.end());
    r.median = values[size_t(paths / 2)];
    r.p99 = values[size_t(paths * 99 / 100)];
    double top = 0;
    for (size_t k = size_t(paths * 99 / 100); k < values.size(); ++k) top += values[k];
    r.top1Share = r.mean > 0 ? top / (r.mean * paths) : 0;
    r.raysPerPath = double(stats.closest + stats.shadow) / paths;
    return r;
}

// A whole number from the command line, or an error that names the argument.
int wholeNumber(const char* text, const char* what, int least) {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || n < least || n > 100000000)
        throw std::runtime_error(std::string(what) + " must be a whole number from " + std::to_string(least) + ", not \"" +
                                 text + "\"");
    return int(n);
}

// Each kind and bounce count's mean, spread per path and share of the variance.
void printSources(const std::vector<Parts>& parts) {
    const double n = double(parts.size());
    std::vector<double> whole;
    double mean = 0, squares = 0;
    for (const Parts& p : parts) {
        double sum = 0;
        for (const auto& kind : p)
            for (double x : kind) sum += x;
        whole.push_back(sum), mean += sum, squares += sum * sum;
    }
    mean /= n;
    const double variance = squares / n - mean * mean;
    const char* kinds[LightBudget::kKinds] = {"sun", "sky", "luminaires"};
    std::printf("\n%-11s %8s %9s %11s %13s\n", "light", "bounces", "mean", "sd per path", "variance share");
    for (int k = 0; k < LightBudget::kKinds; ++k)
        for (int b = 0; b < LightBudget::kBounces; ++b) {
            double m = 0, m2 = 0, cross = 0;
            for (size_t i = 0; i < parts.size(); ++i) {
                const double x = parts[i][size_t(k)][size_t(b)];
                m += x, m2 += x * x, cross += x * whole[i];
            }
            m /= n;
            if (m2 == 0) continue;
            const double sd = std::sqrt(std::max(0.0, m2 / n - m * m)), covariance = cross / n - m * mean;
            const std::string bounces = b == LightBudget::kBounces - 1 ? std::to_string(b) + "+" : std::to_string(b);
            std::printf("%-11s %8s %9.2f %11.2f %12.1f%%\n", kinds[k], bounces.c_str(), m, sd,
                        variance > 0 ? 100 * covariance / variance : 0.0);
        }
}

}  // namespace

int main(int argc, char** argv) try {
    if (argc < 5) {
        std::fprintf(stderr, "usage: %s SCENE LAYOUT SAMPLER ITEM [PATHS] [--sun-patches] [--sources] [--light-roulette A]\n", argv[0]);
        return 2;
    }
    const Scene scene = io::loadScene(argv[1]);
    const Layout layout = io::readLayout(argv[2], scene);
    int samplerIndex = -1;
    for (size_t k = 0; k < scene.samplers.size(); ++k)
        if (scene.samplers[k].name == argv[3]) samplerIndex = int(k);
    if (samplerIndex < 0) throw std::runtime_error(std::string("no sampler named ") + argv[3]);
    const int item = wholeNumber(argv[4], "ITEM", 0);
    int paths = 20000;
    bool sunPatches = false, sources = false;
    double lightRoulette = 0;
    for (int a = 5; a < argc; ++a) {
        if (std::strcmp(argv[a], "--sun-patches") == 0) sunPatches = true;
        else if (std::strcmp(argv[a], "--light-roulette") == 0 && a + 1 < argc) {
            char* end = nullptr;
            lightRoulette = std::strtod(argv[++a], &end);
            if (*end != '\0' || !(lightRoulette >= 0) || !std::isfinite(lightRoulette))
                throw std::runtime_error(std::string("--light-roulette: expected a finite number >= 0, got ") + argv[a]);
        }
        else if (std::strcmp(argv[a], "--sources") == 0) sources = true;
        else if (a == 5 && argv[a][0] != '-') paths = wholeNumber(argv[a], "PATHS", 100);
        else throw std::runtime_error(std::string("unknown argument \"") + argv[a] + "\"");
    }
    std::optional<DaylightEnvironment> daylight;
    if (scene.daylight) daylight = buildDaylight(*scene.daylight, scene.site);
    const EmbreeScene rt(scene, layout);
    // Traced as the rows below trace: it places the sampler and runs the floors' pilot.
    PathTracerOptions tracing;
    tracing.sunPatches = sunPatches;
    const PathTracer tracer(rt, daylight ? &*daylight : nullptr, tracing);
    const auto sampler = placeSampler(scene.samplers[size_t(samplerIndex)], tracer);
    if (item < 0 || item >= sampler->items()) throw std::runtime_error("ITEM " + std::to_string(item) + " is past the sampler's " + std::to_string(sampler->items()) + " items");
    const double lightFloor = lightSampleFloors(tracer, lightRoulette, scene.optimizer.seed)[size_t(samplerIndex)];
    std::printf("%s, item %d, %d paths, sunlit patches %s, light samples' floor %g (%s)\n", argv[3], item, paths,
                sunPatches ? "on" : "off", lightFloor, scene.samplers[size_t(samplerIndex)].type->unit());
    std::printf("%-16s %9s %11s %9s %7s %8s %9s %12s %10s\n", "surface vertices", "mean", "sd per path", "sd / mean",
                "zeros", "median", "99th pct", "top 1% share", "rays/path");
    std::vector<Parts> parts;
    for (int depth : {1, 2, 3, 4, 6, 256}) {
        const Row r = trace(scene, rt, daylight ? &*daylight : nullptr, *sampler, item, paths, depth, sunPatches, lightFloor,
                            sources && depth == 256 ? &parts : nullptr);
        std::printf("%-16s %9.1f %11.1f %9.2f %6.0f%% %8.1f %9.1f %11.0f%% %10.1f\n",
                    depth == 256 ? "all" : std::to_string(depth).c_str(), r.mean, r.sd, r.mean > 0 ? r.sd / r.mean : 0,
                    100 * r.zeros, r.median, r.p99, 100 * r.top1Share, r.raysPerPath);
    }
    if (sources) printSources(parts);
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "luxplan_path_anatomy: %s\n", e.what());
    return 1;
}
