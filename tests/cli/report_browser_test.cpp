// report.html in a real browser: Debian's Chromium, headless (installed by
// scripts/install-deps.sh), opens the page from file:// with WebGL on SwiftShader; the
// page must load without a script error and its 3D view must draw the room.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

namespace fs = std::filesystem;

// Runs `command 2>&1` and returns its output.
std::string shell(const std::string& command) {
    std::string out;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return out;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    pclose(pipe);
    return out;
}

TEST(ReportBrowser, ThePageLoadsAndTheRoomDrawsInHeadlessChromium) {
    ASSERT_EQ(std::system("command -v chromium > /dev/null"), 0)
        << "chromium is not installed: scripts/install-deps.sh installs Debian's";
    test::TempDir dir;
    const fs::path out = dir.path() / "report";
    const std::string scene = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/open-plan.json";
    test::CliResult r = test::runCli("report " + scene + " -o " + out.string() +
                                     " --width 48 --height 32 --spp 1 --paths 4 --cell 1 --cell-paths 2 --threads 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"viewer/three.min.js", "viewer/GLTFLoader.js", "viewer/OrbitControls.js", "scene.glb"})
        ASSERT_TRUE(fs::is_regular_file(out / f)) << f;

    const std::string dom = shell("chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader "
                                  "--user-data-dir=" + (dir.path() / "profile").string() +
                                  " --enable-logging=stderr --v=0 --virtual-time-budget=15000 --dump-dom file://" +
                                  (out / "report.html").string());
    std::smatch body;
    ASSERT_TRUE(std::regex_search(dom, body, std::regex("<body[^>]*>"))) << dom.substr(0, 2000);
    const std::string tag = body.str();
    EXPECT_EQ(tag.find("data-viewer-error"), std::string::npos) << tag;
    EXPECT_NE(tag.find("data-viewer=\"drawn\""), std::string::npos) << tag;
    std::smatch lit;
    ASSERT_TRUE(std::regex_search(tag, lit, std::regex("data-viewer-lit=\"([0-9.]+)\""))) << tag;
    // The room covers a good part of the canvas (about a fifth for the open-plan office).
    EXPECT_GT(std::stod(lit[1].str()), 0.05) << tag;
    // No script error reached the console.
    EXPECT_EQ(dom.find("Uncaught"), std::string::npos) << dom.substr(0, 4000);
}

}  // namespace
}  // namespace luxplan
