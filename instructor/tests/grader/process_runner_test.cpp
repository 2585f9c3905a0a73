// The process runner tells every way a child can end apart, and survives all of them.
#include "process/control_group.hpp"
#include "process/process_runner.hpp"
#include "process/syscall_filter.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <optional>
#include <random>
#include <sstream>
#include <sys/socket.h>
#include <sys/wait.h>
#include <thread>
#include <vector>

using namespace whitted::grade;

namespace {

ProcessRun run_child(std::vector<std::string> arguments, Limits limits = {}) {
    arguments.insert(arguments.begin(), MISBEHAVING_CHILD);
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("runner_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);
    ProcessRun run = run_process({arguments, folder, {{"WHITTED_RUNNER_TEST", "42"}}, limits, {}, {}, false, {}, {}});
    std::filesystem::remove_all(folder);
    return run;
}

Limits short_limits() {
    Limits limits;
    limits.wall_seconds = 1.0;
    return limits;
}

} // namespace

TEST(ProcessRunner, ExitCodeIsReported) {
    const ProcessRun run = run_child({"exit", "3"});
    EXPECT_EQ(run.end, ProcessRun::End::exited);
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_EQ(describe(run, {}), "exited with code 3");
}

TEST(ProcessRunner, SegfaultIsASignalNamedSIGSEGV) {
    const ProcessRun run = run_child({"segfault"});
    ASSERT_EQ(run.end, ProcessRun::End::signalled);
    EXPECT_EQ(signal_name(run.signal), "SIGSEGV");
    EXPECT_EQ(describe(run, {}).rfind("killed by SIGSEGV", 0), 0u);
}

TEST(ProcessRunner, AbortIsSIGABRT) {
    const ProcessRun run = run_child({"abort"});
    ASSERT_EQ(run.end, ProcessRun::End::signalled);
    EXPECT_EQ(run.signal, SIGABRT);
}

TEST(ProcessRunner, EndlessLoopTimesOutOnTheWallClock) {
    const ProcessRun run = run_child({"loop"}, short_limits());
    EXPECT_EQ(run.end, ProcessRun::End::timed_out);
    EXPECT_LT(run.seconds, 3.0);
    EXPECT_EQ(describe(run, short_limits()), "did not finish within 1 s and was killed");
}

TEST(ProcessRunner, EndlessLoopHitsTheCpuLimit) {
    Limits limits;
    limits.wall_seconds = 10.0;
    limits.cpu_seconds = 1.0;
    const ProcessRun run = run_child({"loop"}, limits);
    ASSERT_EQ(run.end, ProcessRun::End::signalled);
    EXPECT_EQ(run.signal, SIGXCPU);
}

TEST(ProcessRunner, SleepingChildIsKilledAtTheTimeout) {
    const ProcessRun run = run_child({"sleep"}, short_limits());
    EXPECT_EQ(run.end, ProcessRun::End::timed_out);
    EXPECT_LT(run.seconds, 3.0);
}

// A sleeping child uses no CPU: with an idle limit it is ended as hung long before the wall clock.
TEST(ProcessRunner, ASleepingChildIsHungOnceItUsedNoCpuForTheIdleLimit) {
    Limits limits;
    limits.wall_seconds = 30.0;
    limits.idle_seconds = 0.5;
    const ProcessRun run = run_child({"sleep"}, limits);
    EXPECT_EQ(run.end, ProcessRun::End::timed_out);
    EXPECT_TRUE(run.hung);
    EXPECT_LT(run.seconds, 5.0);
    EXPECT_EQ(describe(run, limits), "used no CPU for 0.5 s (asleep, or waiting for something that never came) and was killed");
}

// Whether a run ended at its CPU limit. Two watchers race for a looping process, and either verdict is right: the
// kernel's RLIMIT_CPU (SIGXCPU) and the runner's count of the tree's CPU time (read from /proc five times a second,
// so it may see the limit passed before the kernel's next tick sends the signal). Both read "used more than N s".
bool ended_by_its_cpu_limit(const ProcessRun& run) {
    return (run.end == ProcessRun::End::signalled && run.signal == SIGXCPU) ||
           (run.end == ProcessRun::End::timed_out && run.out_of_cpu);
}

// Busy threads beside it slow a computing child down but never stop it using the CPU: it is ended by its
// CPU limit, not taken for hung, however busy the machine (this process's threads on every core).
TEST(ProcessRunner, ABusyMachineNeverMakesAComputingChildHung) {
    std::atomic<bool> stop{false};
    std::vector<std::thread> busy;
    for (unsigned i = 0; i < 2 * std::max(1u, std::thread::hardware_concurrency()); ++i)
        busy.emplace_back([&stop] {
            volatile unsigned long spin = 0;
            while (!stop.load(std::memory_order_relaxed)) spin = spin + 1;
        });
    Limits limits;
    limits.wall_seconds = 60.0;
    limits.cpu_seconds = 1.0;
    limits.idle_seconds = 0.3;
    const ProcessRun run = run_child({"loop"}, limits);
    stop = true;
    for (std::thread& thread : busy) thread.join();
    EXPECT_FALSE(run.hung) << run.seconds << " s";
    EXPECT_TRUE(ended_by_its_cpu_limit(run));
    EXPECT_GE(run.cpu_seconds, 0.9);
}

// RLIMIT_CPU counts each process alone: a program that forks four looping children would use five times its limit.
// The runner counts the whole tree and ends it at the limit.
TEST(ProcessRunner, TheCpuLimitCountsEveryProcessTheProgramStarted) {
    Limits limits;
    limits.wall_seconds = 60.0;
    limits.cpu_seconds = 1.0;
    limits.idle_seconds = 1.0;
    const ProcessRun run = run_child({"loops", "4"}, limits);
    EXPECT_EQ(run.end, ProcessRun::End::timed_out);
    EXPECT_TRUE(run.out_of_cpu);
    EXPECT_LT(run.seconds, 10.0);
    EXPECT_EQ(describe(run, limits), "used more than 1 s of CPU time and was killed");
}

// A pair is idle only when both are: the leader asleep while the follower computes is the checker waiting
// for the worker. Once the follower is gone, the sleeping leader alone is hung.
TEST(ProcessRunner, APairIsHungOnlyWhenNeitherUsesTheCpu) {
    Limits computing;
    computing.wall_seconds = 30.0;
    computing.cpu_seconds = 1.0;
    computing.idle_seconds = 0.3;
    ProcessSpec leader{{MISBEHAVING_CHILD, "sleep"}, {}, {}, computing, {}, {}, false, {}, {}};
    ProcessSpec follower{{MISBEHAVING_CHILD, "loop"}, {}, {}, computing, {}, {}, false, {}, {}};
    const auto [slept, looped] = run_pair({leader, follower}, 30.0);
    EXPECT_TRUE(ended_by_its_cpu_limit(looped));
    EXPECT_FALSE(looped.hung);
    EXPECT_EQ(slept.end, ProcessRun::End::timed_out);
    EXPECT_TRUE(slept.hung);
    EXPECT_GE(slept.seconds, 0.9) << "hung while the follower still computed";
}

// Whether `pid` is a process that still runs (not gone, not a zombie).
bool still_running(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) return false;
    const std::size_t close = line.rfind(')');
    return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

// The children of `parent`, from /proc.
std::vector<pid_t> children_of(pid_t parent) {
    std::vector<pid_t> children;
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        if (!std::getline(stat, line)) continue;
        const std::size_t close = line.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(line.substr(close + 2));
        char state = 0;
        pid_t ppid = 0;
        if (rest >> state >> ppid && ppid == parent) children.push_back(static_cast<pid_t>(std::stol(name)));
    }
    return children;
}

