// The settings of a run: how light is traced (TracingSettings) and how the layout is
// searched (SearchSettings). The scene file's "optimizer" object and the command line's
// `--set KEY=VALUE` set them through one key table (io/settings_table.h), which is also
// their documentation (docs/scene-format.md, "optimizer"; `luxplan settings`). A new
// setting is one field here and one row there.
#pragma once

#include <cstdint>
#include <optional>

namespace luxplan {

// The default paths per point of the report and `measure` (report_paths_per_point):
// with it every point of a window-lit room under the CIE overcast sky reads within 1%
// of the converged value (3 times its seed-to-seed spread; docs/light-transport.md,
// "How accurate a default measurement is").
inline constexpr int kDefaultReportPaths = 32000;
// ... and of the search's independent measurements (selection_paths_per_point): dozens
// in a run, which choose among layouts and report nothing.
inline constexpr int kDefaultSelectionPaths = 1000;
// light_roulette's most: a floor that may add ten times a path's variance.
inline constexpr double kMostLightRoulette = 10;

// Where the room's sunlit patches are sampled at every surface a path meets: in the
// search, the report and the pictures (On), nowhere (Off), or everywhere but in the
// search (Report: there they cost more rays than their lower noise saves).
enum class SunPatchUse { On, Off, Report };

struct TracingSettings {
    int pathsPerPoint = 1000;        // per sampler point: `measure`'s default, and the search's when given
    int searchPathsPerPoint = 64;    // what the search uses: paths_per_point if the file gives it, else 64
    int reportPathsPerPoint = kDefaultReportPaths;  // the final layout's report, `measure` and `render`
    // The search's independent measurements: a zero cost's confirmation, the candidates'
    // re-measures (the report's count where the file sets that alone).
    int selectionPathsPerPoint = kDefaultSelectionPaths;
    bool lowDiscrepancy = true;      // sampling: scrambled Sobol first vertices (sobol), or PCG only (random)
    // Unset: the command's default (measure, render and report: On; optimize: Report).
    std::optional<SunPatchUse> sunPatches;
    bool exteriorSun = true;         // the sun and sky on sunlit surfaces outside, through the openings
    // The light samples' roulette floor, a share of each sampler's variance per path;
    // 0: every sample. Unset: the command's default (measure 0, optimize's search 0.2).
    std::optional<double> lightRoulette;
    bool adaptive = false;           // measure: each sampler stops once its penalty is settled
    bool fixedPaths = false;         // optimize: the search traces exactly its paths per point
    bool fullEvaluation = false;     // optimize: every path of every layout traced, no path cache
    bool checkCache = false;         // optimize: every path the cache reads back traced again and compared
    bool freshNoise = false;         // optimize: every estimate drawn anew, the penalty method's test

    // Whether a command whose default is `fallback` samples the sunlit patches in its
    // search (`search`) or in its report-accuracy measurements and pictures.
    bool samplesSunPatches(SunPatchUse fallback, bool search) const {
        const SunPatchUse p = sunPatches.value_or(fallback);
        return p == SunPatchUse::On || (p == SunPatchUse::Report && !search);
    }
};

struct SearchSettings {
    int iterations = 10000;
    uint64_t seed = 1;
    bool flat = false;               // hierarchy "flat": ignore groups (the paper's Figure 6 comparison)
    // "flat": true: measure reads the flattened scene (optimize's layout_flat.json);
    // optimize searches it, as hierarchy "flat".
    bool flatScene = false;
    int innerIterations = 0;         // object-level proposals per group-level one; 0: by degrees of freedom
    bool nested = false;             // object-level proposals move the members of the group just proposed
    bool cycle = false;              // ... move any group's members (the paper's plain cycle): nested off, said
    bool constantTemperature = false;
    double temperatureStart = 0.1, temperatureEnd = 0.001;
    bool startFromScene = false;     // start from the scene's placement instead of uniform draws
    double polishShare = 0.2;        // the run's last share: a zero-temperature polish of the best
    double restartShare = 0.3;       // the schedule's cycles, each later one from the polished best
    bool guided = true;              // the guided move from the light map (optimizer/light_map.h)
    int planIterations = 20000;      // the planned start's proposals on the light surrogate; 0: none
    int plans = 8;                   // the planned start's plans, the best by a traced look
    int suggestions = 0;             // distinct layouts written beside the result (optimize --suggestions)
    double margin = 2;               // the search's margin inside every lighting band, in standard errors
    bool adaptiveShare = true;       // the object level's share by what the levels' proposals yield
    bool noiseBlind = false;         // the paper's plain Metropolis test, the temperature free to fall below the noise
    bool singleTest = false;         // one Metropolis test after lighting every proposal (no delayed acceptance)
    int snapshots = 0;               // snapshots.json: the best layout at this many checkpoints; 0: none
};

// Both, as the scene holds them (Scene::optimizer).
struct OptimizerSettings : SearchSettings, TracingSettings {};

}  // namespace luxplan
