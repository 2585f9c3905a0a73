// FileRecord notices a file that was changed, added or removed, and only within what it watches.
#include "grader/tamper_check.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

using namespace whitted::grade;
namespace fs = std::filesystem;

namespace {

class FileRecordTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() / ("tamper_check_test_" + std::to_string(getpid()));
        fs::remove_all(folder_);
        fs::create_directories(folder_ / "images");
        write("images/reference.png", "reference");
        write("rubric.json", "{}");
        write("libframework.a", "objects");
    }
    void TearDown() override { fs::remove_all(folder_); }

    void write(const std::string& name, const std::string& text) { std::ofstream(folder_ / name) << text; }
    std::optional<std::string> change_since(const FileRecord& before, const std::vector<std::string>& extensions = {}) {
        return before.first_change(FileRecord::of({folder_}, extensions));
    }

    fs::path folder_;
};

} // namespace

TEST_F(FileRecordTest, NothingChangedIsNoChange) {
    EXPECT_EQ(change_since(FileRecord::of({folder_})), std::nullopt);
}

TEST_F(FileRecordTest, RewrittenFileIsNamed) {
    const FileRecord before = FileRecord::of({folder_});
    write("images/reference.png", "hostile");
    const std::optional<std::string> change = change_since(before);
    ASSERT_TRUE(change);
    EXPECT_EQ(*change, (folder_ / "images/reference.png").string() + " was changed");
}

TEST_F(FileRecordTest, SameSizeRewriteIsSeenByItsTime) {
    const FileRecord before = FileRecord::of({folder_});
    fs::last_write_time(folder_ / "rubric.json", fs::last_write_time(folder_ / "rubric.json") + std::chrono::seconds(1));
    EXPECT_NE(change_since(before), std::nullopt);
}

TEST_F(FileRecordTest, AddedAndRemovedFilesAreNamed) {
    const FileRecord before = FileRecord::of({folder_});
    write("images/extra.png", "x");
    EXPECT_EQ(change_since(before), (folder_ / "images/extra.png").string() + " was added");
    fs::remove(folder_ / "images/extra.png");
    fs::remove(folder_ / "rubric.json");
    EXPECT_EQ(change_since(before), (folder_ / "rubric.json").string() + " was removed");
}

TEST_F(FileRecordTest, OnlyTheWatchedExtensionsCount) {
    const FileRecord before = FileRecord::of({folder_}, {".a"});
    write("rubric.json", "{\"changed\": true}");
    EXPECT_EQ(change_since(before, {".a"}), std::nullopt);
    write("libframework.a", "other objects");
    EXPECT_NE(change_since(before, {".a"}), std::nullopt);
}