// A grader killed with SIGKILL (no handler can run) takes the programs it runs with it.
TEST(ProcessRunner, ProgramsDieWithTheirGraderEvenWhenItIsKilled) {
    const pid_t grader = fork();
    ASSERT_GE(grader, 0);
    if (grader == 0) {
        Limits limits;
        limits.wall_seconds = 60.0;
        run_process({{MISBEHAVING_CHILD, "sleep"}, {}, {}, limits, {}, {}, false, {}, {}});
        _exit(0);
    }
    std::vector<pid_t> children;
    for (int i = 0; i < 200 && children.empty(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        children = children_of(grader);
    }
    ASSERT_EQ(children.size(), 1u) << "the grader did not start its program";
    kill(grader, SIGKILL);
    waitpid(grader, nullptr, 0);
    bool gone = false;
    for (int i = 0; i < 200 && !gone; ++i) {
        gone = !still_running(children.front());
        if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_TRUE(gone) << "process " << children.front() << " outlived its grader by 2 s";
    if (!gone) kill(children.front(), SIGKILL);
}

TEST(ProcessRunner, UnboundedAllocationFailsInsideTheAddressSpaceLimit) {
    Limits limits;
    limits.address_space = std::size_t(512) << 20;
    const ProcessRun run = run_child({"allocate"}, limits);
    ASSERT_EQ(run.end, ProcessRun::End::signalled); // std::bad_alloc, uncaught: std::terminate
    EXPECT_EQ(run.signal, SIGABRT);
    EXPECT_NE(run.output.find("bad_alloc"), std::string::npos) << run.output;
}

TEST(ProcessRunner, HugeFileStopsAtTheFileSizeLimit) {
    Limits limits;
    limits.file_size = std::size_t(4) << 20;
    const ProcessRun run = run_child({"big-file"}, limits);
    ASSERT_EQ(run.end, ProcessRun::End::signalled);
    EXPECT_EQ(signal_name(run.signal), "SIGXFSZ");
}

TEST(ProcessRunner, MegabytesOfOutputAreCutButReadToTheEnd) {
    Limits limits;
    limits.output_bytes = 4096;
    const ProcessRun run = run_child({"spew", "20"}, limits);
    EXPECT_EQ(run.end, ProcessRun::End::exited);
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.output.size(), 4096u);
    EXPECT_TRUE(run.output_truncated);
}

TEST(ProcessRunner, EnvironmentEntriesReachTheChild) {
    const ProcessRun run = run_child({"env", "WHITTED_RUNNER_TEST"});
    EXPECT_EQ(run.output, "42\n");
    EXPECT_FALSE(run.output_truncated);
}

TEST(ProcessRunner, ChildrenLeftBehindAreKilledWithTheGroup) {
    const auto start = std::chrono::steady_clock::now();
    const ProcessRun run = run_child({"orphan"}, short_limits());
    EXPECT_EQ(run.end, ProcessRun::End::exited);
    EXPECT_EQ(run.output, "parent done\n");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.9);
}

