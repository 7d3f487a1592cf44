// Optimizer outputs: report.json (costs, per-constraint penalties, samplers, move
// statistics, settings), trace.csv (iteration, current, best) and layout.json.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include <luxplan/optimizer/optimizer.h>

namespace luxplan {

// The run's settings as the scene file's "optimizer" object holds them, every key of
// the settings table with the value the run used (io::settingsJson): report.json's
// "settings". The table lives with the scene reader, above this module.
using RunSettings = nlohmann::json;

// report.json as text (see docs/optimizer.md for every key).
std::string reportJson(const Scene& scene, const OptimizerResult& result, const RunSettings& settings);

// What a designer counts: lighting goals met (a sampler whose value and every statistics
// goal lie in their targets in the result's measurement) and rules held (every
// relational constraint at penalty 0, and the overlap rule at 0; none of them held
// when a hard limit is passed). A rule at a penalty above 0 is not held, however small.
struct GoalCount {
    int lightingMet = 0, lighting = 0, rulesHeld = 0, rules = 0;
    int lightingWithinNoise = 0;  // not met, but past a bound by less than a standard error (Reach::WithinNoise)
    // "10 of 12 lighting goals met (1 more at its bound within noise), 21 of 21 rules held"
    std::string sentence() const;
    bool all() const { return lightingMet == lighting && rulesHeld == rules; }
};
GoalCount countGoals(const Scene& scene, const OptimizerResult& result);
// The file of suggestion `index` (0-based) in the output folder: "suggestions/1.json", ...
std::string suggestionFile(size_t index);

void writeReport(const std::filesystem::path& file, const Scene& scene, const OptimizerResult& result,
                 const RunSettings& settings);

// trace.csv: "iteration,current,best,feasible,temperature,acceptance" (the test's
// temperature, 0 in the polish; the share of proposals accepted since the row before); best is empty while no feasible
// layout has been found.
void writeTrace(const std::filesystem::path& file, const OptimizerResult& result);

// report.json and trace.csv in `folder` (created); the layout itself is written by
// the caller (io::writeLayout), in the scene file's hierarchy.
void writeOptimizerOutputs(const std::filesystem::path& folder, const Scene& scene, const OptimizerResult& result,
                           const RunSettings& settings);

}  // namespace luxplan
