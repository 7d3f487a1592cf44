// A long run stopped by SIGINT, SIGTERM or SIGHUP writes its best layout, whole, and
// exits with 128 + the signal; a second Ctrl-C skips the pictures still to make; an
// output folder that cannot take files is refused before the search starts.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

const std::string kLongRunScene = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/paper/fig7-office-morning.json";  // never reaches C = 0

// An endless search writing to `out`, started in a child process; returns once it
// catches its stop signals (it makes the output folder after that), at whatever
// stage the run then is.
template <typename... Extra>
pid_t startSearch(const std::string& out, Extra... extra) {
    const pid_t pid = fork();
    if (pid == 0) {
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        execl(LUXPLAN_CLI, "luxplan", "optimize", kLongRunScene.c_str(), "-o", out.c_str(), "--iterations", "100000000", "--paths", "4",
              "--threads", "1", "-q", extra..., static_cast<char*>(nullptr));
        _exit(127);
    }
    for (int k = 0; k < 200 && pid > 0 && !std::filesystem::exists(out); ++k)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return pid;
}

TEST(CliSignals, EachStopSignalWritesTheBestLayout) {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
        test::TempDir dir;
        const std::string out = (dir.path() / "out").string();
        const pid_t pid = startSearch(out, "--no-pictures");
        ASSERT_GT(pid, 0);
        kill(pid, signal);
        int status = 0;
        ASSERT_EQ(waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal;
        EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
        for (const char* name : {"layout.json", "report.json"}) {
            std::ifstream in(std::filesystem::path(out) / name);
            ASSERT_TRUE(in) << name;
            EXPECT_TRUE(nlohmann::json::accept(in)) << name << " is not whole";
        }
        for (const auto& entry : std::filesystem::directory_iterator(out))
            EXPECT_EQ(entry.path().string().find(".part-"), std::string::npos) << entry.path();
    }
}

TEST(CliSignals, ASecondCtrlCSkipsThePictures) {
    test::TempDir dir;
    const std::string out = (dir.path() / "out").string();
    // Pictures that would take minutes: the second signal surely comes before them.
    const pid_t pid = startSearch(out, "--spp", "4096");
    ASSERT_GT(pid, 0);
    const auto layout = std::filesystem::path(out) / "layout.json";
    kill(pid, SIGINT);
    for (int k = 0; k < 600 && !std::filesystem::exists(layout); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    kill(pid, SIGINT);
    int status = 0;
    for (int k = 0; k < 1200 && waitpid(pid, &status, WNOHANG) == 0; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (waitpid(pid, &status, WNOHANG) == 0) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        FAIL() << "the second Ctrl-C did not stop the pictures within 60 s";
    }
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    std::ifstream in(layout);
    EXPECT_TRUE(nlohmann::json::accept(in));
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(out) / "render.png"));
}

TEST(CliSignals, AnUnwritableOutputFolderIsRefusedFirst) {
    test::TempDir dir;
    const auto file = dir.write("a-file", "x");
    const auto started = std::chrono::steady_clock::now();
    test::CliResult r = test::runCli("optimize " + kLongRunScene + " -o " + (file / "out").string() + " --iterations 100000000 -q");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find((file / "out").string() + ": cannot create the output folder"), std::string::npos) << r.output;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 30.0);
}

}  // namespace
}  // namespace luxplan
