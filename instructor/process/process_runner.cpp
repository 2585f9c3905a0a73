#include "process/process_runner.hpp"
#include "process/syscall_filter.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/prctl.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace whitted::grade {
namespace {

using Clock = std::chrono::steady_clock;

// name=value strings: the grader's environment (or a clean one) with the spec's entries added or replaced.
std::vector<std::string> child_environment(const ProcessSpec& spec) {
    std::vector<std::string> result;
    if (spec.clean_environment) {
        result = {"PATH=/usr/bin:/bin", "LC_ALL=C", "HOME=/nonexistent"};
    } else {
        for (char** entry = environ; *entry; ++entry) result.emplace_back(*entry);
    }
    std::erase_if(result, [&](const std::string& text) {
        for (const auto& [name, value] : spec.environment)
            if (text.rfind(name + "=", 0) == 0) return true;
        return false;
    });
    for (const auto& [name, value] : spec.environment) result.push_back(name + "=" + value);
    return result;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> result;
    for (std::string& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
}

void set_limit(int resource, rlim_t soft, rlim_t hard) {
    const rlimit limit{soft, hard};
    setrlimit(resource, &limit);
}

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void become_child(const ProcessSpec& spec, char** argv, char** envp, int output_fd, int error_fd,
                               const int* descriptors, std::size_t descriptor_count, const int* groups, std::size_t group_count,
                               pid_t grader) {
    // A session of its own, so also a process group of its own: no controlling terminal, so the program
    // cannot open /dev/tty to write on the grader's terminal or push input into it (TIOCSTI).
    if (setsid() < 0) {
        const int error = errno;
        [[maybe_unused]] auto written = write(error_fd, &error, sizeof error);
        _exit(127);
    }
    for (std::size_t i = 0; i < group_count; ++i) {
        if (write(groups[i], "0", 1) != 1) { // "0": this process; its children follow it
            const int error = errno;
            [[maybe_unused]] auto written = write(error_fd, &error, sizeof error);
            _exit(127);
        }
    }
    // Out of the way of 3, 4, ... first: the pipes and the descriptors to hand on may be any of them.
    output_fd = fcntl(output_fd, F_DUPFD_CLOEXEC, 100);
    error_fd = fcntl(error_fd, F_DUPFD_CLOEXEC, 100);
    int moved[16];
    for (std::size_t i = 0; i < descriptor_count && i < 16; ++i) moved[i] = fcntl(descriptors[i], F_DUPFD_CLOEXEC, 100);
    for (std::size_t i = 0; i < descriptor_count && i < 16; ++i)
        if (moved[i] < 0 || dup2(moved[i], static_cast<int>(3 + i)) < 0) _exit(127); // dup2 clears close-on-exec
    const Limits& l = spec.limits;
    set_limit(RLIMIT_CORE, 0, 0);
    if (l.cpu_seconds > 0) {
        const rlim_t cpu = static_cast<rlim_t>(std::ceil(l.cpu_seconds));
        set_limit(RLIMIT_CPU, cpu, cpu + 1);
    }
    if (l.address_space > 0) set_limit(RLIMIT_AS, l.address_space, l.address_space);
    if (l.file_size > 0) set_limit(RLIMIT_FSIZE, l.file_size, l.file_size);
    if (l.processes > 0) set_limit(RLIMIT_NPROC, l.processes, l.processes);
    if (spec.identity) {
        // Groups first: once the user is switched, they can no longer be changed.
        if (setgroups(0, nullptr) != 0 || setgid(spec.identity->gid) != 0 || setuid(spec.identity->uid) != 0) {
            const int error = errno;
            [[maybe_unused]] auto written = write(error_fd, &error, sizeof error);
            _exit(127);
        }
    }
    // Nothing outlives the grader, however it ends (SIGKILL included): the kernel kills this program when the
    // grader dies. Set after the change of user, which clears it; a grader already gone is checked after.
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != grader) _exit(127);
    const int null_fd = open("/dev/null", O_RDONLY);
    if (null_fd >= 0) dup2(null_fd, STDIN_FILENO);
    dup2(output_fd, STDOUT_FILENO);
    dup2(output_fd, STDERR_FILENO);
    if (!spec.working_directory.empty() && chdir(spec.working_directory.c_str()) != 0) {
        const int error = errno;
        [[maybe_unused]] auto written = write(error_fd, &error, sizeof error);
        _exit(127);
    }
    if (!spec.syscall_filter.empty()) {
        if (const int error = install_syscall_filter(spec.syscall_filter); error != 0) {
            [[maybe_unused]] auto written = write(error_fd, &error, sizeof error);
            _exit(127);
        }
    }
    execvpe(argv[0], argv, envp);
    const int error = errno;
    [[maybe_unused]] auto written = write(error_fd, &error, sizeof error);
    _exit(127);
}

// Keeps the first `limit` bytes of what arrives.
void keep(ProcessRun& run, const char* data, std::size_t size, std::size_t limit) {
    const std::size_t room = run.output.size() < limit ? limit - run.output.size() : 0;
    run.output.append(data, std::min(room, size));
    if (size > room) run.output_truncated = true;
}

// One program of run_together, from fork to reaping.
struct Running {
    ProcessRun run;
    pid_t pid = -1;
    int output_fd = -1;
    int start_error_fd = -1;
    Clock::time_point start, deadline;
    bool reaped = false, timed_out = false;
    int wait_status = 0;
};

Running start_child(const ProcessSpec& spec) {
    Running r;
    std::vector<std::string> argv_strings = spec.argv;
    std::vector<std::string> env_strings = child_environment(spec);
    std::vector<char*> argv = c_strings(argv_strings);
    std::vector<char*> envp = c_strings(env_strings);
    r.reaped = true;
    int output[2], start_error[2];
    if (argv_strings.empty() || spec.descriptors.size() > 16 || pipe2(output, O_CLOEXEC) != 0) {
        r.run.start_error = "no program given, too many descriptors or no pipe";
        return r;
    }
    if (pipe2(start_error, O_CLOEXEC) != 0) {
        close(output[0]);
        close(output[1]);
        r.run.start_error = std::strerror(errno);
        return r;
    }
    std::vector<int> groups;
    for (const std::filesystem::path& file : spec.join_groups) {
        groups.push_back(open(file.c_str(), O_WRONLY | O_CLOEXEC));
        if (groups.back() < 0) {
            r.run.start_error = "cannot join the control group " + file.string() + ": " + std::strerror(errno);
            for (const int fd : groups)
                if (fd >= 0) close(fd);
            for (const int fd : {output[0], output[1], start_error[0], start_error[1]}) close(fd);
            return r;
        }
    }
    r.start = Clock::now();
    r.deadline = r.start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(spec.limits.wall_seconds));
    const pid_t grader = getpid();
    const pid_t pid = fork();
    if (pid == 0)
        become_child(spec, argv.data(), envp.data(), output[1], start_error[1], spec.descriptors.data(), spec.descriptors.size(),
                     groups.data(), groups.size(), grader);
    for (const int fd : groups) close(fd);
    close(output[1]);
    close(start_error[1]);
    if (pid < 0) {
        close(output[0]);
        close(start_error[0]);
        r.run.start_error = std::string("fork failed: ") + std::strerror(errno);
        return r;
    }
    r.pid = pid;
    r.output_fd = output[0];
    r.start_error_fd = start_error[0];
    r.reaped = false;
    return r;
}

