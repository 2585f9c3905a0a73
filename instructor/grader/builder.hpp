// The instructor build the grader relies on, and what compilers print.
//
// Why: the checkers (the tests with the reference) and the grading kit (what a
// worker is built from) come from the instructor's own CMake build of the
// tree. They must be current, so the grader builds their target there before
// each grading, under the folder's lock, unless no file of the tree and none
// of what the last update made has changed since (path, size and time).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace whitted::grade {

struct BuildStep {
    bool ok = false;
    std::string log; // what the build tools and the compiler printed (the start of it)
};

/// Builds the target grading_parts of the instructor build `build` (a Release
/// build of `instructor_tree` with its tests), unless nothing changed since its
/// last update (BUILD/grading-parts.state). Throws std::runtime_error saying
/// why it cannot be used.
void update_instructor_build(const std::filesystem::path& build, const std::filesystem::path& instructor_tree, int jobs);

/// A fingerprint of every file of the tree the build may read (path, size,
/// modification time): all but build folders (with a CMakeCache.txt), graders'
/// output folders (with a .whitted-grade file) and hidden ones (.git).
std::string source_state(const std::filesystem::path& tree);

/// The compiler's first errors in a build log, without build-tool noise and
/// with the given paths replaced (absolute -> shown).
std::string first_compiler_errors(const std::string& log, const std::vector<std::pair<std::string, std::string>>& paths);

/// The folder a CMake build folder was configured from, or empty if it has no CMakeCache.txt.
std::filesystem::path configured_source(const std::filesystem::path& build);

/// The value of a CMake cache entry ("CMAKE_BUILD_TYPE" gives "Release"), or empty when there is none.
std::string cache_entry(const std::filesystem::path& build, const std::string& name);

/// The CMAKE_BUILD_TYPE the instructor build must have: the reference pictures are made with it.
inline constexpr const char* grading_build_type = "Release";

} // namespace whitted::grade
