// An exclusive advisory lock on a build folder, held for the object's lifetime.
//
// Why: two graders may run at once (one per terminal, or a batch script and an
// instructor), and CMake and the build tools do not expect two builds in one
// folder at the same time. Each grader takes the lock of a folder it builds in:
// the instructor build whose checkers and grading kit it brings up to date.
#pragma once

#include <filesystem>

namespace whitted::grade {

class FolderLock {
public:
    /// Creates the folder if needed and waits for its lock file (.whitted-grade.lock); does without a lock when the file cannot be opened.
    explicit FolderLock(const std::filesystem::path& folder);
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int fd_ = -1;
};

} // namespace whitted::grade
