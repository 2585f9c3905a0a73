// How far a submission's tests are fenced in, and the command line that does it.
//
// Why: a test program runs the student's code. Limits and a process group of
// its own (process_runner.hpp) stop it from crashing, stalling or flooding the
// grader, but not from reading the solution, writing the instructor's files or
// starting processes without end. Three more fences close those, each where
// the machine allows it:
//   - bubblewrap (Debian `bubblewrap`), when installed: a private view of the
//     file system with only the system, the test program, the tests' scenes
//     and reference images (read-only; the solution and the test sources are
//     not there) and the test's own folder (writable); no network.
//   - a grader running as root runs the tests as user nobody, so that
//     RLIMIT_NPROC bounds their processes and the instructor's files are
//     read-only to them; an ordinary user gets RLIMIT_NPROC over what it runs.
//   - after each test, whatever it left running outside its process group is
//     killed (the grader is a child subreaper).
// The mode that ran is one line in results.json and report.html.
#pragma once

#include "grade/process_runner.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace whitted::grade {

enum class SandboxChoice { automatic, bubblewrap, none };

/// What the tests need to see: everything else is hidden inside bubblewrap.
struct SandboxPaths {
    std::filesystem::path instructor_tree; // its scenes/ and tests/ are shown read-only, minus the sources
    std::filesystem::path programs;        // the folder of the test programs, shown read-only
    std::filesystem::path out;             // the grading output; each test may write its own folder
};

struct Sandbox {
    bool bubblewrap = false;
    std::optional<Identity> identity; // nobody, when the grader is root and nobody can reach the files
    long processes = 0;               // RLIMIT_NPROC for the tests; 0: none (root without nobody)
    std::vector<std::string> bwrap_prefix; // bwrap and its options up to the writable folder
    std::string description;               // one line without paths: which fences are up
    std::string unreachable;               // for the instructor: the path user nobody could not reach
    std::string bwrap_error;               // for the instructor: what bwrap said when it failed

    /// The spec that runs `spec` inside the fences; `writable` is the only folder it may write.
    ProcessSpec wrap(ProcessSpec spec, const std::filesystem::path& writable) const;

    /// How the wrapped program ended: bubblewrap reports a test killed by
    /// signal S as exit code 128 + S, which becomes the signal again.
    ProcessRun unwrap(ProcessRun run) const;
};

/// Works out which fences this machine allows. Throws GraderFailure when
/// bubblewrap is asked for and does not work. `max_processes` > 0 overrides the
/// process limit.
Sandbox make_sandbox(SandboxChoice choice, const SandboxPaths& paths, long max_processes);

/// Hands a folder the grader made to the identity the tests run as, so that they can write in it.
void give_folder(const Sandbox& sandbox, const std::filesystem::path& folder);

} // namespace whitted::grade