void finish(Running& r, const ProcessSpec& spec) {
    if (r.pid < 0) return; // failed before fork: End::failed_to_start
    kill(-r.pid, SIGKILL);
    r.run.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
    int exec_errno = 0;
    if (read(r.start_error_fd, &exec_errno, sizeof exec_errno) == sizeof exec_errno) {
        r.run.end = ProcessRun::End::failed_to_start;
        r.run.start_error = spec.argv[0] + ": " + std::strerror(exec_errno);
    } else if (r.timed_out) {
        r.run.end = ProcessRun::End::timed_out;
    } else if (WIFSIGNALED(r.wait_status)) {
        r.run.end = ProcessRun::End::signalled;
        r.run.signal = WTERMSIG(r.wait_status);
    } else {
        r.run.end = ProcessRun::End::exited;
        r.run.exit_code = WEXITSTATUS(r.wait_status);
    }
    close(r.start_error_fd);
}

// One line of /proc/<pid>/stat: the parent and the clock ticks of CPU used (its own and its reaped children's).
struct ProcStat {
    pid_t pid = 0, parent = 0;
    uid_t uid = 0; // the owner of /proc/<pid>: the process's user
    long long ticks = 0;
};

std::vector<ProcStat> all_processes() {
    std::vector<ProcStat> processes;
    DIR* proc = opendir("/proc");
    if (!proc) return processes;
    while (const dirent* entry = readdir(proc)) {
        char* end = nullptr;
        const long pid = std::strtol(entry->d_name, &end, 10);
        if (*end != '\0' || pid <= 0) continue;
        std::ifstream stat_file(std::string("/proc/") + entry->d_name + "/stat");
        std::string stat;
        std::getline(stat_file, stat);
        // The command name (field 2) is in parentheses and may hold spaces: read after the last ')'.
        const std::size_t close = stat.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(stat.substr(close + 1));
        std::string field;
        ProcStat p;
        p.pid = static_cast<pid_t>(pid);
        struct stat owner {};
        if (::stat((std::string("/proc/") + entry->d_name).c_str(), &owner) == 0) p.uid = owner.st_uid;
        // Fields 3.. : state, ppid, pgrp, session, tty, tpgid, flags, 4 fault counts, utime, stime, cutime, cstime.
        long long value = 0;
        rest >> field >> value;
        p.parent = static_cast<pid_t>(value);
        for (int skipped = 0; skipped < 9; ++skipped) rest >> field; // fields 5 to 13
        for (int i = 0; i < 4 && rest >> value; ++i) p.ticks += value; // fields 14 to 17
        processes.push_back(p);
    }
    closedir(proc);
    return processes;
}

