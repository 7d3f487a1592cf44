// Validated reading of JSON objects: every problem becomes a Diagnostic with its
// JSON Pointer. An object knows its keys from what its reader reads (pbrt's
// ReportUnused): each accessor marks its key, and finish() reports the rest as
// unknown, or as not applying to the kind being read when another kind of the same
// family reads it. No list of keys is kept by hand, so none can drift.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <luxplan/core/error.h>
#include <luxplan/core/format.h>
#include <luxplan/core/limits.h>
#include <luxplan/core/math.h>

namespace luxplan::json {

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

// A number for the files luxplan writes: infinite or undefined ones as null.
nlohmann::ordered_json numberOrNull(double v);

// An inclusive or exclusive numeric range, with the unit for messages.
struct Range {
    double lo = -kInf, hi = kInf;
    bool loOpen = false, hiOpen = false;
    const char* unit = "";
    // A bound on the magnitude from core/limits.h, reported apart from the range:
    // "value 1e+308 exceeds the limit of 100000 m".
    double limit = kInf;
    static Range atLeast(double lo, const char* unit = "") { return {lo, kInf, false, false, unit}; }
    static Range positive(const char* unit = "") { return {0, kInf, true, false, unit}; }
    static Range closed(double lo, double hi, const char* unit = "") { return {lo, hi, false, false, unit}; }
    bool contains(double v) const {
        return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
    }
    bool withinLimit(double v) const { return std::abs(v) <= limit; }
    Range limitedTo(double l) const {
        Range r = *this;
        r.limit = l;
        return r;
    }
    std::string describe() const;
    // "value 1e+308 exceeds the limit of 100000 m" (or "" when within the limit).
    std::string limitProblem(double v) const;
};

// The ranges of core/limits.h: every coordinate (positions, centres, corners) and
// every size (lengths, radii), in metres.
inline Range coordinateRange() { return Range{-kInf, kInf, false, false, "m"}.limitedTo(limits::kMaxCoordinate); }
// A signed length (a side vector's component).
inline Range signedLengthRange() { return Range{-kInf, kInf, false, false, "m"}.limitedTo(limits::kMaxLength); }
inline Range lengthRange() { return Range::positive("m").limitedTo(limits::kMaxLength); }
// A luminaire's side or radius.
inline Range luminaireSizeRange() { return Range::atLeast(limits::kMinLuminaireSize, "m").limitedTo(limits::kMaxLength); }
// A rotation about +z, degrees.
inline Range rotationRange() { return Range{-kInf, kInf, false, false, "deg"}.limitedTo(limits::kMaxRotationDeg); }
// A non-negative length (an offset along a wall, a sill).
inline Range offsetRange() { return Range::atLeast(0).limitedTo(limits::kMaxLength); }
// The factors of the cost C (limits.h): a weight, [0, kMaxWeight]; a sampler's or a
// goal's tolerance in its unit, [kMinTolerance, kMaxTargetValue]; a distance
// constraint's tolerance and its min and max, m.
inline Range weightRange() { return Range::atLeast(0).limitedTo(limits::kMaxWeight); }
inline Range toleranceRange(const char* unit = "") {
    return Range::atLeast(limits::kMinTolerance, unit).limitedTo(limits::kMaxTargetValue);
}
inline Range distanceToleranceRange() { return Range::atLeast(limits::kMinTolerance, "m").limitedTo(limits::kMaxLength); }
inline Range distanceBoundRange() { return Range::atLeast(0).limitedTo(limits::kMaxLength); }

// One JSON object being read. Construction checks it is an object; the accessors
// report wrong types, missing keys and bad ranges, and mark their key as read.
class Fields {
public:
    Fields(DiagnosticSink& sink, const Json& value, std::string path, const char* what = "an object");
    // An object merged from several places of the file (an entity made from a
    // template): `keyPaths` gives the JSON Pointer of each key that came from
    // elsewhere, so that its problems name the place it was written.
    Fields(DiagnosticSink& sink, const Json& value, std::string path, std::map<std::string, std::string> keyPaths);

    bool valid() const { return valid_; }
    bool has(const char* key) const;         // also makes `key` a known key of this object
    const Json& get(const char* key) const;  // only when has(key); marks it read
    std::string at(const char* key) const;
    const std::string& path() const { return path_; }
    void error(const char* key, std::string message) const { sink_.error(at(key), std::move(message)); }
    void error(std::string message) const { sink_.error(path_, std::move(message)); }  // the object itself
    void missing(const char* key) const;

    std::optional<double> number(const char* key, Range range = {}, bool required = false) const;
    double number(const char* key, double fallback, Range range = {}) const;
    std::optional<int> integer(const char* key, Range range = {}, bool required = false) const;
    // A whole number in [0, 2^64 - 1] (a seed): read as uint64, never through a double
    // or an int, so that distinct seeds stay distinct.
    std::optional<uint64_t> unsignedInteger(const char* key, bool required = false) const;
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
    // An array of `length` numbers, each in `range`.
    std::optional<std::vector<double>> numbers(const char* key, size_t length, Range range = {}, bool required = false) const;
    // Where problems go, for values below this object's keys.
    DiagnosticSink& sink() const { return sink_; }

    // Reports every key of the object that was not read: "\"k\" does not apply to
    // <kind>" when `family` (the keys of the other kinds) holds it, else "unknown key",
    // with the closest known key as a hint and the known keys listed. With no `kind`
    // (it was not recognised) the family's keys are not judged.
    void finish(const std::string& kind = "", const std::vector<std::string>& family = {}) const;
    // The keys this reader asked for, in the order it first asked.
    const std::vector<std::string>& known() const { return known_; }

private:
    DiagnosticSink& sink_;
    const Json* value_;
    std::string path_;
    std::map<std::string, std::string> keyPaths_;
    bool valid_ = false;
    mutable std::vector<std::string> known_;
    mutable std::set<std::string> read_;
    void note(const char* key) const;
    void markRead(const char* key) const;
};

// The keys `reader` asks for on an empty object: how a family of kinds learns every
// key its members read, for finish()'s "does not apply" messages.
std::vector<std::string> probeKeys(const std::function<void(const Fields&)>& reader);
// The union of several key lists, first occurrence first.
std::vector<std::string> unionKeys(const std::vector<std::vector<std::string>>& lists);

// Reads numbers from a JSON array of fixed length at `path`.
std::optional<std::vector<double>> readNumbers(DiagnosticSink& sink, const Json& value, const std::string& path,
                                               size_t length, Range range = {});

// Human-readable JSON type name ("a number", "a string", ...).
std::string typeName(const Json& value);
using luxplan::formatNumber;  // core/format.h

}  // namespace luxplan::json
