// The grader skips the instructor build's update when no file the build may
// read has changed: the tree's fingerprint must change with every such file
// and with nothing else.
#include "grader/builder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace whitted::grade;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

} // namespace

TEST(Builder, TheTreesFingerprintChangesWithEveryFileTheBuildMayRead) {
    const fs::path tree = fs::temp_directory_path() / ("builder_test_" + std::to_string(getpid()));
    write(tree / "CMakeLists.txt", "project(x)\n");
    write(tree / "solution" / "01_ray_casting.cpp", "int x;\n");
    write(tree / "build" / "CMakeCache.txt", "cache\n");
    write(tree / "grading" / ".whitted-grade", "marker\n");
    write(tree / ".git" / "HEAD", "ref\n");
    const std::string before = source_state(tree);
    EXPECT_EQ(source_state(tree), before) << "the same tree";

    // Build folders, graders' output folders and hidden folders are not read by the build.
    write(tree / "build" / "tests" / "check_01", "program\n");
    write(tree / "grading" / "results.json", "{}\n");
    write(tree / ".git" / "HEAD", "another ref\n");
    EXPECT_EQ(source_state(tree), before) << "outside what the build reads";

    write(tree / "solution" / "01_ray_casting.cpp", "int xy;\n");
    const std::string edited = source_state(tree);
    EXPECT_NE(edited, before) << "a file's size changed";
    write(tree / "tests" / "new_test.cpp", "\n");
    const std::string added = source_state(tree);
    EXPECT_NE(added, edited) << "a file was added";
    fs::remove(tree / "tests" / "new_test.cpp");
    EXPECT_EQ(source_state(tree), edited) << "the same files again";
    const fs::path file = tree / "solution" / "01_ray_casting.cpp";
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(1));
    EXPECT_NE(source_state(tree), edited) << "a file's time changed";
    fs::remove_all(tree);
}
