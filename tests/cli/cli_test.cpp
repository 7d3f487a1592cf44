// The command line contract: exit codes and FILE: /json/path: message lines.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sys/wait.h>

#include "support/temp_files.h"

namespace luxplan {
namespace {

struct Result {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

Result run(const std::string& args) {
    std::string command = std::string(LUXPLAN_CLI) + " " + args + " 2>&1";
    Result r;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer;
    size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
    int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

const std::string kDemo = std::string(LUXPLAN_SOURCE_DIR) + "/scenes/demo/office.json";

TEST(Cli, ValidateAcceptsTheBundledScene) {
    Result r = run("validate " + kDemo);
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(Cli, ValidateReportsEveryErrorAndFails) {
    test::TempDir dir;
    auto file = dir.write("bad.json", R"({"luxplan": 1, "materials": {"m": {"type": "diffuse", "reflectance": 2}},
        "luminaires": [{"name": "l", "shape": "rect", "center": [0,0,3], "size": [1,1], "flux_lm": -1}]})");
    Result r = run("validate " + file.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(file.string() + ": /materials/m/reflectance: value 2 outside [0, 1]"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(file.string() + ": /luminaires/0/flux_lm: value -1 outside >= 0"), std::string::npos)
        << r.output;
}

TEST(Cli, MalformedJsonAndMissingFile) {
    test::TempDir dir;
    auto file = dir.write("broken.json", "{\"luxplan\": 1,,}");
    Result r = run("validate " + file.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find(file.string() + ": /: malformed JSON at line 1, column 15"), std::string::npos) << r.output;
    r = run("validate " + (dir.path() / "none.json").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("none.json: /: cannot open the file"), std::string::npos) << r.output;
}

TEST(Cli, InfoSummarizesTheScene) {
    Result r = run("info " + kDemo);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* part : {"rooms: 1, openings: 3", "luminaires: 6 fixed", "entities: 24", "samplers: 12", "constraints: 28"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
}

TEST(Cli, UnknownCommandFails) {
    EXPECT_NE(run("frobnicate").exitCode, 0);
    EXPECT_NE(run("validate").exitCode, 0);
}

}  // namespace
}  // namespace luxplan
