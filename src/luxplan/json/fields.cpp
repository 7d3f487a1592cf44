#include <luxplan/json/fields.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include <luxplan/core/names.h>

namespace luxplan::json {

std::string pointer(const std::string& base, const std::string& key) {
    std::string escaped;
    for (char c : key) {
        if (c == '~') escaped += "~0";
        else if (c == '/') escaped += "~1";
        else escaped += c;
    }
    return base + "/" + escaped;
}

std::string pointer(const std::string& base, size_t index) { return base + "/" + std::to_string(index); }

nlohmann::ordered_json numberOrNull(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr); }

std::string Range::describe() const {
    std::string u = *unit ? std::string(" ") + unit : "";
    if (std::isinf(hi)) return std::string(loOpen ? "> " : ">= ") + formatNumber(lo) + u;
    if (std::isinf(lo)) return std::string(hiOpen ? "< " : "<= ") + formatNumber(hi) + u;
    return std::string(loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) + (hiOpen ? ")" : "]") + u;
}

std::string Range::limitProblem(double v) const {
    if (withinLimit(v)) return "";
    std::string u = *unit ? std::string(" ") + unit : "";
    return "value " + formatNumber(v) + " exceeds the limit of " + (v < 0 ? "-" : "") + formatNumber(limit) + u;
}

std::string typeName(const Json& v) {
    switch (v.type()) {
        case Json::value_t::null: return "null";
        case Json::value_t::object: return "an object";
        case Json::value_t::array: return "an array";
        case Json::value_t::string: return "a string";
        case Json::value_t::boolean: return "a boolean";
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
        case Json::value_t::number_float: return "a number";
        default: return "an unsupported value";
    }
}

Fields::Fields(DiagnosticSink& sink, const Json& value, std::string path, const char* what)
    : sink_(sink), value_(&value), path_(std::move(path)) {
    if (!value.is_object()) {
        sink_.error(path_, std::string("expected ") + what + ", got " + typeName(value));
        return;
    }
    valid_ = true;
}

Fields::Fields(DiagnosticSink& sink, const Json& value, std::string path, std::map<std::string, std::string> keyPaths)
    : Fields(sink, value, std::move(path)) {
    keyPaths_ = std::move(keyPaths);
}

std::string Fields::at(const char* key) const {
    auto it = keyPaths_.find(key);
    return it != keyPaths_.end() ? it->second : pointer(path_, key);
}

