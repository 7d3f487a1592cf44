#include "fuzz_case.h"

#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <tbb/global_control.h>

#include <luxplan/checks/scene_warnings.h>
#include <luxplan/constraints/penalty.h>
#include <luxplan/core/error.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/json/fields.h>
#include <luxplan/lightsamplers/light_samplers.h>
#include <luxplan/pathtracer/path_tracer.h>
#include <luxplan/rt/embree_scene.h>
#include <luxplan/scene/layout.h>

#if defined(__SANITIZE_ADDRESS__)
#define LUXPLAN_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LUXPLAN_FUZZ_ASAN 1
#endif
#endif

namespace luxplan::fuzz {

const char* expectName(Expect e) {
    switch (e) {
        case Expect::Refuse: return "refuse";
        case Expect::Accept: return "accept";
        case Expect::Either: return "either";
    }
    return "?";
}

bool parseExpect(const std::string& s, Expect& e) {
    for (Expect x : {Expect::Refuse, Expect::Accept, Expect::Either})
        if (s == expectName(x)) return e = x, true;
    return false;
}

const char* outcomeName(Outcome o) {
    switch (o) {
        case Outcome::Accepted: return "accepted";
        case Outcome::Refused: return "refused";
        case Outcome::Crash: return "crash";
        case Outcome::Hang: return "hang";
        case Outcome::Memory: return "memory";
        case Outcome::NonFinite: return "nonfinite";
        case Outcome::WrongAccept: return "wrong-accept";
        case Outcome::WrongRefuse: return "wrong-refuse";
        case Outcome::Unnamed: return "unnamed-refusal";
    }
    return "?";
}

void writeCase(const Case& c, const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    for (const auto& [name, bytes] : c.files) {
        std::ofstream out(dir / name, std::ios::binary);
        out.write(bytes.data(), std::streamsize(bytes.size()));
    }
    std::ofstream meta(dir / "expect.txt");
    meta << "expect " << expectName(c.expect) << "\nmutation " << c.mutation << "\nscene " << c.scene << "\n";
    if (!c.layout.empty()) meta << "layout " << c.layout << "\n";
    meta << "measure " << (c.measure ? 1 : 0) << "\n";
}

Case readCase(const std::filesystem::path& dir) {
    Case c;
    std::ifstream meta(dir / "expect.txt");
    if (!meta) throw std::runtime_error((dir / "expect.txt").string() + ": cannot read");
    std::string key;
    while (meta >> key) {
        std::string value;
        std::getline(meta >> std::ws, value);
        if (key == "expect") {
            if (!parseExpect(value, c.expect)) throw std::runtime_error((dir / "expect.txt").string() + ": bad expect " + value);
        } else if (key == "mutation") c.mutation = value;
        else if (key == "scene") c.scene = value;
        else if (key == "layout") c.layout = value;
        else if (key == "measure") c.measure = value == "1";
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name == "expect.txt" || !entry.is_regular_file()) continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        c.files[name] = s.str();
    }
    return c;
}