// A child that left the group (setsid, as a fork bomb's may) keeps the output open after the program ended:
// the runner reads what the program wrote and returns, instead of waiting for the wall clock.
TEST(ProcessRunner, AChildThatLeftTheGroupDoesNotHoldTheRunToTheWallClock) {
    Limits limits;
    limits.wall_seconds = 30.0;
    const auto start = std::chrono::steady_clock::now();
    const ProcessRun run = run_child({"escaped"}, limits);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int escaped = 0;
    ASSERT_EQ(std::sscanf(run.output.c_str(), "escaped %d", &escaped), 1) << run.output;
    kill(escaped, SIGKILL);
    EXPECT_EQ(run.end, ProcessRun::End::exited);
    EXPECT_LT(seconds, 3.0);
}

TEST(ProcessRunner, PeakMemoryOfTheChildIsMeasured) {
    const ProcessRun run = run_child({"touch", "64"});
    EXPECT_EQ(run.end, ProcessRun::End::exited);
    EXPECT_GE(run.peak_rss_bytes, std::size_t{64} << 20);
    EXPECT_LT(run.peak_rss_bytes, std::size_t{128} << 20);
}

TEST(ProcessRunner, MissingProgramFailsToStart) {
    const ProcessRun run = run_process({{"/no/such/program"}, {}, {}, {}, {}, {}, false, {}, {}});
    EXPECT_EQ(run.end, ProcessRun::End::failed_to_start);
    EXPECT_NE(run.start_error.find("No such file"), std::string::npos) << run.start_error;
}

// A control group bounds the memory of all its processes together, which
// RLIMIT_AS (one process each) does not: three children of 100 MiB fit no
// 200 MiB group. Needs root and a writable cgroup hierarchy (else skipped).
TEST(ProcessRunner, AControlGroupBoundsTheMemoryOfAllItsProcessesTogether) {
    std::string problem;
    std::optional<ControlGroup> group = ControlGroup::make(std::size_t{200} << 20, 64, problem);
    if (!group) GTEST_SKIP() << problem;
    ProcessSpec spec{{MISBEHAVING_CHILD, "children", "100"}, {}, {}, short_limits(), {}, {}, false, {}, {}};
    spec.limits.wall_seconds = 10;
    EXPECT_EQ(run_process(spec).exit_code, 0) << "outside the group";
    spec.join_groups = group->join_files();
    const ProcessRun run = run_process(spec);
    EXPECT_FALSE(run.end == ProcessRun::End::exited && run.exit_code == 0) << "inside the group: " << describe(run, spec.limits);
    kill_group_processes(group->join_files());
    spec.argv = {MISBEHAVING_CHILD, "children", "10"};
    EXPECT_EQ(run_process(spec).exit_code, 0) << "inside the group, small enough";
}

