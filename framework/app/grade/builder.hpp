// Builds a submission against the instructor tree with CMake: configure once
// with WHITTED_GRADING=ON, then one target at a time, so that a compile error
// in one lab fails only what needs that lab.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace whitted::grade {

struct BuildFolder {
    std::filesystem::path instructor_tree; // the CMake source tree
    std::filesystem::path build;           // the CMake build folder (may be a reused cache)
    std::filesystem::path labs;            // the copied lab files: WHITTED_LABS_DIR
    int jobs = 2;
    double timeout_seconds = 900;          // per CMake call
    std::filesystem::path prebuilt;        // an instructor build to import the shared parts from, or empty (prebuilt.hpp)
};

struct BuildStep {
    bool ok = false;
    std::string log; // what CMake and the compiler printed (the start of it)
};

/// Configures (or re-configures) the build folder, importing the shared parts from
/// `prebuilt` when set. Uses Ninja for a new folder when it is installed.
BuildStep configure(const BuildFolder& folder);

/// Builds the targets.
BuildStep build_targets(const BuildFolder& folder, const std::vector<std::string>& targets);

/// The compiler's first errors in a build log, without build-tool noise and
/// with the given paths replaced (absolute -> shown).
std::string first_compiler_errors(const std::string& log, const std::vector<std::pair<std::string, std::string>>& paths);

/// The folder a CMake build folder was configured from, or empty if it has no CMakeCache.txt.
std::filesystem::path configured_source(const std::filesystem::path& build);

/// The value of a CMake cache entry ("WHITTED_GRADING" gives "ON"), or empty when there is none.
std::string cache_entry(const std::filesystem::path& build, const std::string& name);

/// The CMAKE_BUILD_TYPE of every grading build.
inline constexpr const char* grading_build_type = "Release";

} // namespace whitted::grade
