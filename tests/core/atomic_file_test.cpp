// Output files written whole or not at all (core/atomic_file.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>
#include "support/temp_files.h"

namespace luxplan {
namespace {

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary) {
    test::TempDir dir;
    const auto file = dir.path() / "layout.json";
    writeFileAtomically(file, "first");
    EXPECT_EQ(contents(file), "first");
    writeFileAtomically(file, std::string(100000, 'x'));
    EXPECT_EQ(contents(file), std::string(100000, 'x'));
    writeFileAtomically(file, "");
    EXPECT_EQ(contents(file), "");
    int entries = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
        ++entries;
        EXPECT_EQ(e.path(), file);
    }
    EXPECT_EQ(entries, 1);
}

TEST(AtomicFile, AFailureNamesTheFileAndKeepsTheOldOne) {
    test::TempDir dir;
    const auto notAFolder = dir.write("plain", "old");
    try {
        writeFileAtomically(notAFolder / "report.json", "new");
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), (notAFolder / "report.json").string() + ": cannot write (Not a directory)");
    }
    // A target that is a folder: the rename fails, the temporary goes.
    std::filesystem::create_directory(dir.path() / "folder");
    EXPECT_THROW(writeFileAtomically(dir.path() / "folder", "new"), IoError);
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().string().find(".part-"), std::string::npos) << e.path();
    EXPECT_EQ(contents(notAFolder), "old");
}

}  // namespace
}  // namespace luxplan
