// One fuzz input: a folder of files (a scene, maybe a layout, a mesh, a photometric
// file) with what the program must do with it, and the run of it in a child process.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace luxplan::fuzz {

// What a mutation class promises: the input must be refused (with a message naming
// the file and a JSON path or FILE:LINE), must be accepted, or may go either way (but
// must not crash, hang, exhaust memory or print a non-finite number).
enum class Expect { Refuse, Accept, Either };
const char* expectName(Expect e);
bool parseExpect(const std::string& s, Expect& e);

struct Case {
    std::string mutation;                      // the mutation class that made it
    Expect expect = Expect::Either;
    std::string scene = "scene.json";          // relative to the case's folder
    std::string layout;                        // "" for none
    bool measure = false;                      // also a tiny measure (a few paths) when accepted
    std::map<std::string, std::string> files;  // name -> bytes (the scene's among them)
};

// What became of one input.
enum class Outcome { Accepted, Refused, Crash, Hang, Memory, NonFinite, WrongAccept, WrongRefuse, Unnamed };
const char* outcomeName(Outcome o);
inline bool isFailure(Outcome o) { return o != Outcome::Accepted && o != Outcome::Refused; }

struct Result {
    Outcome outcome = Outcome::Accepted;
    std::string detail;  // the refusal's message, the signal, ...
};

struct Bounds {
    double seconds = 10;              // CPU time per input (a busy machine does not make a hang)
    double wallSeconds = 60;          // wall clock per input (an input that blocks)
    std::uint64_t memoryBytes = 3ull << 30;  // address space per input (not under ASan)
};

// Writes the case's files and its expect.txt into `dir` (created).
void writeCase(const Case& c, const std::filesystem::path& dir);
// Reads a folder written by writeCase (a kept regression).
Case readCase(const std::filesystem::path& dir);

// Runs the loader (and validate's checks, and maybe a measure) on the case in `dir`,
// in a forked child under the bounds, and judges the result against c.expect.
Result runCase(const Case& c, const std::filesystem::path& dir, const Bounds& bounds);

// The layout.json of a scene's initial placement, made in a child process (so that
// the fuzzer's own process never starts TBB's threads before it forks); "" on error.
std::string layoutFor(const std::filesystem::path& scene);

}  // namespace luxplan::fuzz
