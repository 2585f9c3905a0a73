// How far the student's code is fenced in, and the command line that does it.
//
// Why: the student's code runs in two kinds of processes, the compiler (its
// #include and asm(".incbin") read files) and the worker (the lab functions,
// answering the checker). Limits and a process group of their own
// (process_runner.hpp) stop them from crashing, stalling or flooding the
// grader; these fences keep them from reading the answers (the solution, the
// tests, the reference pictures, the checker and every program holding
// reference code) and from touching anything of the grader's:
//   - bubblewrap (Debian `bubblewrap`), where it can create namespaces: a
//     private view of the file system with only the system folders and the
//     paths a run is given (read-only, one writable folder at most), its own
//     process ids (the checker is invisible), no network.
//   - a grader running as root runs them as a user id of the grading's own
//     (no account, no other process has it): the grader's files are then
//     protected by their permissions, RLIMIT_NPROC binds, and every process of
//     that user can be killed after each run without touching anyone else's.
//   - a control group of the grading's own where the machine gives one
//     (control_group.hpp): one memory and process ceiling for all of it.
//   - after each run, whatever it left running outside its process group is
//     killed (the grader is a child subreaper).
// Without bubblewrap, the answers are safe only when other users cannot read
// them; make_sandbox probes that as the student code's user, and a machine where the student's code could
// read them grades only when the instructor allows it explicitly.
#pragma once

#include "process/process_runner.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace whitted::grade {

enum class SandboxChoice { automatic, bubblewrap, none };

struct Sandbox {
    bool bubblewrap = false;
    std::optional<Identity> identity; // a user id of the grading's own, when the grader is root
    long processes = 0;               // RLIMIT_NPROC for the student's code; 0: none
    std::vector<std::filesystem::path> groups; // cgroup.procs files of the grading's control group, if it has one
    std::vector<std::string> bwrap_prefix; // bwrap and its options for the system folders
    std::string mode;                      // "sandbox", "users" or "exposed"
    std::vector<std::string> fences;       // for the instructor, without paths: the fences that are up
    std::vector<std::string> gaps;         // for the instructor: the fences that are not, and why
    std::string exposed;                   // for the instructor: what the student's code could read, or empty
    std::string bwrap_error;               // for the instructor: what bwrap said when it failed
    std::vector<std::byte> syscall_filter; // the workers' seccomp program (syscall_filter.hpp); empty where none could be made

    /// The spec that runs `spec` inside the fences, seeing `readable` (read-only) and `writable` (if given) besides the system.
    /// Without `writable` it is a worker, which also gets the system call filter.
    ProcessSpec wrap(ProcessSpec spec, const std::vector<std::filesystem::path>& readable,
                     const std::optional<std::filesystem::path>& writable) const;

    /// After runs of the student's code: kills every process of its control
    /// group and of its user (when it has them), then whatever is left among
    /// the grader's children, and removes what its user left where every user
    /// may write, so that no run passes anything on to the next.
    void end_runs() const;

    /// One line for the instructor: "sandbox mode: fence, fence; gap".
    std::string description() const;

    /// How the wrapped program ended: bubblewrap reports a program killed by
    /// signal S as exit code 128 + S, which becomes the signal again.
    ProcessRun unwrap(ProcessRun run) const;
};

/// Works out which fences this machine allows. `secrets` are files the
/// student's code must not read (a sample of each kind: a solution file, a
/// hidden test, the checker, the grader's own program); `scratch` is a folder
/// of the grader's that the probes may run in. Throws std::runtime_error when
/// bubblewrap is asked for and does not work, or when the answers would be
/// readable and `allow_exposed` is false. `max_processes` > 0 overrides the process limit.
Sandbox make_sandbox(SandboxChoice choice, const std::vector<std::filesystem::path>& secrets,
                     const std::filesystem::path& scratch, long max_processes, bool allow_exposed);

/// Hands a folder the grader made to the identity the student's code runs as, so that it can write in it.
void give_folder(const Sandbox& sandbox, const std::filesystem::path& folder);

} // namespace whitted::grade
