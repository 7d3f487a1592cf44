#include "option_checks.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace luxplan::cli {
namespace {

// The whole text as an unsigned 64-bit number, or why not.
std::string parseWhole(const std::string& text, uint64_t& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc::result_out_of_range) return "expected a whole number up to 18446744073709551615, got " + text;
    if (ec != std::errc() || ptr != end || text.empty()) return "expected a whole number, got " + text;
    return "";
}

}  // namespace

CLI::Validator wholeNumber(int least) {
    return CLI::Validator(
        [least](std::string& text) -> std::string {
            uint64_t v = 0;
            std::string why = parseWhole(text, v);
            if (!why.empty()) return why + " (at least " + std::to_string(least) + ")";
            if (v < uint64_t(least)) return "must be at least " + std::to_string(least) + ", got " + text;
            if (v > uint64_t(std::numeric_limits<int>::max()))
                return "must be at most " + std::to_string(std::numeric_limits<int>::max()) + ", got " + text;
            return "";
        },
        "INT >= " + std::to_string(least));
}

CLI::Validator positiveNumber() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double v = 0;
            const char* end = text.data() + text.size();
            auto [ptr, ec] = std::from_chars(text.data(), end, v);
            if (ec != std::errc() || ptr != end || text.empty()) return "expected a number, got " + text;
            if (!std::isfinite(v) || v <= 0) return "must be a finite number > 0, got " + text;
            return "";
        },
        "NUMBER > 0");
}

CLI::Option* addSeedOption(CLI::App* cmd, std::optional<uint64_t>& seed) {
    return cmd
        ->add_option_function<std::string>(
            "--seed",
            [&seed](const std::string& text) {
                uint64_t v = 0;
                std::string why = parseWhole(text, v);
                if (!why.empty()) throw CLI::ValidationError("--seed", why);
                seed = v;
            },
            "Random seed, a whole number in [0, 2^64 - 1] (default: optimizer.seed)")
        ->type_name("UINT64");
}

}  // namespace luxplan::cli
