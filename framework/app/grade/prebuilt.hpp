// The instructor build whose compiled shared parts a grading build imports.
//
// Why: nearly everything a grading build compiles (the framework, the test
// support, every lab's tests, the reference labs) is the same for every
// submission, and the instructor build `whitted` comes from has compiled it
// already. Importing it (cmake/WhittedGradingPrebuilt.cmake) leaves a cold
// grading build only the student's six files to compile. The parts must be
// current, so the instructor build is brought up to date first; when it cannot
// be used the grader compiles everything itself, as it always did.
#pragma once

#include <filesystem>
#include <string>

namespace whitted::grade {

struct PrebuiltCheck {
    bool usable = false;
    std::string reason; // why not, when not usable
};

/// Brings the target grading_shared_parts of the instructor build `build` up to
/// date (a no-op when nothing changed), under its folder lock; not usable when
/// `build` is not a build of `instructor_tree` with those parts, or they do not build.
PrebuiltCheck update_prebuilt(const std::filesystem::path& build, const std::filesystem::path& instructor_tree, int jobs);

/// The lines "whitted grading: ..." of a configure log, where the tree says whether it imported the parts and why not.
std::string prebuilt_notes(const std::string& configure_log);

} // namespace whitted::grade
