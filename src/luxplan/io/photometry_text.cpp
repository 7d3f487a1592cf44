#include <luxplan/io/photometry_text.h>

#include <cmath>
#include <cstdlib>

namespace luxplan::io::photometry {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = end + 1;
    }
    // A final newline ends the last line; it starts none.
    if (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

std::string_view trim(std::string_view s) {
    const char* ws = " \t\r\n\f\v";
    size_t a = s.find_first_not_of(ws);
    if (a == std::string_view::npos) return {};
    return s.substr(a, s.find_last_not_of(ws) - a + 1);
}

std::optional<double> parseNumber(std::string_view s) {
    std::string t(trim(s));
    if (t.empty()) return std::nullopt;
    for (char& c : t)
        if (c == ',') c = '.';
    char* end = nullptr;
    double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::string quote(std::string_view s) {
    std::string out = "\"";
    size_t n = 0;
    for (unsigned char c : s) {
        if (++n > 40) {
            out += "...";
            break;
        }
        if (c < 0x80) {
            out += char(c);
        } else {
            out += char(0xC0 | (c >> 6));
            out += char(0x80 | (c & 0x3F));
        }
    }
    return out + "\"";
}

}  // namespace luxplan::io::photometry