namespace {

void writeAll(int fd, const std::string& s) {
    size_t done = 0;
    while (done < s.size()) {
        ssize_t n = ::write(fd, s.data() + done, s.size() - done);
        if (n <= 0) return;
        done += size_t(n);
    }
}

bool finite(double v) { return std::isfinite(v); }

// The child: the loader, validate's checks and maybe a measure, then one report on
// `fd`: ACCEPT, NONFINITE what, MEMORY, SCENE + one "file\tpath\tmessage" per
// diagnostic, IO message, OTHER message.
[[noreturn]] void child(const Case& c, const std::filesystem::path& dir, const Bounds& bounds, int fd) {
    alarm(unsigned(std::ceil(bounds.wallSeconds)));
    const rlim_t cpu = rlim_t(std::ceil(bounds.seconds));
    rlimit cpuLimit{cpu, cpu + 1};
    setrlimit(RLIMIT_CPU, &cpuLimit);
#ifndef LUXPLAN_FUZZ_ASAN
    rlimit lim{bounds.memoryBytes, bounds.memoryBytes};
    setrlimit(RLIMIT_AS, &lim);
#endif
    rlimit core{0, 0};
    setrlimit(RLIMIT_CORE, &core);
    int err = ::open((dir / "stderr.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err >= 0) dup2(err, 2);
    int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, 1);
    std::string report;
    try {
        tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
        Scene scene = io::loadScene(dir / c.scene);
        Layout layout = c.layout.empty() ? initialLayout(scene) : io::readLayout(dir / c.layout, scene);
        (void)sceneWarnings(scene);
        report = "ACCEPT";
        if (c.measure) {
            std::optional<DaylightEnvironment> daylight;
            if (scene.daylight) daylight = buildDaylight(*scene.daylight, scene.site);
            EmbreeScene rt(scene, layout);
            PathTracer tracer(rt, daylight ? &*daylight : nullptr);
            MeasureOptions options;
            options.pathsPerPoint = 2;
            options.seed = scene.optimizer.seed;
            MeasureResult result = measureSamplers(tracer, options);
            for (size_t k = 0; k < result.samplers.size() && report == "ACCEPT"; ++k) {
                const SamplerResult& r = result.samplers[k];
                const std::string name = k < scene.samplers.size() ? scene.samplers[k].name : std::to_string(k);
                if (!finite(r.value) || !finite(r.standardError)) report = "NONFINITE sampler " + name + " value";
                for (double p : r.points)
                    if (!finite(p)) report = "NONFINITE sampler " + name + " point";
                if (k < scene.samplers.size() && !finite(lightingPenalty(scene.samplers[k], r.value)))
                    report = "NONFINITE sampler " + name + " penalty";
            }
            if (report == "ACCEPT" && !finite(lightingCostOfResults(scene, result.samplers))) report = "NONFINITE L";
        }
    } catch (const SceneError& e) {
        report = "SCENE\n";
        for (const Diagnostic& d : e.diagnostics()) report += d.file + "\t" + d.jsonPath + "\t" + d.message + "\n";
    } catch (const IoError& e) {
        report = std::string("IO\n") + e.what();
    } catch (const std::bad_alloc&) {
        report = "MEMORY";
    } catch (const std::length_error& e) {
        report = std::string("MEMORY ") + e.what();
    } catch (const std::exception& e) {
        report = std::string("OTHER\n") + e.what();
    }
    writeAll(fd, report);
    ::close(fd);
    _exit(0);
}

std::string tail(const std::filesystem::path& file, size_t n) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    std::string t = s.str();
    return t.size() > n ? t.substr(t.size() - n) : t;
}

bool startsWithKnownFile(const std::string& text, const std::vector<std::string>& files) {
    for (const std::string& f : files)
        if (text.compare(0, f.size(), f) == 0 && text.size() > f.size() && text[f.size()] == ':') return true;
    return false;
}

}  // namespace

