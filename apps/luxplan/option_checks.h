// Checks of command-line values that say what was expected: CLI11's own number checks
// print their range with 1.8e308 written out in full, and its int64 options saturate a
// larger seed silently.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include <CLI/CLI.hpp>

namespace luxplan::cli {

// A whole number in [least, 2^31 - 1] (--paths, --iterations, --threads, ...).
CLI::Validator wholeNumber(int least);
// A finite number > 0 (--cell, ...).
CLI::Validator positiveNumber();
// --suggestions' most: each is measured again at the report's accuracy, and a designer
// reads a handful.
constexpr int kMostSuggestions = 50;
// --seed: a whole number in [0, 2^64 - 1], read exactly; unset when not given.
CLI::Option* addSeedOption(CLI::App* cmd, std::optional<uint64_t>& seed);

}  // namespace luxplan::cli
