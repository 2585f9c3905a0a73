// free_own_file (framework/app/child_process.hpp), Windows only: the running program moves its own file aside and
// puts a copy in its place. A program of its own, with this one test: CTest runs tests side by side, and another
// test of the same program starting while its file is renamed would fail by this test's doing, not its own.
#include "child_process.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace whitted;

// Windows refuses to open a running program's file for writing (a build that relinks it fails) until the
// program moves it aside: then a copy is in its place, which a build may rewrite.
TEST(FreeOwnFile, LetsABuildRewriteTheRunningProgramsFile) {
    const std::filesystem::path self = own_executable();
    const auto size = std::filesystem::file_size(self);
    // A copy an earlier run left behind, stopped before it could put the copy in its place.
    const std::filesystem::path left = self.parent_path() / (self.stem().string() + ".copy-1.exe");
    std::ofstream(left, std::ios::binary) << "left by an earlier run";
    ASSERT_TRUE(std::filesystem::exists(left));
    free_own_file();
    ASSERT_TRUE(std::filesystem::is_regular_file(self)) << self;
    EXPECT_EQ(std::filesystem::file_size(self), size) << "not a copy of the program";
    bool moved = false;
    bool copy_left = false;
    for (const auto& entry : std::filesystem::directory_iterator(self.parent_path())) {
        const std::string name = entry.path().filename().string();
        moved = moved || name.starts_with(self.stem().string() + ".running-");
        copy_left = copy_left || name.starts_with(self.stem().string() + ".copy-");
    }
    EXPECT_TRUE(moved) << "the running program was not moved aside";
    EXPECT_FALSE(copy_left) << "a copy is left under its own name: an earlier run's, or this one's not put in place";
    std::ofstream rewrite(self, std::ios::binary | std::ios::app);
    EXPECT_TRUE(rewrite.is_open()) << "the program's file is still locked";
}
