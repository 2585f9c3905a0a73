// Running another program and waiting for it: the second of the two platform files (platform.cpp is the first),
// where Windows and POSIX systems spell process creation differently.
//
// Why: `whitted explore` renders with the student's labs in a child process, so that a lab that crashes or
// loops forever cannot take the page down, and so that the labs can be rebuilt while the page is served
// (Windows cannot overwrite a running program). The child's standard output and error go to a file, its
// standard input reads nothing.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted {

/// How a child process ended.
struct ChildExit {
    int code = 0;         // its exit code; on Windows, the exception code of a crash (0xC0000005, ...)
    bool crashed = false; // killed by a signal (POSIX) or ended by an exception (Windows), not by exiting
    std::string reason;   // "exit code 2", "crashed: segmentation fault (signal 11)", "stopped"

    bool success() const { return !crashed && code == 0; }
};

/// A program that could not be started (not found, not executable).
struct ChildStartError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// One running child process. Destroying it stops the child (if still running) and waits for it.
class ChildProcess {
  public:
    /// Starts `argv[0]` (a path, not searched on the PATH) with arguments argv[1..]; its standard output and error
    /// both go to `output` (created or emptied). Throws ChildStartError.
    ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& output);
    ~ChildProcess();
    ChildProcess(ChildProcess&& other) noexcept;
    ChildProcess& operator=(ChildProcess&& other) noexcept;
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    /// How the child ended, if it has; waits at most `timeout` (zero: only looks).
    std::optional<ChildExit> wait_for(std::chrono::milliseconds timeout);
    /// Waits until the child ends.
    ChildExit wait();
    /// Ends the child at once (nothing if it has ended); its exit then says "stopped".
    void stop();

  private:
    struct Handle;
    Handle* handle_ = nullptr;
    std::optional<ChildExit> exit_;
    bool stopped_ = false;
};

/// Runs argv to its end (see ChildProcess) and returns how it ended.
ChildExit run_child(const std::vector<std::string>& argv, const std::filesystem::path& output);

/// The path of the running program's own executable file.
std::filesystem::path own_executable();

/// Lets a build rewrite this program's file while it runs. Windows locks the file of a running program (a build
/// that relinks it fails), but lets it be renamed: the running program moves aside, to NAME.running-PID.exe
/// beside it, and a copy takes its place. The files earlier runs left are removed (not a running run's).
/// Nothing on other systems, where a build writes a new file and a running program keeps its old one.
void free_own_file();

/// Lets the programs this one starts find their libraries in `folder` too (Windows: DLLs beside a program copied
/// elsewhere; the folder goes first on the PATH they inherit). Nothing on other systems.
void add_library_folder(const std::filesystem::path& folder);

} // namespace whitted
