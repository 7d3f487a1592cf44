// The optimizer's lighting term measured by the path tracer: L(x) of Eq. 3 from every
// light sampler, for the layout the chain proposes.
#pragma once

#include <tbb/task_group.h>

#include <memory>
#include <optional>

#include <luxplan/annual/coefficient_cache.h>
#include <luxplan/incremental/checked_paths.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/optimizer/lighting.h>

namespace luxplan {

class PathTracedLighting : public LightingEvaluator {
public:
    // `daylight` may be null (night). Every evaluation uses the same seed: common random
    // numbers, so that the difference between two layouts' costs carries less noise
    // than either cost (the paths differ only where the geometry does).
    // A scene with annual goals (LightSamplerSpec::annual) gets its year (sceneYear) here:
    // each measurement adds the goals' shares of hours in range from daylight
    // coefficients at the same paths and seed, the search's kept between layouts
    // (CoefficientCache).
    // `searchTracing` for the search's evaluations, `reportTracing` for the independent
    // measurements and, in the search too, for the glare surveys (ugr and dgp samplers):
    // the sunlit patches, say, cost the search more than they save it, but lower the
    // report's error, and a survey's adaptive stops need them (measureSamplers).
    PathTracedLighting(const Scene& scene, const DaylightEnvironment* daylight, const MeasureOptions& options,
                       const PathTracerOptions& searchTracing = {}, const PathTracerOptions& reportTracing = {});
    ~PathTracedLighting() noexcept override;  // tbb::task_group's may throw: waited for first

    double evaluate(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out) override;
    // A fixed number of paths per point (setReportPaths or setSelectionPaths, by `use`;
    // unset, the search's), from `seed`, without the path cache: `measure --seed S
    // --paths N` gives the same.
    double measureIndependently(const Layout& layout, const std::vector<Transform>& world, LightingBreakdown* out,
                                uint64_t seed, IndependentUse use) override;
    void setReportPaths(int pathsPerPoint) { reportPaths_ = pathsPerPoint; }
    void setSelectionPaths(int pathsPerPoint) { selectionPaths_ = pathsPerPoint; }
    // The path cache takes in or drops the last evaluation's paths in the background:
    // the next evaluation waits for it only once its own layout is in the ray tracer,
    // whose rebuild runs on one thread, so that the two overlap.
    void commit() override;
    void revert() override;
    // Whether evaluations reuse the paths a move cannot change (on by default; the
    // numbers are the same either way, incremental/path_cache.h).
    void setIncremental(bool on) { incremental_ = on; }
    void setSearchMargin(double z) override { margin_ = z; }
    // Traced in a ray tracer of its own, the movable furniture far below the floor.
    std::vector<double> emptyRoomIlluminance(const std::vector<Vec3>& points, int paths, uint64_t seed) override;
    // Traced in a ray tracer of its own, on a copy of the scene that holds only those samplers.
    std::vector<std::vector<double>> aloneInEmptyRoom(int entity, const std::vector<Placement>& placements,
                                                      const std::vector<int>& samplers, int paths, uint64_t seed) override;
    // Every path the cache reads back is traced again and compared (CheckedPaths): a
    // diagnostic, at the cost of a full evaluation and more.
    void setCheckCache(bool on) { checkCache_ = on; }
    // The search's light samples' roulette (MeasureOptions::lightFloors): floors at
    // `share` times each sampler's variance per path over its mean, from a pilot at the
    // scene's own layout (lightSampleFloors), fixed for the run; 0: every sample traced.
    // The independent measurements trace every sample. Before the first evaluation.
    void setLightRoulette(double share);
    // What the cache check found so far (off: no check).
    const CacheCheck& cacheCheck() const { return check_; }
    // Each sampler's light floor in the search ("search_light_floor", when the roulette
    // is on) and the cache check ("path_cache_check", when on).
    LightingNotes notes() const override;
    // Fresh noise: every evaluation draws its own seed (from the seed and a count of
    // evaluations, so a run still repeats), without the path cache. The optimizer then
    // measures its current layout again before each test and uses the penalty method:
    // exact for the true costs, at twice the evaluations, none of them incremental.
    void setFreshNoise(bool on) { fresh_ = on; }
    bool drawsAnew() const override { return fresh_; }

    // The full measurement of the last evaluated layout (per-point values, errors).
    const MeasureResult& lastMeasurement() const { return last_; }
    uint64_t evaluations() const { return evaluations_; }
    // Paths over all evaluations: traced, and read from the path cache.
    uint64_t tracedPaths() const override { return tracedPaths_; }
    uint64_t reusedPaths() const { return reusedPaths_; }
    // The scene's year, when it has annual goals (else null).
    const DaylightCoefficients* year() const { return year_.get(); }
    RayStats rays() const { return rays_; }

private:
    // L of the measurement, its bands narrowed by `margin` standard errors (the search's).
    double measure(PathTracer& tracer, const std::vector<Transform>& world, const MeasureOptions& options,
                   PathSource* source, LightingBreakdown* out, PathTracer* glareTracer = nullptr, double margin = 0);
    void settleCache();  // waits for the cache's commit() or revert() under way
    // The annual goals' shares of hours in range, into last_ (no annual goal: nothing);
    // through the coefficient cache for the search's evaluations.
    void measureYear(const MeasureOptions& options, bool cached);

    const Scene& scene_;
    EmbreeScene rt_;
    PathTracer tracer_, reportTracer_;
    PathTracerOptions searchTracing_;
    bool hasGlareSurveys_ = false;  // a ugr or dgp sampler: the search traces it with reportTracer_
    MeasureOptions options_;
    int reportPaths_ = 0, selectionPaths_ = 0;  // 0: options_.pathsPerPoint
    PathCache cache_;
    CheckedPaths checked_{cache_};
    bool checkCache_ = false;
    tbb::task_group cacheUpdate_;  // commit() or revert() under way
    bool cacheUpdating_ = false;
    bool incremental_ = true;
    double margin_ = 0;  // the search's (setSearchMargin); independent measurements take none
    bool fresh_ = false;
    uint64_t freshDraws_ = 0;
    MeasureResult last_;
    uint64_t evaluations_ = 0;
    RayStats rays_;
    uint64_t tracedPaths_ = 0, reusedPaths_ = 0;
    CacheCheck check_;
    // The annual goals' (a scene without any: all null).
    std::unique_ptr<const DaylightCoefficients> year_;
    std::unique_ptr<PathTracer> yearTracer_;  // under year_'s basis sky, on rt_
    std::unique_ptr<CoefficientCache> yearCache_;
};

}  // namespace luxplan
