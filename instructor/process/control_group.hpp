// A control group (cgroup) of the grading's own: one memory ceiling and one
// process ceiling for everything the student's code runs at once.
//
// Why: resource limits (process_runner.hpp) bind one process each. A worker
// that forks up to the process limit, each child filling its own 2 GiB of
// address space, could still take the whole machine. In a control group the
// kernel counts the memory and the processes of the group together, and a
// group can be emptied at once after each run. Creating one needs root and a
// writable cgroup hierarchy (v1's memory and pids controllers, or v2 with
// both delegated); elsewhere, as in many containers, make() says why not and
// the grader keeps the per-process limits (instructor/docs/grading.md, "A total budget").
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace whitted::grade {

class ControlGroup {
  public:
    /// A new group under the grader's own, with a memory and a process ceiling;
    /// empty, with the reason in `problem`, where this machine gives none.
    static std::optional<ControlGroup> make(std::size_t memory_bytes, long max_processes, std::string& problem);

    ControlGroup(ControlGroup&& other) noexcept;
    ControlGroup& operator=(ControlGroup&&) = delete;
    ControlGroup(const ControlGroup&) = delete;
    ~ControlGroup(); // kills what is left in the group and removes it

    /// The files a new process writes "0" into to join the group (one per hierarchy).
    std::vector<std::filesystem::path> join_files() const;
    /// Changes the memory ceiling (the compilers of `--jobs` files need more than one test).
    bool set_memory(std::size_t memory_bytes) const;
    /// "cgroup v1" or "cgroup v2", for the instructor.
    const std::string& kind() const { return kind_; }

  private:
    ControlGroup() = default;
    std::string kind_;
    std::vector<std::filesystem::path> folders_; // one per hierarchy (v1: memory, pids; v2: one)
};

/// Kills every process in the groups whose cgroup.procs files are given, until none is left.
void kill_group_processes(const std::vector<std::filesystem::path>& join_files);

} // namespace whitted::grade
