// Where the grader finds a submission's lab files: the shapes students submit
// in (the files alone, a project tree, a zipped folder), and the ambiguous ones.
#include "grader/submission.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

using namespace whitted::grade;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kLabs = {"01_ray_casting", "02_shadows", "03_blinn_phong"};

// A fresh empty folder for one test.
class Submission : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("submission_test_" + std::to_string(getpid()) + "_" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override { fs::remove_all(root_); }

    // Writes the named lab files into `folder` (relative to the submission).
    void put(const std::string& folder, const std::vector<std::string>& labs) {
        fs::create_directories(root_ / folder);
        for (const std::string& lab : labs) std::ofstream(root_ / folder / (lab + ".cpp")) << "// " << lab << "\n";
    }
    std::string ambiguity() {
        try {
            find_lab_folder(root_, kLabs);
        } catch (const AmbiguousSubmission& error) {
            return error.what();
        }
        return "no error";
    }
    fs::path root_;
};

} // namespace

TEST_F(Submission, TheFilesAtTheTop) {
    put(".", kLabs);
    const LabFolder found = find_lab_folder(root_, kLabs);
    EXPECT_EQ(found.folder, root_);
    EXPECT_EQ(found.shown, "");
    EXPECT_EQ(found.files, 3);
}

TEST_F(Submission, AProjectTreeWithLabs) {
    put("labs", kLabs);
    fs::create_directories(root_ / "tests" / "labs" / "01_ray_casting"); // a folder named like a lab is not a lab file
    const LabFolder found = find_lab_folder(root_, kLabs);
    EXPECT_EQ(found.folder, root_ / "labs");
    EXPECT_EQ(found.shown, "labs/");
}

// Gradescope unzips a zipped folder as one folder at the top: my-labs/labs/*.cpp.
TEST_F(Submission, AZippedProjectOneFolderDown) {
    put("my-labs/labs", {"01_ray_casting", "02_shadows"});
    fs::create_directories(root_ / "__MACOSX" / "my-labs" / "labs");
    std::ofstream(root_ / "__MACOSX" / "my-labs" / "labs" / "._01_ray_casting.cpp") << "resource fork";
    const LabFolder found = find_lab_folder(root_, kLabs);
    EXPECT_EQ(found.folder, root_ / "my-labs" / "labs");
    EXPECT_EQ(found.shown, "my-labs/labs/");
    EXPECT_EQ(found.files, 2);
}

TEST_F(Submission, AZippedFolderOfFiles) {
    put("lab-files", kLabs);
    EXPECT_EQ(find_lab_folder(root_, kLabs).shown, "lab-files/");
}

TEST_F(Submission, HiddenFoldersAndMacOsFoldersAreNotSearched) {
    put("labs", kLabs);
    put(".git/old", kLabs);
    put("__MACOSX", kLabs);
    EXPECT_EQ(find_lab_folder(root_, kLabs).shown, "labs/");
}

// A folder that is a link may point at the solution: it is not followed.
TEST_F(Submission, AFolderThatIsALinkIsNotSearched) {
    put("real", kLabs);
    fs::create_directory_symlink(root_ / "real", root_ / "link");
    EXPECT_EQ(find_lab_folder(root_, kLabs).shown, "real/");
}

TEST_F(Submission, NoLabFilesAnywhere) {
    std::ofstream(root_ / "notes.txt") << "hello";
    const LabFolder found = find_lab_folder(root_, kLabs);
    EXPECT_EQ(found.folder, root_);
    EXPECT_EQ(found.files, 0);
}

TEST_F(Submission, FilesInTwoPlacesAreNamedEachWithTheirCount) {
    put("labs", kLabs);
    put("backup/labs", {"02_shadows"});
    EXPECT_EQ(ambiguity(), "lab files were found in 2 places: labs/ (3 files) and backup/labs/ (1 file). "
                           "Keep one copy of each file, all in one folder, and submit again.");
}

TEST_F(Submission, FilesSplitBetweenTheTopAndLabs) {
    put(".", {"01_ray_casting"});
    put("labs", {"02_shadows", "03_blinn_phong"});
    put("old", {"03_blinn_phong"});
    EXPECT_EQ(ambiguity(), "lab files were found in 3 places: the top folder (1 file), labs/ (2 files) and old/ (1 file). "
                           "Keep one copy of each file, all in one folder, and submit again.");
}

