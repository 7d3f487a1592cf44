// The options measure, optimize, render and report share, registered once: the scene,
// --layout (where it applies), --paths, --seed, --threads and --set KEY=VALUE (any
// setting of the scene file's "optimizer" object: io/settings_table.h), -q (where it
// applies). The default --help shows what a designer uses; --help-all shows the
// advanced options too and every --set key with its default.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <luxplan/io/settings_table.h>
#include <luxplan/scene/scene.h>

namespace luxplan::cli {

struct SharedArgs {
    std::string scene, layout;
    int paths = 0;  // 0: the scene's count for what the command measures
    std::optional<uint64_t> seed;
    std::vector<std::string> settings;  // --set KEY=VALUE, in the order given
    bool quiet = false;
};

enum SharedOption : unsigned { kLayoutOption = 1, kQuietOption = 2 };

// Registers the shared options on `cmd` (`which`: kLayoutOption | kQuietOption);
// `pathsHelp` says which count --paths sets for this command.
void addSharedOptions(CLI::App* cmd, SharedArgs& args, int& threads, const std::string& pathsHelp, unsigned which);
// The group of options the default --help leaves out (--help-all shows them).
std::string advancedGroup();
// Whether this run asked for --help-all (main() turns it into --help).
void setHelpAll(bool all);
// Loads the scene with the --set settings over its "optimizer" object; a --set that
// is wrong on its own (a malformed value, keys that exclude each other) is a usage
// error (CLI::ValidationError: exit 2).
Scene loadSceneWithSettings(const SharedArgs& args);

}  // namespace luxplan::cli