Result runCase(const Case& c, const std::filesystem::path& dir, const Bounds& bounds) {
    int fds[2];
    if (pipe(fds) != 0) return {Outcome::Crash, "pipe failed"};
    const pid_t pid = fork();
    if (pid < 0) {
        ::close(fds[0]), ::close(fds[1]);
        return {Outcome::Crash, "fork failed"};
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(c, dir, bounds, fds[1]);
    }
    ::close(fds[1]);
    std::string report;
    timespec start{};
    clock_gettime(CLOCK_MONOTONIC, &start);
    bool timedOut = false;
    for (;;) {
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC, &now);
        const double elapsed = double(now.tv_sec - start.tv_sec) + 1e-9 * double(now.tv_nsec - start.tv_nsec);
        const double left = bounds.wallSeconds + 2 - elapsed;
        if (left <= 0) {
            timedOut = true;
            kill(pid, SIGKILL);
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        int r = poll(&p, 1, int(left * 1000) + 1);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) continue;
        char buf[4096];
        ssize_t n = ::read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        report.append(buf, size_t(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    const std::string err = tail(dir / "stderr.log", 2000);
    if (timedOut || (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM))
        return {Outcome::Hang, "no answer within " + json::formatNumber(bounds.wallSeconds) + " s"};
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
        return {Outcome::Hang, "more than " + json::formatNumber(bounds.seconds) + " s of CPU time"};
    if (WIFSIGNALED(status)) {
        if (WTERMSIG(status) == SIGKILL) return {Outcome::Memory, "killed (SIGKILL): " + err};
        return {Outcome::Crash, std::string("signal ") + strsignal(WTERMSIG(status)) + "\n" + err};
    }
    if (WEXITSTATUS(status) != 0 || report.empty())
        return {Outcome::Crash, "exit status " + std::to_string(WEXITSTATUS(status)) + " without a report\n" + err};

    std::vector<std::string> known;
    for (const auto& [name, bytes] : c.files) known.push_back((dir / name).string());
    const auto refused = [&](std::string detail) -> Result {
        if (c.expect == Expect::Accept) return {Outcome::WrongRefuse, detail};
        return {Outcome::Refused, detail};
    };
    if (report == "ACCEPT") {
        if (c.expect == Expect::Refuse) return {Outcome::WrongAccept, "accepted"};
        return {Outcome::Accepted, ""};
    }
    if (report.rfind("NONFINITE", 0) == 0) return {Outcome::NonFinite, report};
    if (report.rfind("MEMORY", 0) == 0) return {Outcome::Memory, report};
    if (report.rfind("SCENE\n", 0) == 0) {
        std::istringstream lines(report.substr(6));
        std::string line, message;
        int n = 0;
        while (std::getline(lines, line)) {
            if (line.empty()) continue;
            const size_t t1 = line.find('\t'), t2 = t1 == std::string::npos ? t1 : line.find('\t', t1 + 1);
            if (t2 == std::string::npos) continue;  // the rest of a multi-line message
            ++n;
            const std::string file = line.substr(0, t1);
            const std::string path = line.substr(t1 + 1, t2 - t1 - 1);
            message += file + ": " + (path.empty() ? "/" : path) + ": " + line.substr(t2 + 1) + "\n";
            bool named = false;
            for (const std::string& k : known) named |= file == k;
            if (!named) return {Outcome::Unnamed, "diagnostic names no input file: " + line};
            if (!path.empty() && path[0] != '/') return {Outcome::Unnamed, "diagnostic path is no JSON pointer: " + line};
        }
        if (n == 0) return {Outcome::Unnamed, "a SceneError with no diagnostic"};
        return refused(message);
    }
    if (report.rfind("IO\n", 0) == 0) {
        const std::string message = report.substr(3);
        if (!startsWithKnownFile(message, known)) return {Outcome::Unnamed, "I/O error names no input file: " + message};
        return refused(message);
    }
    return {Outcome::Unnamed, "exception naming no file: " + report.substr(report.find('\n') + 1)};
}

}  // namespace luxplan::fuzz

namespace luxplan::fuzz {

std::string layoutFor(const std::filesystem::path& scene) {
    int fds[2];
    if (pipe(fds) != 0) return "";
    const pid_t pid = fork();
    if (pid == 0) {
        ::close(fds[0]);
        std::string text;
        try {
            tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
            Scene s = io::loadScene(scene);
            text = io::layoutToJson(s, initialLayout(s));
        } catch (const std::exception&) {
        }
        writeAll(fds[1], text);
        _exit(0);
    }
    ::close(fds[1]);
    std::string text;
    char buf[4096];
    for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) != 0;) {
        if (n < 0) {
            if (errno == EINTR) continue;
            break;
        }
        text.append(buf, size_t(n));
    }
    ::close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return text;
}

}  // namespace luxplan::fuzz
