// Subcommands of the luxplan executable; each lives in its own cmd_*.cpp and
// registers its options and callback on the CLI11 app. The commands that trace light
// bind their --threads to main()'s `threads`, which limits TBB once for the whole run.
#pragma once

#include <CLI/CLI.hpp>

namespace luxplan::cli {

void registerValidateCommand(CLI::App& app);
void registerInfoCommand(CLI::App& app);
void registerMeasureCommand(CLI::App& app, int& threads);
void registerOptimizeCommand(CLI::App& app, int& threads);
void registerSunCommand(CLI::App& app);
void registerRenderCommand(CLI::App& app, int& threads);
void registerReportCommand(CLI::App& app, int& threads);

}  // namespace luxplan::cli
