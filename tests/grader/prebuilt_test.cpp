// The grader imports an instructor build's shared parts only from a build of
// the same tree with the grading build type, and reads what the tree decided.
#include "grade/builder.hpp"
#include "grade/prebuilt.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace whitted::grade;

namespace {

class PrebuiltTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder = std::filesystem::temp_directory_path() / ("prebuilt_test_" + std::to_string(getpid()));
        tree = folder / "tree";
        build = folder / "build";
        std::filesystem::create_directories(tree);
        std::filesystem::create_directories(build);
    }
    void TearDown() override { std::filesystem::remove_all(folder); }

    // A CMakeCache.txt as CMake writes it, with the given source folder and build type.
    void write_cache(const std::filesystem::path& source, const std::string& build_type) const {
        std::ofstream(build / "CMakeCache.txt") << "# This is the CMakeCache file.\n"
                                                << "//Choose the type of build\n"
                                                << "CMAKE_BUILD_TYPE:STRING=" << build_type << "\n"
                                                << "CMAKE_BUILD_TYPE-ADVANCED:INTERNAL=1\n"
                                                << "WHITTED_GRADING:BOOL=OFF\n"
                                                << "CMAKE_HOME_DIRECTORY:INTERNAL=" << source.string() << "\n";
    }

    std::filesystem::path folder, tree, build;
};

} // namespace

TEST_F(PrebuiltTest, CacheEntriesAreReadByTheirExactName) {
    write_cache(tree, "Release");
    EXPECT_EQ(cache_entry(build, "CMAKE_BUILD_TYPE"), "Release");
    EXPECT_EQ(cache_entry(build, "WHITTED_GRADING"), "OFF");
    EXPECT_EQ(cache_entry(build, "WHITTED"), "");
    EXPECT_EQ(cache_entry(build, "CMAKE_BUILD_TYPE-ADVANCED"), "1");
    EXPECT_EQ(configured_source(build), tree);
    EXPECT_EQ(cache_entry(folder / "nowhere", "CMAKE_BUILD_TYPE"), "");
}

TEST_F(PrebuiltTest, AFolderWithoutACMakeCacheIsNotUsed) {
    const PrebuiltCheck check = update_prebuilt(build, tree, 1);
    EXPECT_FALSE(check.usable);
    EXPECT_NE(check.reason.find("not a CMake build folder"), std::string::npos) << check.reason;
}

TEST_F(PrebuiltTest, ABuildOfAnotherTreeIsNotUsed) {
    write_cache(folder / "other", "Release");
    const PrebuiltCheck check = update_prebuilt(build, tree, 1);
    EXPECT_FALSE(check.usable);
    EXPECT_NE(check.reason.find("was configured from"), std::string::npos) << check.reason;
}

TEST_F(PrebuiltTest, ADebugBuildIsNotUsedNorBuilt) {
    write_cache(tree, "Debug");
    const PrebuiltCheck check = update_prebuilt(build, tree, 1);
    EXPECT_FALSE(check.usable);
    EXPECT_NE(check.reason.find("is a Debug build, grading builds are Release"), std::string::npos) << check.reason;
    EXPECT_FALSE(std::filesystem::exists(build / ".whitted-grade.lock")); // refused before locking and building
}

TEST_F(PrebuiltTest, ABuildWithoutTheExportedPartsIsNotUsed) {
    write_cache(tree, "Release");
    const PrebuiltCheck check = update_prebuilt(build, tree, 1);
    EXPECT_FALSE(check.usable);
    EXPECT_NE(check.reason.find("exports no grading parts"), std::string::npos) << check.reason;
}

TEST(PrebuiltNotes, AreTheTreesOwnLinesOfTheConfigureLog) {
    const std::string log = "-- The CXX compiler identification is GNU 12.2.0\n"
                            "-- whitted grading: using the prebuilt shared parts of /b\n"
                            "-- Configuring done\n";
    EXPECT_EQ(prebuilt_notes(log), "using the prebuilt shared parts of /b\n");
    EXPECT_EQ(prebuilt_notes("-- Configuring done\n"), "");
}
