#include <luxplan/json/parse.h>

#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include <luxplan/core/limits.h>

namespace luxplan::json {
namespace {

// Where the parser is: one frame per open array or object.
struct ParseState {
    struct Frame {
        bool isArray = false;
        size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    std::vector<Frame> stack;
    std::vector<std::string> duplicates;  // JSON Pointers of repeated keys

    // The path of the innermost open container (frames but the last).
    std::string pathOfTop() const { return pathOf(stack.size() > 0 ? stack.size() - 1 : 0); }
    // The path of the value being read in the innermost container.
    std::string pathOfValue() const { return pathOf(stack.size()); }
    std::string pathOf(size_t frames) const {
        std::string p;
        for (size_t i = 0; i < frames; ++i) p = stack[i].isArray ? pointer(p, stack[i].index) : pointer(p, stack[i].key);
        return p;
    }
    void elementDone() {
        if (!stack.empty() && stack.back().isArray) ++stack.back().index;
    }
};

// Thrown from the parser's callback to stop at once.
struct TooDeep {
    std::string path;
};

std::pair<size_t, size_t> lineColumn(const std::string& text, size_t byte) {
    size_t line = 1, col = 1;
    for (size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, col = 1;
        else ++col;
    }
    return {line, col};
}

// nlohmann's message without its "[json.exception.xxx.nnn] " prefix.
std::string detailOf(const std::string& what) {
    auto bracket = what.find("] ");
    return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

}  // namespace

std::optional<std::string> readInputFile(DiagnosticSink& sink, const std::filesystem::path& file,
                                         std::uintmax_t maxBytes) {
    std::error_code ec;
    auto status = std::filesystem::status(file, ec);
    if (ec || !std::filesystem::exists(status)) {
        sink.error("", "cannot open the file");
        return std::nullopt;
    }
    if (!std::filesystem::is_regular_file(status)) {
        sink.error("", "not a regular file (a folder, FIFO or device cannot be read)");
        return std::nullopt;
    }
    auto size = std::filesystem::file_size(file, ec);
    if (!ec && size > maxBytes) {
        sink.error("", "file of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(maxBytes) +
                           " bytes");
        return std::nullopt;
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        sink.error("", "cannot open the file");
        return std::nullopt;
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

std::optional<Json> parseJson(const std::string& text, DiagnosticSink& sink) {
    ParseState state;
    auto callback = [&](int, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                // Checked before the container is built: a deep nesting is refused at
                // its first level too many, in time and memory linear in that depth.
                if (state.stack.size() >= size_t(limits::kMaxJsonDepth)) throw TooDeep{state.pathOfValue()};
                state.stack.emplace_back();
                state.stack.back().isArray = event == Json::parse_event_t::array_start;
                break;
            case Json::parse_event_t::key: {
                auto& top = state.stack.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second) state.duplicates.push_back(pointer(state.pathOfTop(), top.key));
                break;
            }
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                state.stack.pop_back();
                state.elementDone();
                break;
            case Json::parse_event_t::value: state.elementDone(); break;
        }
        return true;
    };
    try {
        Json root = Json::parse(text, callback, /*allow_exceptions=*/true, /*ignore_comments=*/false);
        for (const auto& d : state.duplicates) sink.error(d, "duplicate key (JSON objects need unique keys)");
        return root;
    } catch (const TooDeep& e) {
        sink.error(e.path, "nesting depth " + std::to_string(limits::kMaxJsonDepth + 1) + " (arrays and objects inside "
                               "each other) exceeds the limit of " + std::to_string(limits::kMaxJsonDepth));
    } catch (const Json::parse_error& e) {
        auto [line, col] = lineColumn(text, e.byte > 0 ? e.byte - 1 : 0);
        std::string what = e.what();
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line ..., column ...: ".
        auto colon = what.find(": ", what.find("parse error"));
        std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
        sink.error("", "malformed JSON at line " + std::to_string(line) + ", column " + std::to_string(col) + ": " +
                           detail);
    } catch (const Json::out_of_range& e) {
        // A number beyond a double (1e400): the parser stops at the value it was reading.
        sink.error(state.pathOfValue(), detailOf(e.what()) + " (the largest number is about 1.8e308)");
    } catch (const Json::exception& e) {
        sink.error(state.pathOfValue(), "malformed JSON: " + detailOf(e.what()));
    }
    return std::nullopt;
}

}  // namespace luxplan::json
