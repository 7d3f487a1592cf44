// Subcommands of the luxplan executable; each lives in its own cmd_*.cpp and
// registers its options and callback on the CLI11 app. The commands that trace light
// bind their --threads to main()'s `threads`, which limits TBB once for the whole run.
#pragma once

#include <CLI/CLI.hpp>

#include <luxplan/api/scene.h>
#include <luxplan/core/error.h>
#include <luxplan/scene/scene.h>

namespace luxplan::cli {

// Runs a command on the scene file `scene` (api::namingScene): an exception that names
// no file is reported as SCENE: /: message; CLI11's exits pass unchanged too.
template <class Fn>
void namingScene(const std::string& scene, Fn&& fn) {
    try {
        api::namingScene(scene, std::forward<Fn>(fn),
                         [](const std::exception& e) { return dynamic_cast<const CLI::Error*>(&e) != nullptr; });
    } catch (const api::UsageError& e) {
        throw CLI::ValidationError(e.option(), e.problem());
    }
}

// Valid, but maybe not what was meant (checks/scene_warnings.h): each on stderr as
// FILE: /json/path: warning: ..., never failing. validate, measure and optimize say them.
void printSceneWarnings(const Scene& scene);
// A warning on stderr where `paths` per point (from --paths, or else setting `key`,
// api::fewPathsWarning) leave the samplers without a standard error and a
// directional sampler without its cross-fitted choice: fewer than 2.
void warnFewPaths(const Scene& scene, int paths, bool fromOption, const std::string& key);
// A warning on stderr before a large measurement (optimizer/progress_line.h:
// points x paths per point above kLargeMeasurementPaths): "FILE: warning: <what> N
// points (S samplers) x P paths per point = X paths, ...".
void warnLargeMeasurement(const Scene& scene, int pathsPerPoint, const std::string& what);

void registerValidateCommand(CLI::App& app);
void registerInfoCommand(CLI::App& app);
void registerMeasureCommand(CLI::App& app, int& threads);
void registerOptimizeCommand(CLI::App& app, int& threads);
void registerSunCommand(CLI::App& app);
void registerRenderCommand(CLI::App& app, int& threads);
void registerReportCommand(CLI::App& app, int& threads);
// `luxplan settings`: every --set key (the scene file's "optimizer" keys) with its type, default and meaning.
void registerSettingsCommand(CLI::App& app);

}  // namespace luxplan::cli