// The CPU seconds each root process and everything it started (still running) have used. A process that left
// the tree (setsid and its parent gone: it is the grader's now) still counts for the root whose user
// (`users[i]`, -1: none of its own) it runs as.
std::vector<double> cpu_seconds_of_trees(const std::vector<pid_t>& roots, const std::vector<long long>& users) {
    const std::vector<ProcStat> processes = all_processes();
    std::map<pid_t, pid_t> parent;
    for (const ProcStat& p : processes) parent[p.pid] = p.parent;
    static const double tick = 1.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
    std::vector<double> seconds(roots.size(), 0.0);
    for (const ProcStat& p : processes) {
        if (const auto user = std::find(users.begin(), users.end(), static_cast<long long>(p.uid)); user != users.end()) {
            seconds[static_cast<std::size_t>(user - users.begin())] += static_cast<double>(p.ticks) * tick;
            continue;
        }
        // Walk up to a root (bounded: a chain of parents ends at init).
        pid_t at = p.pid;
        for (int depth = 0; depth < 64 && at > 1; ++depth) {
            const auto root = std::find(roots.begin(), roots.end(), at);
            if (root != roots.end()) {
                seconds[static_cast<std::size_t>(root - roots.begin())] += static_cast<double>(p.ticks) * tick;
                break;
            }
            const auto up = parent.find(at);
            if (up == parent.end()) break;
            at = up->second;
        }
    }
    return seconds;
}

