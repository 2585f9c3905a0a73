// Runs one program in its own process group under resource limits, with a
// wall-clock timeout that kills the whole group, and captures its output.
//
// Time is judged in CPU time where a machine's load must not change the
// verdict: RLIMIT_CPU ends a program that computes too long, and a run whose
// programs (with everything they started) all stop using the CPU for
// `idle_seconds` is ended as hung (a sleep, or a wait for what never comes). A
// busy machine slows a program down but never stops it using some CPU, so
// neither limit depends on the load; the wall clock is then only a last resort.
//
// Why: a student's code may crash, loop, sleep, eat memory, fill the disk or
// print without end. None of that may take the grader down or stall it; each
// ending is told apart so that it can be reported precisely.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace whitted::grade {

/// Limits for one run; 0 means "no limit" for every field but wall_seconds.
struct Limits {
    double wall_seconds = 10.0;     // real time, then SIGKILL to the whole process group
    double cpu_seconds = 0.0;       // RLIMIT_CPU: SIGXCPU at the limit (all threads count); with idle_seconds, also
                                    // the whole tree's: a program and everything it started, killed together
    double idle_seconds = 0.0;      // 0, or: the run is hung once its programs used no CPU for this long
    std::size_t address_space = 0;  // RLIMIT_AS in bytes: allocations beyond it fail
    std::size_t file_size = 0;      // RLIMIT_FSIZE in bytes: SIGXFSZ when a file would grow beyond it
    long processes = 0;             // RLIMIT_NPROC: counts all processes and threads of the user; root ignores it
    std::size_t output_bytes = 8192; // stdout and stderr kept; the rest is read and dropped
};

/// A user and group to run as (the grader must be root to switch).
struct Identity {
    unsigned uid = 65534; // nobody
    unsigned gid = 65534; // nogroup
};

/// What to run: argv[0] is looked up in PATH when it has no slash.
struct ProcessSpec {
    std::vector<std::string> argv;
    std::filesystem::path working_directory; // empty: the grader's
    std::vector<std::pair<std::string, std::string>> environment; // added to (or replacing in) the grader's
    Limits limits;
    std::optional<Identity> identity; // switch to this user after the limits are set; empty: stay who we are
    std::vector<int> descriptors;     // handed to the program as descriptors 3, 4, ...; the grader's copies are closed once it started
    bool clean_environment = false;   // start from an empty environment (PATH=/usr/bin:/bin, LC_ALL=C), not the grader's
    std::vector<std::filesystem::path> join_groups; // cgroup.procs files to join before the limits are set (control_group.hpp)
    std::vector<std::byte> syscall_filter; // a seccomp program installed just before exec (syscall_filter.hpp); empty: none
};

/// How a run ended. Core dumps are always off (RLIMIT_CORE = 0).
struct ProcessRun {
    enum class End { exited, signalled, timed_out, failed_to_start };
    End end = End::failed_to_start;
    int exit_code = -1; // for End::exited
    int signal = 0;     // for End::signalled
    std::string output; // stdout and stderr interleaved, at most limits.output_bytes
    bool output_truncated = false;
    double seconds = 0.0; // wall clock
    double cpu_seconds = 0.0; // user and system time of the program and what it started, as last seen alive or reaped
    bool hung = false;        // End::timed_out because the run used no CPU for Limits::idle_seconds
    bool out_of_cpu = false;  // End::timed_out because the program and what it started used more than Limits::cpu_seconds
    std::size_t peak_rss_bytes = 0; // the child's peak resident memory (wait4's ru_maxrss), once reaped
    std::string start_error; // for End::failed_to_start
    bool outlived = false;   // killed because it went on after the first program of run_together ended
};

/// Runs the program and waits for it and everything it started (the process group).
ProcessRun run_process(const ProcessSpec& spec);

/// Runs the programs at once, each in its own process group under its own
/// limits, each to its end or its limits.
std::vector<ProcessRun> run_together(const std::vector<ProcessSpec>& specs);

/// Two programs that work together: once the leader has ended, the follower
/// has `linger_seconds` to end by itself, then is killed (ProcessRun::outlived).
struct ProcessPair {
    ProcessSpec leader;
    ProcessSpec follower;
};

/// Runs the two programs at once; returns (leader, follower) runs.
std::pair<ProcessRun, ProcessRun> run_pair(const ProcessPair& pair, double linger_seconds);

/// Makes this process the reaper of every orphan among its descendants, so that
/// a process that left its group (setsid) still ends up as our child.
void become_subreaper();

/// Kills and reaps every child of this process that is still alive: what a
/// test left behind outside its process group. Returns how many it killed.
int kill_leftover_children();

/// Kills every process of the user `uid` (as that user: kill(-1) until none
/// is left), for when the student's code runs as a user of its own: a fork
/// bomb's processes leave their group faster than a scan of /proc finds them.
void kill_user_processes(unsigned uid);

/// Removes what the user `uid` left where every user may write (/tmp, /var/tmp,
/// /dev/shm, /run/lock, POSIX message queues where /dev/mqueue is mounted: the
/// entries it owns there) and its System V shared memory, message queues and
/// semaphores. Call once its processes are gone. Returns how many.
int remove_user_leftovers(unsigned uid);

/// The number of processes and threads the user owns now (what RLIMIT_NPROC counts).
long processes_of_user(unsigned uid);

/// "SIGSEGV" for SIGSEGV, "signal 77" for a number without a name.
std::string signal_name(int signal);

/// One line: "exited with code 3", "killed by SIGSEGV (Segmentation fault)", "timed out after 10 s".
std::string describe(const ProcessRun& run, const Limits& limits);

} // namespace whitted::grade