// What a user of the grading's own leaves where every user may write goes with
// the grading; nobody else's files do. Needs root to hand files to that user.
TEST(ProcessRunner, LeftoversOfTheStudentCodesUserAreRemoved) {
    if (geteuid() != 0) GTEST_SKIP() << "needs root";
    const unsigned uid = 299999, other = 299998;
    const std::string tag = std::to_string(getpid());
    const std::vector<std::filesystem::path> theirs = {"/tmp/leftover-" + tag, "/dev/shm/leftover-" + tag};
    const std::filesystem::path kept = "/tmp/kept-" + tag;
    for (const auto& path : theirs) std::ofstream(path) << "x";
    std::ofstream(kept) << "x";
    for (const auto& path : theirs) ASSERT_EQ(chown(path.c_str(), uid, uid), 0);
    ASSERT_EQ(chown(kept.c_str(), other, other), 0);
    EXPECT_GE(remove_user_leftovers(uid), 2);
    for (const auto& path : theirs) EXPECT_FALSE(std::filesystem::exists(path)) << path;
    EXPECT_TRUE(std::filesystem::exists(kept));
    std::filesystem::remove(kept);
}

// The workers' system call filter: reading works, every way of leaving something behind fails.
TEST(SyscallFilter, AProgramMayReadButNotCreateWriteOrRemoveFiles) {
    std::string why;
    const std::vector<std::byte> filter = worker_syscall_filter(why);
    ASSERT_FALSE(filter.empty()) << why;
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("filter_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "kept") << "kept";
    const auto run = [&](const std::string& script) {
        ProcessSpec spec;
        spec.argv = {"/bin/sh", "-c", script};
        spec.working_directory = folder;
        spec.syscall_filter = filter;
        spec.limits.wall_seconds = 10;
        return run_process(spec);
    };
    const ProcessRun reading = run("cat kept");
    EXPECT_EQ(reading.exit_code, 0) << reading.output;
    EXPECT_EQ(reading.output, "kept");
    for (const std::string script : {"echo x > made", "echo x >> kept", "mkdir made", "ln -s kept made", "rm kept", "mv kept made",
                                     "chmod 777 kept", "mkfifo made", ": > kept"}) {
        const ProcessRun run_of_script = run(script);
        EXPECT_NE(run_of_script.exit_code, 0) << script << ": " << run_of_script.output;
    }
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"kept"});
    std::ifstream kept(folder / "kept");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "kept");
    std::filesystem::remove_all(folder);
}

// What a worker (and a student's lab code) may do under the filter: threads, memory, random numbers, sleeping,
// reading a file, printing. glibc starts threads with clone3 and falls back to clone only on ENOSYS.
TEST(SyscallFilter, ThreadsMemoryTimeAndReadingStillWork) {
    std::string why;
    const std::vector<std::byte> filter = worker_syscall_filter(why);
    ASSERT_FALSE(filter.empty()) << why;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        if (install_syscall_filter(filter) != 0) _exit(10);
        try {
            int counted = 0;
            std::thread thread([&counted] { counted = 1; });
            thread.join();
            if (counted != 1) _exit(11);
            std::random_device device;
            (void)device();
            std::vector<char> block(std::size_t{64} << 20, 1);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            std::ifstream file("/proc/self/status");
            std::string line;
            if (!std::getline(file, line) || block[12345] != 1) _exit(12);
            std::printf("%s", "");
            std::fflush(stdout);
            // And what it may not: a file of its own, a socket.
            if (std::fopen("/tmp/whitted-filter-test-made", "w") != nullptr) _exit(13);
            if (socket(AF_UNIX, SOCK_STREAM, 0) >= 0) _exit(14);
            int pair[2];
            if (socketpair(AF_UNIX, SOCK_STREAM, 0, pair) == 0) _exit(15);
        } catch (...) {
            _exit(16);
        }
        _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 0) << "10 install, 11 thread, 12 memory/file, 13 file made, 14 socket, 15 socketpair, 16 exception";
}