void Fields::note(const char* key) const {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

void Fields::markRead(const char* key) const { read_.insert(key); }

bool Fields::has(const char* key) const {
    note(key);
    return valid_ && value_->contains(key);
}

const Json& Fields::get(const char* key) const {
    note(key);
    markRead(key);
    return (*value_)[key];
}

void Fields::missing(const char* key) const { sink_.error(path_, std::string("missing required key \"") + key + "\""); }

void Fields::finish(const std::string& kind, const std::vector<std::string>& family) const {
    if (!valid_) return;
    std::vector<std::string> all = unionKeys({known_, family});
    for (const auto& [key, _] : value_->items()) {
        if (read_.count(key)) continue;
        bool ofFamily = std::find(family.begin(), family.end(), key) != family.end();
        if (ofFamily && kind.empty()) continue;  // the kind is unknown: its keys cannot be judged
        bool known = std::find(all.begin(), all.end(), key) != all.end();
        if (known && !kind.empty())
            sink_.error(at(key.c_str()), "\"" + key + "\" does not apply to " + kind);
        else
            sink_.error(at(key.c_str()), "unknown key \"" + key + "\"" + didYouMean(key, all) + " (known keys: " +
                                                 listNames(all, ",") + ")");
    }
}

std::vector<std::string> unionKeys(const std::vector<std::vector<std::string>>& lists) {
    std::vector<std::string> out;
    for (const auto& list : lists)
        for (const auto& k : list)
            if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
    return out;
}

std::vector<std::string> probeKeys(const std::function<void(const Fields&)>& reader) {
    static const Json empty = Json::object();
    DiagnosticSink discard;
    Fields f(discard, empty, "");
    reader(f);
    return f.known();
}

static bool checkNumber(DiagnosticSink& sink, const Json& v, const std::string& path, const Range& range, double* out) {
    if (!v.is_number()) {
        sink.error(path, "expected a number, got " + typeName(v));
        return false;
    }
    double d = v.get<double>();
    if (!range.contains(d)) {
        sink.error(path, "value " + formatNumber(d) + " outside " + range.describe());
        return false;
    }
    if (!range.withinLimit(d)) {
        sink.error(path, range.limitProblem(d));
        return false;
    }
    *out = d;
    return true;
}

std::optional<double> Fields::number(const char* key, Range range, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    double d;
    if (!checkNumber(sink_, get(key), at(key), range, &d)) return std::nullopt;
    return d;
}

double Fields::number(const char* key, double fallback, Range range) const {
    return number(key, range, false).value_or(fallback);
}

std::optional<int> Fields::integer(const char* key, Range range, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    const Json& v = get(key);
    if (!v.is_number_integer() && !v.is_number_unsigned()) {
        if (v.is_number_float() && v.get<double>() == std::floor(v.get<double>()) && std::abs(v.get<double>()) < 2e9) {
            // 3.0 is an integer too
        } else {
            error(key, "expected an integer, got " + (v.is_number() ? formatNumber(v.get<double>()) : typeName(v)));
            return std::nullopt;
        }
    }
    double d = v.get<double>();
    if (!range.contains(d)) {
        error(key, "value " + formatNumber(d) + " outside " + range.describe());
        return std::nullopt;
    }
    // Checked before the conversion: a larger number would wrap.
    if (std::abs(d) > double(std::numeric_limits<int>::max())) {
        error(key, "value " + formatNumber(d) + " exceeds the limit of " + std::to_string(std::numeric_limits<int>::max()));
        return std::nullopt;
    }
    return int(d);
}

std::optional<uint64_t> Fields::unsignedInteger(const char* key, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    const Json& v = get(key);
    if (v.is_number_unsigned()) return v.get<uint64_t>();
    if (v.is_number_integer()) {
        error(key, "value " + std::to_string(v.get<int64_t>()) + " outside [0, 18446744073709551615]");
        return std::nullopt;
    }
    // 3.0 is a whole number too, as long as a double holds it exactly (below 2^53).
    if (v.is_number_float()) {
        double d = v.get<double>();
        if (d == std::floor(d) && d >= 0 && d <= 9007199254740992.0) return uint64_t(d);
        error(key, "expected a whole number in [0, 2^64 - 1], got " + formatNumber(d) +
                       (d == std::floor(d) && d > 0 ? " (write a number above 2^53 without a fraction or exponent)" : ""));
        return std::nullopt;
    }
    error(key, "expected an integer, got " + typeName(v));
    return std::nullopt;
}

std::optional<bool> Fields::boolean(const char* key, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    if (!get(key).is_boolean()) {
        error(key, "expected true or false, got " + typeName(get(key)));
        return std::nullopt;
    }
    return get(key).get<bool>();
}

std::optional<std::string> Fields::string(const char* key, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    if (!get(key).is_string()) {
        error(key, "expected a string, got " + typeName(get(key)));
        return std::nullopt;
    }
    return get(key).get<std::string>();
}

std::optional<std::vector<double>> readNumbers(DiagnosticSink& sink, const Json& v, const std::string& path,
                                               size_t length, Range range) {
    if (!v.is_array() || v.size() != length) {
        sink.error(path, "expected an array of " + std::to_string(length) + " numbers, got " +
                             (v.is_array() ? "an array of " + std::to_string(v.size()) : typeName(v)));
        return std::nullopt;
    }
    std::vector<double> out(length);
    bool ok = true;
    for (size_t i = 0; i < length; ++i) ok = checkNumber(sink, v[i], pointer(path, i), range, &out[i]) && ok;
    if (!ok) return std::nullopt;
    return out;
}

std::optional<std::vector<double>> Fields::numbers(const char* key, size_t length, Range range, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    return readNumbers(sink_, get(key), at(key), length, range);
}

std::optional<Vec2> Fields::vec2(const char* key, bool required, Range range) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    auto n = readNumbers(sink_, get(key), at(key), 2, range);
    if (!n) return std::nullopt;
    return Vec2((*n)[0], (*n)[1]);
}

std::optional<Vec3> Fields::vec3(const char* key, bool required, Range range) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    auto n = readNumbers(sink_, get(key), at(key), 3, range);
    if (!n) return std::nullopt;
    return Vec3((*n)[0], (*n)[1], (*n)[2]);
}

std::optional<Vec3> Fields::color(const char* key, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return std::nullopt;
    }
    const Json& v = get(key);
    Range unit = Range::closed(0, 1);
    if (v.is_number()) {
        double d;
        if (!checkNumber(sink_, v, at(key), unit, &d)) return std::nullopt;
        return Vec3(d, d, d);
    }
    if (v.is_array()) return vec3(key, required, unit);
    error(key, "expected a number or [r, g, b], got " + typeName(v));
    return std::nullopt;
}

std::optional<Vec3> Fields::direction(const char* key, bool required) const {
    auto v = vec3(key, required);
    if (!v) return std::nullopt;
    // Scaled first where its length could overflow: that of (1e300, 1e300, 0) is inf,
    // and the direction would normalize to zero. (Only there: results stay bit-identical.)
    double largest = std::max({std::abs(v->x), std::abs(v->y), std::abs(v->z)});
    if (largest > 1e150) *v = *v * (1 / largest);
    if (length(*v) < 1e-12) {
        error(key, "direction must not be the zero vector");
        return std::nullopt;
    }
    return normalize(*v);
}

const Json* Fields::array(const char* key, bool required) const {
    if (!has(key)) {
        if (required && valid_) missing(key);
        return nullptr;
    }
    if (!get(key).is_array()) {
        error(key, "expected an array, got " + typeName(get(key)));
        return nullptr;
    }
    return &get(key);
}

}  // namespace luxplan::json
