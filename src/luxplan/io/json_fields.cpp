#include <luxplan/io/json_fields.h>

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace luxplan::io {

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

std::string formatNumber(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string Range::describe() const {
    std::string u = *unit ? std::string(" ") + unit : "";
    if (std::isinf(hi)) return std::string(loOpen ? "> " : ">= ") + formatNumber(lo) + u;
    if (std::isinf(lo)) return std::string(hiOpen ? "< " : "<= ") + formatNumber(hi) + u;
    return std::string(loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) + (hiOpen ? ")" : "]") + u;
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

Fields::Fields(DiagnosticSink& sink, const Json& value, std::string path, std::vector<std::string> allowedKeys,
               const char* what)
    : sink_(sink), value_(&value), path_(std::move(path)) {
    if (!value.is_object()) {
        sink_.error(path_, std::string("expected ") + what + ", got " + typeName(value));
        return;
    }
    valid_ = true;
    for (const auto& [key, _] : value.items()) {
        if (std::find(allowedKeys.begin(), allowedKeys.end(), key) != allowedKeys.end()) continue;
        std::string known;
        for (size_t i = 0; i < allowedKeys.size(); ++i) known += (i ? ", " : "") + allowedKeys[i];
        sink_.error(pointer(path_, key), "unknown key \"" + key + "\" (known keys: " + known + ")");
    }
}

bool Fields::has(const char* key) const { return valid_ && value_->contains(key); }
const Json& Fields::get(const char* key) const { return (*value_)[key]; }
void Fields::missing(const char* key) const { sink_.error(path_, std::string("missing required key \"") + key + "\""); }

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
    return int(d);
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

}  // namespace luxplan::io
