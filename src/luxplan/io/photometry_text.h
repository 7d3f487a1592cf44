// What both photometric readers need from a text file: its lines (CR LF or LF),
// numbers that may use a decimal comma, and errors that name FILE:LINE.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <luxplan/core/error.h>

namespace luxplan::io::photometry {

std::vector<std::string> splitLines(const std::string& text);
std::string_view trim(std::string_view s);
// The whole of `s` as a number (a ',' read as '.'), or none.
std::optional<double> parseNumber(std::string_view s);
// A file's bytes for a message: ISO-8859-1 (EULUMDAT's encoding, and what old IES
// files use) to UTF-8, shortened to 40 characters.
std::string quote(std::string_view s);

[[noreturn]] inline void fail(const std::string& name, int line, const std::string& message) {
    throw IoError(name + ":" + std::to_string(line) + ": " + message);
}

}  // namespace luxplan::io::photometry
