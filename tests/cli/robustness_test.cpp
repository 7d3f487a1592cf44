// The command line on inputs that once crashed or hung (issue 15): every refusal
// names its file and JSON path (or FILE:LINE in a mesh), with exit status 1.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "run_cli.h"
#include "support/small_room.h"
#include "support/temp_files.h"

namespace luxplan {
namespace {

std::string scene(const std::string& mesh = "") {
    return test::smallRoomScene(mesh.empty() ? "" : ", {\"name\": \"m\", \"mesh\": \"" + mesh + "\", \"material\": \"wall\"}");
}

TEST(CliRobustness, MeshFaceIndexOutOfRange) {
    test::TempDir dir;
    auto obj = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 100000000\n");
    auto file = dir.write("scene.json", scene("bad.obj"));
    test::CliResult r = test::runCli("validate " + file.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /geometry/1/mesh: cannot read mesh: " + obj.string() +
                            ":4: face vertex index 100000000 is out of range"),
              std::string::npos)
        << r.output;
}

TEST(CliRobustness, MeshThatIsAFifoDoesNotBlock) {
    test::TempDir dir;
    ASSERT_EQ(mkfifo((dir.path() / "pipe.obj").c_str(), 0600), 0);
    auto file = dir.write("scene.json", scene("pipe.obj"));
    test::CliResult r = test::runCli("validate " + file.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /geometry/1/mesh: cannot read mesh"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
}

TEST(CliRobustness, LayoutPositionFarAway) {
    test::TempDir dir;
    auto file = dir.write("scene.json", scene());
    auto layout = dir.write("layout.json", R"({"entities": {"desk": {"position": [1e9, 2, 0]}}})");
    for (const std::string& cmd : {"validate " + file.string() + " --layout ", "measure " + file.string() + " --layout "}) {
        test::CliResult r = test::runCli(cmd + layout.string());
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find(layout.string() + ": /entities/desk/position/0: value 1000000000 exceeds the limit of 100000 m"),
                  std::string::npos)
            << r.output;
    }
}

TEST(CliRobustness, NumberOverflowNamesThePath) {
    test::TempDir dir;
    std::string text = scene();
    text.replace(text.find("3200"), 4, "1e400");
    auto file = dir.write("scene.json", text);
    test::CliResult r = test::runCli("validate " + file.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /luminaires/0/flux_lm: number overflow parsing '1e400'"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("json.exception"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace luxplan
