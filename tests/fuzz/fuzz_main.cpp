// luxplan_fuzz: structure-aware fuzzing of luxplan's input path (docs/robustness.md).
//
//   luxplan_fuzz [--count N] [--seconds S] [--seed S] [--jobs J] [--timeout CPU_S] [--wall S]
//                [--save DIR] [--source DIR] [--only INDEX] [--keep DIR] [-v]
//   luxplan_fuzz --replay DIR...     (each DIR a kept case, or a folder of them)
//
// Each input (mutations.h) runs the loader, layout reader and validate's checks (and
// sometimes a measure of 2 paths per point) in a forked child bounded in time and
// memory, and is judged against its mutation's promise. Failures are printed, saved
// under --save (to be kept in tests/fuzz/regressions/) and make the exit status 1.
#include <unistd.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_case.h"
#include "mutate.h"

using namespace luxplan::fuzz;

namespace {

struct Options {
    uint64_t count = 1000;
    double seconds = 0;  // 0: no time budget
    uint64_t seed = 1;
    int jobs = 1;
    double timeout = 10, wall = 60;
    std::string save, source = LUXPLAN_SOURCE_DIR, keep;
    int64_t only = -1;
    bool verbose = false;
    std::vector<std::string> replay;
};

std::filesystem::path tempRoot() {
    std::random_device rd;
    auto p = std::filesystem::temp_directory_path() / ("luxplan-fuzz-" + std::to_string(getpid()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(p);
    return p;
}

void say(const std::string& line) {
    const std::string s = line + "\n";
    (void)!::write(1, s.data(), s.size());
}

void copyCase(const Case& c, const std::filesystem::path& to) {
    std::error_code ec;
    std::filesystem::remove_all(to, ec);
    writeCase(c, to);
}

std::string oneLine(std::string s, size_t n = 400) {
    for (char& ch : s)
        if (ch == '\n') ch = '|';
    return s.size() > n ? s.substr(0, n) + "..." : s;
}

// Runs the cases of indices i = w, w + jobs, ... in this worker; writes the counts of
// each outcome to `countsFile`, "outcome mutation n" lines.
void worker(const Seeds& seeds, const Options& o, int w, const std::filesystem::path& root, const std::filesystem::path& countsFile) {
    const auto start = std::chrono::steady_clock::now();
    std::map<std::pair<std::string, std::string>, uint64_t> counts;
    Bounds bounds;
    bounds.seconds = o.timeout;
    bounds.wallSeconds = o.wall;
    const std::filesystem::path dir = root / ("w" + std::to_string(w));
    for (uint64_t i = uint64_t(w); i < o.count; i += uint64_t(o.jobs)) {
        if (o.only >= 0 && i != uint64_t(o.only)) continue;
        if (o.seconds > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > o.seconds) break;
        Case c;
        try {
            c = makeCase(seeds, o.seed, i);
        } catch (const std::exception& e) {
            // A mutation the harness could not make: its own bug, never the program's.
            say("skip #" + std::to_string(i) + ": the harness could not make this input: " + e.what());
            ++counts[{"skipped", "harness"}];
            continue;
        }
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
        writeCase(c, dir);
        Result r = runCase(c, dir, bounds);
        ++counts[{outcomeName(r.outcome), c.mutation}];
        if (o.verbose || isFailure(r.outcome))
            say(std::string(isFailure(r.outcome) ? "FAIL " : "ok   ") + outcomeName(r.outcome) + " #" + std::to_string(i) + " " +
                c.mutation + " (expect " + expectName(c.expect) + "): " + oneLine(r.detail));
        if (isFailure(r.outcome) && !o.save.empty())
            copyCase(c, std::filesystem::path(o.save) / (std::string(outcomeName(r.outcome)) + "-" + c.mutation + "-s" +
                                                         std::to_string(o.seed) + "-" + std::to_string(i)));
        if (!o.keep.empty()) copyCase(c, std::filesystem::path(o.keep) / std::to_string(i));
    }
    std::ofstream out(countsFile);
    for (const auto& [k, n] : counts) out << k.first << " " << k.second << " " << n << "\n";
}

int fuzz(const Options& o) {
    const auto start = std::chrono::steady_clock::now();
    Seeds seeds = loadSeeds(o.source);
    if (seeds.scenes.empty()) {
        std::cerr << "luxplan_fuzz: no seed scenes under " << o.source << "/scenes\n";
        return 2;
    }
    std::cout << "luxplan_fuzz: seed " << o.seed << ", " << o.count << " inputs" << (o.seconds > 0 ? " at most" : "") << ", "
              << seeds.scenes.size() << " scenes, " << seeds.objs.size() << " OBJ, " << seeds.gltfs.size() << " glTF, " << seeds.glbs.size() << " GLB, "
              << seeds.ies.size() << " IES, " << seeds.ldts.size() << " LDT seeds, " << o.jobs << " jobs" << std::endl;
    const std::filesystem::path root = tempRoot();
    std::vector<pid_t> workers;
    for (int w = 0; w < o.jobs; ++w) {
        const pid_t pid = fork();
        if (pid == 0) {
            worker(seeds, o, w, root, root / ("counts-" + std::to_string(w)));
            _exit(0);
        }
        workers.push_back(pid);
    }
    bool workerFailed = false;
    for (pid_t pid : workers) {
        int status = 0;
        waitpid(pid, &status, 0);
        workerFailed |= !WIFEXITED(status) || WEXITSTATUS(status) != 0;
    }
    std::map<std::string, uint64_t> byOutcome;
    std::map<std::string, std::map<std::string, uint64_t>> byMutation;
    uint64_t total = 0;
    for (int w = 0; w < o.jobs; ++w) {
        std::ifstream in(root / ("counts-" + std::to_string(w)));
        std::string outcome, mutation;
        uint64_t n;
        while (in >> outcome >> mutation >> n)
            byOutcome[outcome] += n, byMutation[mutation][outcome] += n, total += outcome == "skipped" ? 0 : n;
    }
    std::error_code ec;
    std::filesystem::remove_all(root, ec);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    uint64_t failures = 0;
    for (const char* f : {"crash", "hang", "memory", "nonfinite", "wrong-accept", "wrong-refuse", "unnamed-refusal"})
        failures += byOutcome[f];
    std::cout << "by mutation:\n";
    for (const auto& [m, outs] : byMutation) {
        std::cout << "  " << m << ":";
        for (const auto& [k, n] : outs) std::cout << " " << k << " " << n;
        std::cout << "\n";
    }
    std::cout << total << " inputs in " << seconds << " s: accepted " << byOutcome["accepted"] << ", refused "
              << byOutcome["refused"] << "; crashes " << byOutcome["crash"] << ", hangs " << byOutcome["hang"]
              << ", memory blow-ups " << byOutcome["memory"] << ", non-finite outputs " << byOutcome["nonfinite"]
              << ", wrong accepts " << byOutcome["wrong-accept"] << ", wrong refusals " << byOutcome["wrong-refuse"]
              << ", refusals without file and path " << byOutcome["unnamed-refusal"] << std::endl;
    if (workerFailed) std::cout << "a worker process failed\n";
    return failures || workerFailed || total == 0 ? 1 : 0;
}

int replay(const Options& o) {
    std::vector<std::filesystem::path> cases;
    for (const std::string& d : o.replay) {
        if (std::filesystem::exists(std::filesystem::path(d) / "expect.txt")) {
            cases.push_back(d);
            continue;
        }
        if (!std::filesystem::is_directory(d)) {
            std::cerr << d << ": no such case folder\n";
            return 2;
        }
        for (const auto& e : std::filesystem::directory_iterator(d))
            if (std::filesystem::exists(e.path() / "expect.txt")) cases.push_back(e.path());
    }
    std::sort(cases.begin(), cases.end());
    Bounds bounds;
    bounds.seconds = o.timeout;
    bounds.wallSeconds = o.wall;
    const std::filesystem::path root = tempRoot();
    int failures = 0;
    for (const auto& p : cases) {
        Case c = readCase(p);
        const std::filesystem::path dir = root / p.filename();
        writeCase(c, dir);
        Result r = runCase(c, dir, bounds);
        failures += isFailure(r.outcome);
        std::cout << (isFailure(r.outcome) ? "FAIL " : "ok   ") << outcomeName(r.outcome) << " " << p.filename().string() << " ("
                  << c.mutation << ", expect " << expectName(c.expect) << ")"
                  << (o.verbose || isFailure(r.outcome) ? ": " + oneLine(r.detail, 2000) : "") << "\n";
    }
    std::error_code ec;
    std::filesystem::remove_all(root, ec);
    std::cout << cases.size() << " kept inputs, " << failures << " failed\n";
    return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << a << " needs a value\n";
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--count") o.count = std::stoull(next());
        else if (a == "--seconds") o.seconds = std::stod(next());
        else if (a == "--seed") o.seed = std::stoull(next());
        else if (a == "--jobs") o.jobs = std::max(1, std::stoi(next()));
        else if (a == "--timeout") o.timeout = std::stod(next());
        else if (a == "--wall") o.wall = std::stod(next());
        else if (a == "--save") o.save = next();
        else if (a == "--keep") o.keep = next();
        else if (a == "--source") o.source = next();
        else if (a == "--only") o.only = std::stoll(next());
        else if (a == "-v") o.verbose = true;
        else if (a == "--replay") {
            while (i + 1 < argc && argv[i + 1][0] != '-') o.replay.push_back(argv[++i]);
        } else {
            std::cerr << "luxplan_fuzz: unknown option " << a << "\n";
            return 2;
        }
    }
    if (!o.replay.empty()) return replay(o);
    return fuzz(o);
}
