#include "child_process.hpp"

#include <thread>
#include <utility>

#ifdef _WIN32
#include <windows.h>
#else
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __APPLE__
#include <mach-o/dyld.h> // _NSGetExecutablePath
#endif
extern char** environ;
#endif

namespace whitted {

#ifndef _WIN32

struct ChildProcess::Handle {
    pid_t pid = -1;
};

namespace {

ChildExit exit_of(int status) {
    ChildExit result;
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        result.crashed = true;
        result.code = 128 + signal;
        const char* name = strsignal(signal);
        result.reason = "crashed: " + std::string(name ? name : "signal") + " (signal " + std::to_string(signal) + ")";
    } else {
        result.code = WEXITSTATUS(status);
        result.reason = "exit code " + std::to_string(result.code);
    }
    return result;
}

} // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& output) {
    if (argv.empty()) throw ChildStartError("no program to run");
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw ChildStartError("cannot run " + argv[0] + ": " + std::strerror(error));
    handle_ = new Handle{pid};
}

std::optional<ChildExit> ChildProcess::wait_for(std::chrono::milliseconds timeout) {
    if (exit_ || !handle_) return exit_;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        int status = 0;
        const pid_t done = waitpid(handle_->pid, &status, WNOHANG);
        if (done == handle_->pid) {
            exit_ = exit_of(status);
            if (stopped_) exit_->reason = "stopped";
            return exit_;
        }
        if (done < 0 && errno != EINTR) { // not our child any more: nothing to wait for
            exit_ = ChildExit{-1, false, "lost"};
            return exit_;
        }
        if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

void ChildProcess::stop() {
    if (exit_ || !handle_) return;
    stopped_ = true;
    kill(handle_->pid, SIGKILL);
}

std::filesystem::path own_executable() {
#ifdef __APPLE__
    char path[4096];
    std::uint32_t size = sizeof path;
    if (_NSGetExecutablePath(path, &size) != 0) return {};
    return std::filesystem::canonical(path);
#else
    std::error_code error;
    return std::filesystem::read_symlink("/proc/self/exe", error);
#endif
}

#endif // POSIX

ChildProcess::~ChildProcess() {
    if (!handle_) return;
    stop();
    wait();
    delete handle_;
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)), exit_(std::move(other.exit_)), stopped_(other.stopped_) {}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
    if (this != &other) {
        ChildProcess old(std::move(*this));
        handle_ = std::exchange(other.handle_, nullptr);
        exit_ = std::move(other.exit_);
        stopped_ = other.stopped_;
    }
    return *this;
}

ChildExit ChildProcess::wait() {
    for (;;)
        if (std::optional<ChildExit> done = wait_for(std::chrono::hours(1))) return *done;
}

ChildExit run_child(const std::vector<std::string>& argv, const std::filesystem::path& output) {
    return ChildProcess(argv, output).wait();
}

} // namespace whitted
