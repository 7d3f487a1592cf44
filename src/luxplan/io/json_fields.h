// Validated reading of JSON objects: every problem becomes a Diagnostic with
// its JSON Pointer, and keys an object does not know are reported, not ignored.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <luxplan/core/error.h>
#include <luxplan/core/math.h>

namespace luxplan::io {

using Json = nlohmann::json;

// Collects diagnostics for one file.
struct DiagnosticSink {
    std::string file;
    std::vector<Diagnostic> diagnostics;
    void error(const std::string& path, std::string message) { diagnostics.push_back({file, path, std::move(message)}); }
    size_t count() const { return diagnostics.size(); }
};

// Appends a key or index to a JSON Pointer, escaping '~' and '/' (RFC 6901).
std::string pointer(const std::string& base, const std::string& key);
std::string pointer(const std::string& base, size_t index);

// An inclusive or exclusive numeric range, with the unit for messages.
struct Range {
    double lo = -kInf, hi = kInf;
    bool loOpen = false, hiOpen = false;
    const char* unit = "";
    static Range atLeast(double lo, const char* unit = "") { return {lo, kInf, false, false, unit}; }
    static Range positive(const char* unit = "") { return {0, kInf, true, false, unit}; }
    static Range closed(double lo, double hi, const char* unit = "") { return {lo, hi, false, false, unit}; }
    bool contains(double v) const {
        return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    std::string describe() const;
};

// One JSON object being read. Construction checks it is an object and reports
// unknown keys; the accessors report wrong types, missing keys and bad ranges.
class Fields {
public:
    Fields(DiagnosticSink& sink, const Json& value, std::string path, std::vector<std::string> allowedKeys,
           const char* what = "an object");

    bool valid() const { return valid_; }
    bool has(const char* key) const;
    const Json& get(const char* key) const;  // only when has(key)
    std::string at(const char* key) const { return pointer(path_, key); }
    const std::string& path() const { return path_; }
    void error(const char* key, std::string message) const { sink_.error(at(key), std::move(message)); }
    void missing(const char* key) const;

    std::optional<double> number(const char* key, Range range = {}, bool required = false) const;
    double number(const char* key, double fallback, Range range = {}) const;
    std::optional<int> integer(const char* key, Range range = {}, bool required = false) const;
    std::optional<bool> boolean(const char* key, bool required = false) const;
    std::optional<std::string> string(const char* key, bool required = false) const;
    std::optional<Vec2> vec2(const char* key, bool required = false, Range range = {}) const;
    std::optional<Vec3> vec3(const char* key, bool required = false, Range range = {}) const;
    // A number or [r, g, b], each in [0, 1].
    std::optional<Vec3> color(const char* key, bool required = false) const;
    // A direction: three numbers, not all zero; returned normalized.
    std::optional<Vec3> direction(const char* key, bool required = false) const;
    // An array (reports a type error otherwise); nullptr if absent or invalid.
    const Json* array(const char* key, bool required = false) const;

private:
    DiagnosticSink& sink_;
    const Json* value_;
    std::string path_;
    bool valid_ = false;
};

// Reads numbers from a JSON array of fixed length at `path`.
std::optional<std::vector<double>> readNumbers(DiagnosticSink& sink, const Json& value, const std::string& path,
                                               size_t length, Range range = {});

// Human-readable JSON type name ("a number", "a string", ...).
std::string typeName(const Json& value);
std::string formatNumber(double v);

}  // namespace luxplan::io
