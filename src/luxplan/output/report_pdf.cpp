// report.pdf: Chromium run as a child process (no shell), in a process group of its
// own so that a timeout or a stop signal ends it and every process it started.
#include <luxplan/output/report_pdf.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <luxplan/core/atomic_file.h>

extern char** environ;

namespace luxplan {
namespace {

// An executable named `name`: the path itself when it has a '/', else the first on PATH.
std::string executableOnPath(const std::string& name) {
    if (name.empty()) return "";
    if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? name : "";
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
    size_t start = 0;
    while (start <= dirs.size()) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
        const std::string candidate = dir + "/" + name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return "";
}

// file:// URL of an absolute path, every byte but unreserved ones and '/' escaped.
std::string fileUrl(const std::filesystem::path& file) {
    static const char* hex = "0123456789ABCDEF";
    std::string url = "file://";
    for (unsigned char c : file.string()) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
            url += char(c);
        } else {
            url += '%';
            url += hex[c >> 4];
            url += hex[c & 15];
        }
    }
    return url;
}

std::string readWhole(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return in ? std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()) : std::string();
}

// The last few lines of the browser's output on one line, for a failure's message.
std::string lastLines(const std::string& text, size_t lines = 3) {
    std::vector<std::string> all;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) all.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    std::string out;
    for (size_t k = all.size() > lines ? all.size() - lines : 0; k < all.size(); ++k) out += (out.empty() ? "" : " ") + all[k];
    return out;
}

constexpr const char* kWorkPrefix = "luxplan-pdf-";

// Removes the work folders of luxplan processes that no longer run (killed with
// SIGKILL while Chromium printed: no destructor ran): luxplan-pdf-PID-N with no PID.
void removeStaleWorkFolders(const std::filesystem::path& temp) {
    std::error_code ec;
    for (std::filesystem::directory_iterator it(temp, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind(kWorkPrefix, 0) != 0) continue;
        const std::string rest = name.substr(std::strlen(kWorkPrefix));
        const size_t dash = rest.find('-');
        if (dash == 0 || dash == std::string::npos || rest.find_first_not_of("0123456789") != dash) continue;
        const long pid = std::strtol(rest.substr(0, dash).c_str(), nullptr, 10);
        if (pid <= 0 || ::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;
        std::error_code removed;
        std::filesystem::remove_all(it->path(), removed);
    }
}

// A folder of its own under the system's temporary folder, removed with the object.
class PdfWorkFolder {
public:
    PdfWorkFolder() {
        static std::atomic<int> counter{0};
        std::error_code ec;
        const std::filesystem::path temp = std::filesystem::temp_directory_path(ec);
        removeStaleWorkFolders(temp);
        path_ = temp / (kWorkPrefix + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_, ec);
        ok_ = std::filesystem::create_directories(path_, ec) && !ec;
    }
    // Removed with everything in it; a helper of the browser that writes its profile as
    // it goes may leave a file behind the first removal: a few more tries.
    ~PdfWorkFolder() {
        for (int attempt = 0; attempt < 20; ++attempt) {
            std::error_code ec;
            std::filesystem::remove_all(path_, ec);
            if (!std::filesystem::exists(path_, ec)) return;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }
    PdfWorkFolder(const PdfWorkFolder&) = delete;
    PdfWorkFolder& operator=(const PdfWorkFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }
    bool ok() const { return ok_; }

private:
    std::filesystem::path path_;
    bool ok_ = false;
};

}  // namespace

std::string pdfBrowser() {
    if (const char* chosen = std::getenv("LUXPLAN_CHROMIUM"); chosen && *chosen) return executableOnPath(chosen);
    for (const char* name : {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"})
        if (std::string found = executableOnPath(name); !found.empty()) return found;
    return "";
}

std::string writeReportPdf(const std::filesystem::path& folder, double timeoutSeconds, const std::atomic<bool>* cancel) {
    const std::string browser = pdfBrowser();
    if (browser.empty()) {
        const char* chosen = std::getenv("LUXPLAN_CHROMIUM");
        return chosen && *chosen ? std::string("LUXPLAN_CHROMIUM=") + chosen + " is no executable"
                                 : std::string("no Chromium found (chromium on PATH; scripts/install-deps.sh installs it)");
    }
    std::error_code ec;
    const std::filesystem::path page = std::filesystem::absolute(folder / "report.html", ec);
    if (ec || !std::filesystem::is_regular_file(page, ec)) return "no report.html to print";
    PdfWorkFolder work;
    if (!work.ok()) return "cannot create a temporary folder for Chromium";
    const std::filesystem::path pdf = work.path() / "report.pdf", log = work.path() / "chromium.log";

    std::vector<std::string> args = {browser,
                                     "--headless",
                                     "--no-sandbox",
                                     "--disable-gpu",
                                     "--no-first-run",
                                     "--no-default-browser-check",
                                     "--disable-extensions",
                                     "--no-pdf-header-footer",
                                     "--user-data-dir=" + (work.path() / "profile").string(),
                                     "--print-to-pdf=" + pdf.string(),
                                     fileUrl(page)};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t files;
    posix_spawnattr_t attributes;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
    posix_spawnattr_init(&attributes);
    // A process group of its own: a timeout ends the browser and its helpers together.
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, browser.c_str(), &files, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    if (spawned != 0) return browser + " did not start (" + std::strerror(spawned) + ")";

    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    std::string stopped;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) {
            stopped = std::string("waiting for it failed (") + std::strerror(errno) + ")";
            break;
        }
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed > timeoutSeconds) stopped = "it ran past " + std::to_string(int(timeoutSeconds)) + " s";
        if (cancel && cancel->load()) stopped = "stopped by a signal";
        if (!stopped.empty()) {
            ::kill(-pid, SIGKILL);
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!stopped.empty()) return browser + ": " + stopped;
    // Its helpers (the GPU and utility processes) leave with it; a second at most, then
    // they are ended, so that none still writes into the work folder as it goes.
    for (int k = 0; k < 20 && ::kill(-pid, 0) == 0; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (::kill(-pid, 0) == 0) ::kill(-pid, SIGKILL);
    const std::string bytes = readWhole(pdf);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.rfind("%PDF", 0) != 0) {
        const std::string why = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                  : "signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0);
        return browser + " printed no PDF (" + why + "): " + lastLines(readWhole(log));
    }
    writeFileAtomically(folder / "report.pdf", bytes);
    return "";
}

}  // namespace luxplan
