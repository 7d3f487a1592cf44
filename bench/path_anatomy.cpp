// Where one sampler item's light comes from, path by path: the distribution of its
// per-path estimates (mean, spread, zeros, the share of the brightest 1%) and how the
// mean grows as paths may bounce more (each path cut after 1, 2, 3, ... surface
// vertices, the same random numbers, so each row adds the light of one more bounce).
//
//   luxplan_path_anatomy SCENE LAYOUT SAMPLER ITEM [PATHS] [--sun-patches]
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

Row trace(const Scene& scene, const EmbreeScene& rt, const DaylightEnvironment* daylight, const PlacedSampler& sampler,
          int item, int paths, int maxDepth, bool sunPatches) {
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
        sampler.sample(tracer, item, samples, stats, c);
        double own = 0;  // what the path adds to its item's estimate
        for (int k = 0; k < c.size(); ++k)
            if (c.itemAt(k) == item) own += c.valueAt(k);
        values.push_back(sampler.sharesPaths() ? own / sampler.items() : own);
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

}  // namespace

int main(int argc, char** argv) try {
    if (argc < 5) {
        std::fprintf(stderr, "usage: %s SCENE LAYOUT SAMPLER ITEM [PATHS] [--sun-patches]\n", argv[0]);
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
    bool sunPatches = false;
    for (int a = 5; a < argc; ++a) {
        if (std::strcmp(argv[a], "--sun-patches") == 0) sunPatches = true;
        else if (a == 5 && argv[a][0] != '-') paths = wholeNumber(argv[a], "PATHS", 100);
        else throw std::runtime_error(std::string("unknown argument \"") + argv[a] + "\"");
    }
    std::optional<DaylightEnvironment> daylight;
    if (scene.daylight) daylight = buildDaylight(*scene.daylight, scene.site);
    const EmbreeScene rt(scene, layout);
    const auto sampler = placeSampler(scene.samplers[size_t(samplerIndex)], rt);
    if (item < 0 || item >= sampler->items()) throw std::runtime_error("ITEM " + std::to_string(item) + " is past the sampler's " + std::to_string(sampler->items()) + " items");
    std::printf("%s, item %d, %d paths, sunlit patches %s (%s)\n", argv[3], item, paths, sunPatches ? "on" : "off",
                scene.samplers[size_t(samplerIndex)].type->unit());
    std::printf("%-16s %9s %11s %9s %7s %8s %9s %12s %10s\n", "surface vertices", "mean", "sd per path", "sd / mean",
                "zeros", "median", "99th pct", "top 1% share", "rays/path");
    for (int depth : {1, 2, 3, 4, 6, 256}) {
        const Row r = trace(scene, rt, daylight ? &*daylight : nullptr, *sampler, item, paths, depth, sunPatches);
        std::printf("%-16s %9.1f %11.1f %9.2f %6.0f%% %8.1f %9.1f %11.0f%% %10.1f\n",
                    depth == 256 ? "all" : std::to_string(depth).c_str(), r.mean, r.sd, r.mean > 0 ? r.sd / r.mean : 0,
                    100 * r.zeros, r.median, r.p99, 100 * r.top1Share, r.raysPerPath);
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "luxplan_path_anatomy: %s\n", e.what());
    return 1;
}
