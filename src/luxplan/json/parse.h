// Reading a JSON input file safely: only a regular file within a size limit, parsed
// with duplicate keys, nesting depth and number overflow reported with their JSON
// path (syntax errors with line and column), never as a library's bare exception.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include <luxplan/json/fields.h>

namespace luxplan::json {

// The file's bytes, or none after reporting (at "/") why it cannot be read: it does
// not exist, is not a regular file (a folder, FIFO or device), or is larger than
// `maxBytes`. A FIFO or device is never opened.
std::optional<std::string> readInputFile(DiagnosticSink& sink, const std::filesystem::path& file,
                                         std::uintmax_t maxBytes);

// Parses `text`; reports duplicate keys, nesting deeper than limits::kMaxJsonDepth and
// numbers beyond a double (1e400) with their JSON path. None on any problem but a
// duplicate key.
std::optional<Json> parseJson(const std::string& text, DiagnosticSink& sink);

}  // namespace luxplan::json