// Runs the programs at once; program i with a leader (leaders[i] >= 0) is killed
// `linger_seconds` after its leader ended.
std::vector<ProcessRun> run_all(const std::vector<ProcessSpec>& specs, const std::vector<int>& leaders, double linger_seconds) {
    std::vector<Running> running;
    for (const ProcessSpec& spec : specs) running.push_back(start_child(spec));
    // The grader's copies of the handed-over descriptors, closed once every program has started (they may share some).
    std::set<int> handed;
    for (const ProcessSpec& spec : specs) handed.insert(spec.descriptors.begin(), spec.descriptors.end());
    for (const int fd : handed) close(fd);
    std::vector<std::optional<Clock::time_point>> ended(specs.size());
    const auto linger = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(linger_seconds));
    // Hang detection: the shortest idle limit of the runs, and when their CPU use last grew.
    double idle_limit = 0.0;
    for (const ProcessSpec& spec : specs)
        if (spec.limits.idle_seconds > 0 && (idle_limit == 0.0 || spec.limits.idle_seconds < idle_limit)) idle_limit = spec.limits.idle_seconds;
    double used_before = -1.0;
    Clock::time_point last_progress = Clock::now(), next_look = Clock::now();
    char buffer[65536];
    for (;;) {
        const Clock::time_point now = Clock::now();
        if (idle_limit > 0 && now >= next_look) {
            next_look = now + std::chrono::milliseconds(200);
            std::vector<pid_t> roots;
            std::vector<long long> users;
            for (std::size_t i = 0; i < running.size(); ++i) {
                roots.push_back(running[i].reaped ? -1 : running[i].pid);
                users.push_back(!running[i].reaped && specs[i].identity ? static_cast<long long>(specs[i].identity->uid) : -1);
            }
            const std::vector<double> seconds = cpu_seconds_of_trees(roots, users);
            double used = 0.0;
            for (std::size_t i = 0; i < running.size(); ++i) {
                Running& r = running[i];
                if (!r.reaped) r.run.cpu_seconds = std::max(r.run.cpu_seconds, seconds[i]);
                used += r.run.cpu_seconds;
                // RLIMIT_CPU counts each process alone: a program that forks would get the limit once per child.
                const double limit = specs[i].limits.cpu_seconds;
                if (!r.reaped && !r.timed_out && limit > 0 && r.run.cpu_seconds > limit) {
                    r.timed_out = r.run.out_of_cpu = true;
                    kill(-r.pid, SIGKILL);
                }
            }
            if (used != used_before) {
                used_before = used;
                last_progress = now;
            } else if (now - last_progress >= std::chrono::duration<double>(idle_limit)) {
                for (Running& r : running)
                    if (!r.reaped && !r.timed_out) {
                        r.timed_out = r.run.hung = true;
                        kill(-r.pid, SIGKILL);
                    }
            }
        }
        std::vector<pollfd> polled;
        bool active = false;
        for (std::size_t i = 0; i < running.size(); ++i) {
            Running& r = running[i];
            if (!r.reaped && !r.timed_out && now >= r.deadline) {
                r.timed_out = true;
                kill(-r.pid, SIGKILL);
            }
            if (!r.reaped && leaders[i] >= 0 && ended[static_cast<std::size_t>(leaders[i])] &&
                now >= *ended[static_cast<std::size_t>(leaders[i])] + linger) {
                r.run.outlived = true;
                kill(-r.pid, SIGKILL);
            }
            // A process that left the group (a fork bomb's child in a session of its own) can hold the output open
            // after the program ended: what the program wrote is read within half a second, then the runner stops
            // listening, rather than waiting for the wall clock (the grader kills what is left after the run).
            const bool drained = r.reaped && (r.run.outlived || now >= *ended[i] + std::chrono::milliseconds(500));
            if (r.output_fd >= 0 && (now >= r.deadline + std::chrono::seconds(1) || drained)) {
                close(r.output_fd);
                r.output_fd = -1;
            }
            rusage usage{};
            if (!r.reaped && wait4(r.pid, &r.wait_status, WNOHANG, &usage) == r.pid) {
                r.run.peak_rss_bytes = static_cast<std::size_t>(usage.ru_maxrss) * 1024; // Linux counts kilobytes
                r.run.cpu_seconds = std::max(r.run.cpu_seconds, static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                                                                    1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec));
                r.reaped = true;
                ended[i] = now;
                kill(-r.pid, SIGKILL); // whatever it left behind still holds the output open
            }
            if (r.output_fd >= 0) polled.push_back({r.output_fd, POLLIN, 0});
            active |= r.output_fd >= 0 || !r.reaped;
        }
        if (!active) break;
        if (polled.empty()) {
            usleep(2000);
            continue;
        }
        if (poll(polled.data(), polled.size(), 20) <= 0) continue;
        for (const pollfd& p : polled) {
            if (!p.revents) continue;
            for (std::size_t i = 0; i < running.size(); ++i) {
                Running& r = running[i];
                if (r.output_fd != p.fd) continue;
                const ssize_t n = read(r.output_fd, buffer, sizeof buffer);
                if (n > 0) {
                    keep(r.run, buffer, static_cast<std::size_t>(n), specs[i].limits.output_bytes);
                } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
                    close(r.output_fd);
                    r.output_fd = -1;
                }
            }
        }
    }
    std::vector<ProcessRun> runs;
    for (std::size_t i = 0; i < running.size(); ++i) {
        finish(running[i], specs[i]);
        runs.push_back(std::move(running[i].run));
    }
    return runs;
}

} // namespace

std::vector<ProcessRun> run_together(const std::vector<ProcessSpec>& specs) {
    return run_all(specs, std::vector<int>(specs.size(), -1), 0.0);
}

std::pair<ProcessRun, ProcessRun> run_pair(const ProcessPair& pair, double linger_seconds) {
    std::vector<ProcessRun> runs = run_all({pair.leader, pair.follower}, {-1, 0}, linger_seconds);
    return {std::move(runs[0]), std::move(runs[1])};
}

ProcessRun run_process(const ProcessSpec& spec) { return run_together({spec}).front(); }

void become_subreaper() { prctl(PR_SET_CHILD_SUBREAPER, 1); }

namespace {

// The pids of this process's children, from /proc/<pid>/stat.
std::vector<pid_t> children_of(pid_t parent) {
    std::vector<pid_t> children;
    for (const ProcStat& process : all_processes())
        if (process.parent == parent) children.push_back(process.pid);
    return children;
}

} // namespace

int kill_leftover_children() {
    int killed = 0;
    // Killing a child hands its own children to us: repeat until none is left.
    for (int round = 0; round < 100; ++round) {
        const std::vector<pid_t> children = children_of(getpid());
        if (children.empty()) break;
        for (const pid_t child : children) {
            kill(child, SIGKILL);
            ++killed;
        }
        for (const pid_t child : children) waitpid(child, nullptr, 0);
    }
    return killed;
}

