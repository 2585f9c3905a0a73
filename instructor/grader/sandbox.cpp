#include "grader/sandbox.hpp"
#include "process/control_group.hpp"
#include "process/syscall_filter.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <sys/mman.h>
#include <unistd.h>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

// Processes the student's code may start beyond those its user already runs.
constexpr long kExtraProcesses = 256;

// The first of the paths `identity` (or the grader's own user) can read, or empty.
std::string first_readable(const std::vector<fs::path>& paths, const std::optional<Identity>& identity, const fs::path& scratch) {
    ProcessSpec probe;
    probe.argv = {"/bin/sh", "-c", "for p; do if test -r \"$p\"; then printf %s \"$p\"; exit 1; fi; done", "sh"};
    probe.working_directory = scratch;
    probe.identity = identity;
    probe.clean_environment = true;
    for (const fs::path& path : paths) probe.argv.push_back(path.string());
    probe.limits.wall_seconds = 10;
    const ProcessRun run = run_process(probe);
    if (run.end == ProcessRun::End::exited && run.exit_code == 0) return {};
    return run.output.empty() ? "(the probe " + describe(run, probe.limits) + ")" : run.output;
}

// A user and group id of this grading's own: no account has it and no process
// runs as it, so that killing all of its processes after a run (end_runs)
// touches neither another grading's nor a service's, and its files are
// protected from them by the permissions of "others".
Identity fresh_identity() {
    unsigned uid = 200000 + static_cast<unsigned>(getpid()) % 100000;
    while (processes_of_user(uid) > 0) uid = 200000 + (uid - 200000 + 7919) % 100000;
    return Identity{uid, uid};
}

// bwrap's options for the system folders: bound read-only, or re-created as the symbolic links they are.
void add_system_folders(std::vector<std::string>& options) {
    for (const char* folder : {"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc"}) {
        std::error_code error;
        if (fs::is_symlink(folder, error)) {
            options.insert(options.end(), {"--symlink", fs::read_symlink(folder, error).string(), folder});
        } else if (fs::is_directory(folder, error)) {
            options.insert(options.end(), {"--ro-bind", folder, folder});
        }
    }
}

} // namespace

ProcessSpec Sandbox::wrap(ProcessSpec spec, const std::vector<fs::path>& readable, const std::optional<fs::path>& writable) const {
    spec.identity = identity;
    spec.clean_environment = true;
    spec.join_groups = groups;
    if (processes > 0) spec.limits.processes = processes;
    const bool filtered = !writable && !syscall_filter.empty();
    if (!bubblewrap) {
        if (filtered) spec.syscall_filter = syscall_filter;
        return spec;
    }
    std::vector<std::string> argv = bwrap_prefix;
    if (filtered) {
        // bwrap needs the calls the filter denies to set the sandbox up: it installs the filter itself, last.
        const int file = memfd_create("whitted-filter", MFD_CLOEXEC);
        if (file < 0 || write(file, syscall_filter.data(), syscall_filter.size()) != static_cast<ssize_t>(syscall_filter.size()) ||
            lseek(file, 0, SEEK_SET) != 0)
            throw std::runtime_error(std::string("cannot hand the system call filter to bwrap: ") + std::strerror(errno));
        argv.insert(argv.end(), {"--seccomp", std::to_string(3 + spec.descriptors.size())});
        spec.descriptors.push_back(file); // closed by the runner once the program started
    }
    for (const fs::path& path : readable) argv.insert(argv.end(), {"--ro-bind", path.string(), path.string()});
    if (writable) argv.insert(argv.end(), {"--bind", writable->string(), writable->string()});
    if (!spec.working_directory.empty()) argv.insert(argv.end(), {"--chdir", spec.working_directory.string()});
    argv.push_back("--");
    argv.insert(argv.end(), spec.argv.begin(), spec.argv.end());
    spec.argv = std::move(argv);
    spec.working_directory.clear(); // bwrap changes into it, inside
    return spec;
}

void Sandbox::end_runs() const {
    kill_group_processes(groups);
    if (identity) kill_user_processes(identity->uid);
    kill_leftover_children();
    // Nothing a run left may reach the next run (a hidden test's inputs kept for a visible one).
    if (identity) remove_user_leftovers(identity->uid);
}

ProcessRun Sandbox::unwrap(ProcessRun run) const {
    if (bubblewrap && run.end == ProcessRun::End::exited && run.exit_code > 128 && run.exit_code < 128 + 65) {
        run.end = ProcessRun::End::signalled;
        run.signal = run.exit_code - 128;
        run.exit_code = -1;
    }
    return run;
}

