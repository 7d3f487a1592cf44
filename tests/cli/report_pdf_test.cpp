// report.pdf: report.html printed on A4 by headless Chromium (scripts/install-deps.sh
// installs Debian's chromium and poppler-utils' pdftotext and pdfinfo, which read it
// back here). Without a browser the run still succeeds, with a warning and no PDF.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>

#include <sys/wait.h>
#include <unistd.h>

#include "run_cli.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

namespace fs = std::filesystem;

namespace reportpdftest {

bool installed(const char* program) { return std::system((std::string("command -v ") + program + " > /dev/null").c_str()) == 0; }

// A 6 x 4 m room, a ceiling panel and a desk whose task area is named "reading desk".
const char* kPdfScene = R"({"luxplan": 1,
  "name": "pdf office",
  "materials": {"wall": {"type": "diffuse", "reflectance": 0.5}, "wood": {"type": "diffuse", "reflectance": 0.4}},
  "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"}}],
  "luminaires": [{"name": "panel", "shape": "rect", "center": [3,2,2.99], "normal": [0,0,-1], "size": [0.6,0.6], "flux_lm": 4000}],
  "entities": [{"name": "desk", "position": [2.5, 2],
                "placement": {"regions": [{"min": [1,1], "max": [5,3], "rotations": [0, 90]}]},
                "parts": [{"preset": "table", "size": [1.2, 0.8, 0.75], "material": "wood"}],
                "samplers": [{"name": "reading desk", "type": "planar", "center": [0,0,0.76], "size": [0.8,0.6],
                              "grid": [2,2], "target": [300, null], "tolerance": 100}]}],
  "objective": {"lighting_weight": 0.8},
  "optimizer": {"iterations": 30, "seed": 2, "paths_per_point": 8, "report_paths_per_point": 16}})";

const std::string kTinyPictures = " --threads 2 --spp 1 --width 48 --height 32 --paths 8 --cell 0.5 --cell-paths 4";

}  // namespace reportpdftest

using namespace reportpdftest;

TEST(ReportPdf, ReportHtmlPrintedOnA4WithTheResultsFirst) {
    if (!installed("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh installs it): no report.pdf";
    if (!installed("pdftotext") || !installed("pdfinfo"))
        GTEST_SKIP() << "pdftotext/pdfinfo are not installed (poppler-utils; scripts/install-deps.sh installs it)";
    test::TempDir dir;
    // The work folder a run killed with SIGKILL while Chromium printed left behind (a
    // process that has exited: its id runs nothing now) goes with the next print.
    const pid_t gone = fork();
    if (gone == 0) _exit(0);
    ASSERT_GT(gone, 0);
    waitpid(gone, nullptr, 0);
    const fs::path stale = fs::temp_directory_path() / ("luxplan-pdf-" + std::to_string(gone) + "-0");
    fs::create_directories(stale / "profile");
    const fs::path scene = dir.write("scene.json", kPdfScene), out = dir.path() / "report";
    test::CliResult r = test::runCli("report " + scene.string() + " -o " + out.string() + kTinyPictures);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(fs::is_regular_file(out / "report.pdf")) << r.output;
    EXPECT_FALSE(fs::exists(stale)) << stale;
    EXPECT_NE(r.output.find((out / "report.pdf").string()), std::string::npos) << r.output;  // said as written
    EXPECT_TRUE(fs::is_regular_file(out / "plan.png"));  // the pictures are still files too
    for (const auto& entry : fs::directory_iterator(out))
        EXPECT_EQ(entry.path().filename().string().find(".part-"), std::string::npos) << entry.path();

    const std::string text = test::runShell("pdftotext -layout " + (out / "report.pdf").string() + " -").output;
    EXPECT_NE(text.find("Results"), std::string::npos) << text;
    EXPECT_NE(text.find("Task areas"), std::string::npos) << text;
    EXPECT_NE(text.find("reading desk"), std::string::npos) << text;
    EXPECT_NE(text.find("(mean)"), std::string::npos) << text;  // no maintenance factor: not called maintained
    EXPECT_NE(text.find("Appendix"), std::string::npos) << text;
    // The results come first, the appendix on pages of its own after them.
    EXPECT_LT(text.find("Results"), text.find("Appendix"));
    EXPECT_EQ(text.find("drag to turn"), std::string::npos) << "the 3D view's text in print";

    const std::string info = test::runShell("pdfinfo " + (out / "report.pdf").string()).output;
    std::smatch pages, size;
    ASSERT_TRUE(std::regex_search(info, pages, std::regex("Pages:\\s+([0-9]+)"))) << info;
    const int count = std::stoi(pages[1].str());
    EXPECT_GE(count, 2) << info;  // the results and the appendix
    EXPECT_LE(count, 12) << info;
    ASSERT_TRUE(std::regex_search(info, size, std::regex("Page size:[^\\n]*\\(A4\\)"))) << info;
}

// No browser: report.html and the pictures as always, a warning, no report.pdf, exit 0.
TEST(ReportPdf, WithoutABrowserTheRunWarnsAndWritesTheRest) {
    test::TempDir dir;
    const fs::path scene = dir.write("scene.json", kPdfScene), out = dir.path() / "report";
    ::setenv("LUXPLAN_CHROMIUM", (dir.path() / "no-such-browser").c_str(), 1);
    test::CliResult r = test::runCli("report " + scene.string() + " -o " + out.string() + kTinyPictures);
    ::unsetenv("LUXPLAN_CHROMIUM");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::is_regular_file(out / "report.html"));
    EXPECT_FALSE(fs::exists(out / "report.pdf"));
    EXPECT_NE(r.output.find("warning: report.pdf not written: LUXPLAN_CHROMIUM=" + (dir.path() / "no-such-browser").string() +
                            " is no executable"),
              std::string::npos)
        << r.output;
    // --no-pdf: neither a PDF nor a warning.
    test::CliResult quiet = test::runCli("report " + scene.string() + " -o " + out.string() + kTinyPictures + " --no-pdf");
    ASSERT_EQ(quiet.exitCode, 0) << quiet.output;
    EXPECT_EQ(quiet.output.find("report.pdf"), std::string::npos) << quiet.output;
    EXPECT_FALSE(fs::exists(out / "report.pdf"));
}

}  // namespace
}  // namespace luxplan