void kill_user_processes(unsigned uid) {
    const pid_t killer = fork();
    if (killer == 0) {
        // kill(-1) reaches every process the user may signal: all of its own, but never this one.
        if (setgroups(0, nullptr) != 0 || setgid(uid) != 0 || setuid(uid) != 0) _exit(1);
        // Rounds catch what forked since the last; zombies (not reaped yet) still count, so rounds are few.
        for (int round = 0; round < 20; ++round) {
            if (kill(-1, SIGKILL) != 0 && errno == ESRCH) _exit(0);
            usleep(200);
        }
        _exit(0);
    }
    if (killer > 0) waitpid(killer, nullptr, 0);
}

int remove_user_leftovers(unsigned uid) {
    int removed = 0;
    for (const char* shared : {"/tmp", "/var/tmp", "/dev/shm", "/run/lock", "/dev/mqueue"}) { // /var/lock: a link to /run/lock
        std::error_code error;
        for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(shared, error)) {
            struct stat info {};
            if (lstat(entry.path().c_str(), &info) != 0 || info.st_uid != uid) continue;
            std::error_code ignored;
            removed += std::filesystem::remove_all(entry.path(), ignored) > 0; // links are removed, never followed
        }
    }
    // /proc/sysvipc/{shm,msg,sem}: a header line, then one object a line; the id is the second field, the owner's uid
    // the eighth (shm, msg) or fifth (sem).
    struct Kind {
        const char* file;
        int uid_field;
        int (*remove)(int id);
    };
    const Kind kinds[] = {{"/proc/sysvipc/shm", 8, [](int id) { return shmctl(id, IPC_RMID, nullptr); }},
                          {"/proc/sysvipc/msg", 8, [](int id) { return msgctl(id, IPC_RMID, nullptr); }},
                          {"/proc/sysvipc/sem", 5, [](int id) { return semctl(id, 0, IPC_RMID); }}};
    for (const Kind& kind : kinds) {
        std::ifstream file(kind.file);
        std::string line;
        std::getline(file, line);
        while (std::getline(file, line)) {
            std::istringstream fields(line);
            std::vector<long long> values;
            for (long long value; values.size() < 8 && fields >> value;) values.push_back(value);
            if (static_cast<int>(values.size()) < kind.uid_field || values[static_cast<std::size_t>(kind.uid_field - 1)] != uid) continue;
            removed += kind.remove(static_cast<int>(values[1])) == 0;
        }
    }
    return removed;
}

long processes_of_user(unsigned uid) {
    long count = 0;
    DIR* proc = opendir("/proc");
    if (!proc) return 0;
    while (const dirent* entry = readdir(proc)) {
        if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue;
        std::ifstream status(std::string("/proc/") + entry->d_name + "/status");
        bool ours = false;
        for (std::string line; std::getline(status, line);) {
            if (line.rfind("Uid:", 0) == 0) ours = std::strtoul(line.c_str() + 4, nullptr, 10) == uid;
            if (ours && line.rfind("Threads:", 0) == 0) count += std::strtol(line.c_str() + 8, nullptr, 10);
        }
    }
    closedir(proc);
    return count;
}

std::string signal_name(int signal) {
    if (const char* abbreviation = sigabbrev_np(signal)) return std::string("SIG") + abbreviation;
    return "signal " + std::to_string(signal);
}

std::string describe(const ProcessRun& run, const Limits& limits) {
    char seconds[32];
    switch (run.end) {
    case ProcessRun::End::exited: return "exited with code " + std::to_string(run.exit_code);
    case ProcessRun::End::signalled: {
        const char* description = sigdescr_np(run.signal);
        return "killed by " + signal_name(run.signal) + (description ? std::string(" (") + description + ")" : "");
    }
    case ProcessRun::End::timed_out:
        if (run.out_of_cpu) {
            std::snprintf(seconds, sizeof seconds, "%g", limits.cpu_seconds);
            return std::string("used more than ") + seconds + " s of CPU time and was killed";
        }
        if (run.hung) {
            std::snprintf(seconds, sizeof seconds, "%g", limits.idle_seconds);
            return std::string("used no CPU for ") + seconds + " s (asleep, or waiting for something that never came) and was killed";
        }
        std::snprintf(seconds, sizeof seconds, "%g", limits.wall_seconds);
        return std::string("did not finish within ") + seconds + " s and was killed";
    case ProcessRun::End::failed_to_start: return "could not start: " + run.start_error;
    }
    return "ended in an unknown way";
}

} // namespace whitted::grade