Sandbox make_sandbox(SandboxChoice choice, const std::vector<fs::path>& secrets, const fs::path& scratch, long max_processes,
                     bool allow_exposed) {
    Sandbox sandbox;
    std::vector<std::string>& fences = sandbox.fences;
    fences = {"resource limits", "a process group per run", "leftover processes killed", "the verdict in a separate checker process"};
    std::vector<std::string>& missing = sandbox.gaps;
    const bool root = geteuid() == 0;
    if (root) {
        sandbox.identity = fresh_identity();
        fences.push_back("student code runs as a user of its own");
    }
    const unsigned uid = sandbox.identity ? sandbox.identity->uid : getuid();
    if (max_processes > 0) sandbox.processes = max_processes;
    else sandbox.processes = processes_of_user(uid) + kExtraProcesses;
    fences.push_back("a process limit");
    std::string no_filter;
    sandbox.syscall_filter = worker_syscall_filter(no_filter);
    if (!sandbox.syscall_filter.empty()) fences.push_back(syscall_filter_summary());
    else missing.push_back("no system call filter: " + no_filter);

    if (choice != SandboxChoice::none) {
        // One run of `true` inside tells whether bwrap is installed (the runner looks it up in PATH) and works here.
        std::string problem;
        sandbox.bubblewrap = true;
        sandbox.bwrap_prefix = {"bwrap", "--die-with-parent", "--new-session", "--unshare-all", "--cap-drop", "ALL",
                                "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"};
        add_system_folders(sandbox.bwrap_prefix);
        ProcessSpec truth;
        truth.argv = {"/bin/true"};
        ProcessSpec probe = sandbox.wrap(truth, {}, std::nullopt);
        probe.limits.wall_seconds = 10;
        const ProcessRun run = run_process(probe);
        if (run.end == ProcessRun::End::failed_to_start) {
            problem = "bwrap is not installed (apt-get install bubblewrap)";
        } else if (run.end != ProcessRun::End::exited || run.exit_code != 0) {
            problem = "bwrap does not work here (" + describe(run, probe.limits) + ")";
            sandbox.bwrap_error = run.output.substr(0, 300);
        }
        if (!problem.empty()) {
            sandbox.bubblewrap = false;
            sandbox.bwrap_prefix.clear();
        }
        if (!problem.empty() && choice == SandboxChoice::bubblewrap) throw std::runtime_error("--sandbox bubblewrap: " + problem);
        if (sandbox.bubblewrap) fences.push_back("bubblewrap (no network, own process ids, only the system and its own files visible)");
        else missing.push_back("no bubblewrap: " + problem);
    } else {
        missing.push_back("no bubblewrap (--sandbox none)");
    }
    if (!sandbox.bubblewrap) {
        if (!sandbox.identity) sandbox.exposed = "student code runs as the grader's own user, which can read every answer";
        else if (const std::string readable = first_readable(secrets, sandbox.identity, scratch); !readable.empty())
            sandbox.exposed = "other users can read " + readable;
        if (!sandbox.exposed.empty()) {
            if (!allow_exposed)
                throw std::runtime_error("this machine cannot keep the answers from the student's code: " + sandbox.exposed +
                                         ". Install bubblewrap where it can run, or as root make the instructor tree and build "
                                         "unreadable to other users (chmod o-rwx), or pass --allow-exposed-answers to grade anyway "
                                         "(instructor/docs/grading.md, \"Fences\")");
            missing.push_back("ANSWERS EXPOSED (--allow-exposed-answers): " + sandbox.exposed);
        } else {
            fences.push_back("the answers unreadable to other users (probed)");
        }
    }
    sandbox.mode = sandbox.bubblewrap ? "sandbox" : sandbox.exposed.empty() ? "users" : "exposed";
    return sandbox;
}

std::string Sandbox::description() const {
    std::string text = mode + " mode: ";
    for (std::size_t i = 0; i < fences.size(); ++i) text += (i ? ", " : "") + fences[i];
    for (const std::string& gap : gaps) text += "; " + gap;
    return text;
}

void give_folder(const Sandbox& sandbox, const fs::path& folder) {
    if (sandbox.identity && chown(folder.c_str(), sandbox.identity->uid, sandbox.identity->gid) != 0)
        throw std::runtime_error("cannot hand " + folder.string() + " to the student code's user");
}

} // namespace whitted::grade
