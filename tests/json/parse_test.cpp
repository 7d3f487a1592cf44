// Safe JSON input: nesting depth, numbers beyond a double and non-regular files are
// refused with their JSON path, never as a library's bare exception.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <luxplan/core/limits.h>
#include <luxplan/json/parse.h>
#include "support/temp_files.h"

namespace luxplan::json {
namespace {

std::vector<std::string> problems(const std::string& text) {
    DiagnosticSink sink;
    sink.file = "f.json";
    auto root = parseJson(text, sink);
    std::vector<std::string> out;
    for (const auto& d : sink.diagnostics) out.push_back(d.str());
    if (out.empty()) {
        EXPECT_TRUE(root.has_value());
    }
    return out;
}

TEST(ParseJson, NestingDepthLimit) {
    std::string ok(limits::kMaxJsonDepth, '['), tooDeep(limits::kMaxJsonDepth + 1, '[');
    ok += std::string(limits::kMaxJsonDepth, ']');
    tooDeep += std::string(limits::kMaxJsonDepth + 1, ']');
    EXPECT_TRUE(problems(ok).empty());
    auto p = problems(tooDeep);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NE(p[0].find("nesting depth 129 (arrays and objects inside each other) exceeds the limit of 128"), std::string::npos);
    // A million levels: refused at the first level too many.
    std::string huge(1000000, '[');
    EXPECT_EQ(problems(huge).size(), 1u);
    EXPECT_EQ(problems(R"({"a": {"b": [)" + std::string(200, '[')).front().rfind("f.json: /a/b/0/0/0/", 0), 0u);
}

TEST(ParseJson, NumberOverflowNamesItsPath) {
    EXPECT_EQ(problems(R"({"a": [1, 2, 1e400]})"),
              std::vector<std::string>{"f.json: /a/2: number overflow parsing '1e400' (the largest number is about 1.8e308)"});
    EXPECT_EQ(problems(R"({"a": {"b": -1e999}})"),
              std::vector<std::string>{"f.json: /a/b: number overflow parsing '-1e999' (the largest number is about 1.8e308)"});
}

TEST(ParseJson, SyntaxAndDuplicates) {
    EXPECT_EQ(problems("{\"a\": 1,\n \"a\": 2}"), std::vector<std::string>{"f.json: /a: duplicate key (JSON objects need unique keys)"});
    auto p = problems("{\"a\": }");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].rfind("f.json: /: malformed JSON at line 1, column 7", 0), 0u) << p[0];
}

TEST(ReadInputFile, RegularFilesOnlyWithinTheSizeLimit) {
    test::TempDir dir;
    DiagnosticSink sink;
    EXPECT_EQ(readInputFile(sink, dir.write("a.json", "{}"), 100), std::optional<std::string>("{}"));
    EXPECT_FALSE(readInputFile(sink, dir.write("b.json", std::string(101, ' ')), 100));
    auto fifo = dir.path() / "fifo.json";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_FALSE(readInputFile(sink, fifo, 100));
    EXPECT_FALSE(readInputFile(sink, "/dev/zero", 100));
    EXPECT_FALSE(readInputFile(sink, dir.path() / "missing.json", 100));
    ASSERT_EQ(sink.diagnostics.size(), 4u);
    EXPECT_EQ(sink.diagnostics[0].message, "file of 101 bytes exceeds the limit of 100 bytes");
    EXPECT_EQ(sink.diagnostics[1].message, "not a regular file (a folder, FIFO or device cannot be read)");
    EXPECT_EQ(sink.diagnostics[2].message, "not a regular file (a folder, FIFO or device cannot be read)");
    EXPECT_EQ(sink.diagnostics[3].message, "cannot open the file");
}

}  // namespace
}  // namespace luxplan::json
