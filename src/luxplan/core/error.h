// Typed errors thrown by library code; only apps/ catches them, prints each
// message on its own line and sets the exit code.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace luxplan {

// One problem with an input file: FILE: /json/path: message.
struct Diagnostic {
    std::string file;
    std::string jsonPath;  // JSON Pointer (RFC 6901), "" for the whole document
    std::string message;
    std::string str() const { return file + ": " + (jsonPath.empty() ? "/" : jsonPath) + ": " + message; }
};

// All problems found in one scene or layout file; what() lists them, one per line.
class SceneError : public std::runtime_error {
public:
    explicit SceneError(std::vector<Diagnostic> diags) : std::runtime_error(join(diags)), diagnostics_(std::move(diags)) {}
    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

private:
    static std::string join(const std::vector<Diagnostic>& d) {
        std::string s;
        for (size_t i = 0; i < d.size(); ++i) {
            if (i) s += '\n';
            s += d[i].str();
        }
        return s;
    }
    std::vector<Diagnostic> diagnostics_;
};

// A file that cannot be read or written (not a content problem).
class IoError : public std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A problem at a place inside a file that is not a scene (a mesh, a photometric
// file): what() is "FILE:LINE: message" (a text format), "FILE: /json/path: message"
// (a glTF) or "FILE: message" (the file as a whole).
class FileError : public IoError {
public:
    FileError(const std::string& file, const std::string& where, const std::string& message)
        : IoError(file + (where.empty() ? "" : where[0] == '/' ? ": " + where : ":" + where) + ": " + message) {}
};

// Embree reported an error through its device callback.
class EmbreeError : public std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace luxplan
