// Subcommands of the luxplan executable; each lives in its own cmd_*.cpp and
// registers its options and callback on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

namespace luxplan::cli {

void registerValidateCommand(CLI::App& app);
void registerInfoCommand(CLI::App& app);
void registerMeasureCommand(CLI::App& app);
void registerOptimizeCommand(CLI::App& app);
void registerSunCommand(CLI::App& app);
void registerRenderCommand(CLI::App& app);
void registerReportCommand(CLI::App& app);

}  // namespace luxplan::cli
