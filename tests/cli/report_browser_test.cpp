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

// Writes the report of the bundled scene `name` and opens it in headless Chromium;
// returns the page's <body> tag once the 3D view has drawn, "" after a failure.
std::string reportBodyInChromium(const std::string& name, test::TempDir& dir) {
    EXPECT_EQ(std::system("command -v chromium > /dev/null"), 0)
        << "chromium is not installed: scripts/install-deps.sh installs Debian's";
    const fs::path out = dir.path() / "report";
    const std::string scene = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/" + name + ".json";
    test::CliResult r = test::runCli("report " + scene + " -o " + out.string() +
                                     " --width 48 --height 32 --spp 1 --paths 4 --cell 1 --cell-paths 2 --threads 2");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* f : {"viewer/three.min.js", "viewer/GLTFLoader.js", "viewer/OrbitControls.js", "scene.glb"})
        if (!fs::is_regular_file(out / f)) {
            ADD_FAILURE() << f;
            return "";
        }

    const std::string dom = test::runShell("chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader "
                                  "--user-data-dir=" + (dir.path() / "profile").string() +
                                  " --enable-logging=stderr --v=0 --virtual-time-budget=15000 --dump-dom file://" +
                                  (out / "report.html").string()).output;
    std::smatch body;
    if (!std::regex_search(dom, body, std::regex("<body[^>]*>"))) {
        ADD_FAILURE() << dom.substr(0, 2000);
        return "";
    }
    const std::string tag = body.str();
    EXPECT_EQ(tag.find("data-viewer-error"), std::string::npos) << tag;
    EXPECT_NE(tag.find("data-viewer=\"drawn\""), std::string::npos) << tag;
    // No script error reached the console.
    EXPECT_EQ(dom.find("Uncaught"), std::string::npos) << dom.substr(0, 4000);
    return tag;
}

// The share of the canvas that is not background (data-viewer-lit), -1 without one.
double viewerLit(const std::string& tag) {
    std::smatch lit;
    return std::regex_search(tag, lit, std::regex("data-viewer-lit=\"([0-9.]+)\"")) ? std::stod(lit[1].str()) : -1;
}

TEST(ReportBrowser, ThePageLoadsAndTheRoomDrawsInHeadlessChromium) {
    test::TempDir dir;
    const std::string tag = reportBodyInChromium("open-plan", dir);
    ASSERT_FALSE(tag.empty());
    // The view starts from the scene's first camera, inside the room.
    EXPECT_NE(tag.find("data-viewer-view=\"camera door\""), std::string::npos) << tag;
    // The room covers a good part of the canvas.
    EXPECT_GT(viewerLit(tag), 0.05) << tag;
}

// A scene without cameras, with a building across the street: the view starts from the
// file's default camera (render.png's view, inside the room), so the room fills the
// canvas instead of being a speck beside the building.
TEST(ReportBrowser, WithoutSceneCamerasTheViewStartsInsideTheRoom) {
    test::TempDir dir;
    const std::string tag = reportBodyInChromium("daylit-office", dir);
    ASSERT_FALSE(tag.empty());
    EXPECT_NE(tag.find("data-viewer-view=\"camera default view\""), std::string::npos) << tag;
    EXPECT_GT(viewerLit(tag), 0.5) << tag;
}

}  // namespace
}  // namespace luxplan