// Copying names a missing file where the student put the others, and puts the untouched stub in its place.
TEST_F(Submission, AMissingFileIsNamedWhereTheOthersAre) {
    put("my-labs/labs", {"01_ray_casting", "03_blinn_phong"});
    const LabFolder found = find_lab_folder(root_, kLabs);
    const fs::path stubs = root_.string() + "_stubs", copied = root_.string() + "_copied";
    fs::create_directories(stubs);
    for (const std::string& lab : kLabs) std::ofstream(stubs / (lab + ".cpp")) << "// stub\n";
    const auto refused = copy_lab_files(found, stubs, copied, kLabs);
    std::ifstream copy(copied / "02_shadows.cpp");
    const std::string text((std::istreambuf_iterator<char>(copy)), std::istreambuf_iterator<char>());
    fs::remove_all(stubs);
    fs::remove_all(copied);
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused.at("02_shadows"), "the submission has no my-labs/labs/02_shadows.cpp");
    EXPECT_EQ(text, "// stub\n");
}

// A browser's "(1)", another case or another extension: the near miss is named with what to do, and not graded
// (the grader takes the exact names only, so that no file is graded by a guess).
TEST_F(Submission, ANearMissOfAFileNameIsNamedAndNotTaken) {
    put("labs", {"01_ray_casting"});
    std::ofstream(root_ / "labs" / "02_shadows (1).cpp") << "// renamed by a browser\n";
    std::ofstream(root_ / "labs" / "03_Blinn_Phong.cpp") << "// another case\n";
    std::ofstream(root_ / "labs" / "03_blinn_phong.cpp.txt") << "// another extension\n";
    const fs::path stubs = root_.string() + "_stubs", copied = root_.string() + "_copied";
    fs::create_directories(stubs);
    for (const std::string& lab : kLabs) std::ofstream(stubs / (lab + ".cpp")) << "// stub\n";
    const auto refused = copy_lab_files(find_lab_folder(root_, kLabs), stubs, copied, kLabs);
    std::ifstream copy(copied / "02_shadows.cpp");
    const std::string text((std::istreambuf_iterator<char>(copy)), std::istreambuf_iterator<char>());
    fs::remove_all(stubs);
    fs::remove_all(copied);
    ASSERT_EQ(refused.size(), 2u);
    EXPECT_EQ(refused.at("02_shadows"), "the submission has no labs/02_shadows.cpp; labs/02_shadows (1).cpp looks like it: "
                                        "rename it 02_shadows.cpp exactly, and submit again");
    EXPECT_EQ(refused.at("03_blinn_phong"), "the submission has no labs/03_blinn_phong.cpp; labs/03_Blinn_Phong.cpp, "
                                            "labs/03_blinn_phong.cpp.txt look like it: keep one, named 03_blinn_phong.cpp "
                                            "exactly, and submit again");
    EXPECT_EQ(text, "// stub\n");
}

TEST_F(Submission, NoLabFileAnywhereSaysWhereTheGraderLooked) {
    const fs::path stubs = root_.string() + "_stubs", copied = root_.string() + "_copied";
    fs::create_directories(stubs);
    for (const std::string& lab : kLabs) std::ofstream(stubs / (lab + ".cpp")) << "// stub\n";
    const auto refused = copy_lab_files(find_lab_folder(root_, kLabs), stubs, copied, kLabs);
    fs::remove_all(stubs);
    fs::remove_all(copied);
    ASSERT_EQ(refused.size(), 3u);
    EXPECT_NE(refused.at("01_ray_casting").find("at the top of the submission, in labs/, or one folder down"), std::string::npos)
        << refused.at("01_ray_casting");
}

// A submission that is itself a link (to the solution, say) is refused, however it is written; a link above it is the
// instructor's own path and is followed.
TEST_F(Submission, ASubmissionThatIsALinkIsRefused) {
    put("real", kLabs);
    fs::create_directory_symlink(root_ / "real", root_ / "alice");
    for (const char* written : {"alice", "alice/", "alice//", "alice/.", "./alice"}) {
        const std::optional<std::string> why = linked_submission(root_ / written);
        ASSERT_TRUE(why) << written;
        EXPECT_EQ(*why, "alice is a symbolic link, which the grader does not follow (it could lead to any folder of the grading "
                        "machine): grade the folder itself")
            << written;
    }
    EXPECT_FALSE(linked_submission(root_ / "real"));
    EXPECT_FALSE(linked_submission(root_ / "real/"));
    fs::create_directories(root_ / "real" / "bob");
    fs::create_directory_symlink(root_ / "real", root_ / "class");
    EXPECT_FALSE(linked_submission(root_ / "class" / "bob")) << "a link above the submission is the instructor's";
}
