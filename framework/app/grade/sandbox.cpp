#include "grade/sandbox.hpp"

#include <algorithm>
#include <stdexcept>
#include <unistd.h>

namespace whitted::grade {
namespace {

namespace fs = std::filesystem;

// Processes a test may start beyond those its user already runs.
constexpr long kExtraProcesses = 256;

// Inside the tests' folder, what bubblewrap hides: sources, and folders no test reads.
bool is_source(const fs::path& file) {
    const std::string extension = file.extension().string();
    return extension == ".cpp" || extension == ".hpp" || extension == ".h" || extension == ".cc";
}
const char* const kHiddenTestFolders[] = {"mistakes", "solution", "grader", "calibration", "fuzz"};

bool holds_source(const fs::path& folder) {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file() && is_source(entry.path())) return true;
    return false;
}

// bwrap's options that show the folder's data read-only and none of its sources:
// a folder without sources whole (one mount), else its other files one by one.
void show_data(const fs::path& folder, std::vector<std::string>& options) {
    if (!holds_source(folder)) {
        options.insert(options.end(), {"--ro-bind", folder.string(), folder.string()});
        return;
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        if (entry.is_directory()) {
            const std::string name = entry.path().filename().string();
            const bool hidden = std::find(std::begin(kHiddenTestFolders), std::end(kHiddenTestFolders), name) != std::end(kHiddenTestFolders);
            if (!hidden || folder.filename() != "tests") show_data(entry.path(), options);
        } else if (entry.is_regular_file() && !is_source(entry.path())) {
            options.insert(options.end(), {"--ro-bind", entry.path().string(), entry.path().string()});
        }
    }
}

// The first of the paths user nobody cannot read and enter, or empty when it reaches all of them.
std::string unreachable_for_nobody(const std::vector<fs::path>& paths) {
    ProcessSpec probe{{"/bin/sh", "-c", "for p; do test -r \"$p\" && test -x \"$p\" || { printf %s \"$p\"; exit 1; }; done", "sh"},
                      "/", {}, {}, Identity{}};
    for (const fs::path& path : paths) probe.argv.push_back(path.string());
    probe.limits.wall_seconds = 10;
    const ProcessRun run = run_process(probe);
    if (run.end == ProcessRun::End::exited && run.exit_code == 0) return {};
    return run.output.empty() ? describe(run, probe.limits) : run.output;
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

std::vector<std::string> bwrap_options(const std::string& bwrap, const SandboxPaths& paths) {
    std::vector<std::string> options = {bwrap, "--die-with-parent", "--new-session", "--unshare-all", "--cap-drop", "ALL",
                                        "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"};
    add_system_folders(options);
    const fs::path tests = paths.instructor_tree / "tests";
    const fs::path scenes = paths.instructor_tree / "scenes";
    if (fs::is_directory(scenes)) options.insert(options.end(), {"--ro-bind", scenes.string(), scenes.string()});
    show_data(tests, options);
    options.insert(options.end(), {"--ro-bind", paths.programs.string(), paths.programs.string()});
    return options;
}

} // namespace

ProcessSpec Sandbox::wrap(ProcessSpec spec, const fs::path& writable) const {
    spec.identity = identity;
    if (processes > 0) spec.limits.processes = processes;
    if (!bubblewrap) return spec;
    std::vector<std::string> argv = bwrap_prefix;
    argv.insert(argv.end(), {"--bind", writable.string(), writable.string(), "--chdir", writable.string(), "--"});
    argv.insert(argv.end(), spec.argv.begin(), spec.argv.end());
    spec.argv = std::move(argv);
    spec.working_directory = writable;
    return spec;
}

ProcessRun Sandbox::unwrap(ProcessRun run) const {
    if (bubblewrap && run.end == ProcessRun::End::exited && run.exit_code > 128 && run.exit_code < 128 + 65) {
        run.end = ProcessRun::End::signalled;
        run.signal = run.exit_code - 128;
        run.exit_code = -1;
    }
    return run;
}

Sandbox make_sandbox(SandboxChoice choice, const SandboxPaths& paths, long max_processes) {
    Sandbox sandbox;
    std::vector<std::string> fences = {"resource limits", "a process group per test", "leftover processes killed"};
    std::vector<std::string> missing;
    const bool root = geteuid() == 0;
    if (root) {
        const std::string unreachable = unreachable_for_nobody({paths.instructor_tree / "tests", paths.programs, paths.out});
        if (unreachable.empty()) {
            sandbox.identity = Identity{};
            fences.push_back("run as user nobody");
        } else {
            // The path stays out of the report, which the student sees.
            missing.push_back("tests run as root: user nobody cannot reach the tests or the grading folder");
            sandbox.unreachable = unreachable;
        }
    }
    const unsigned uid = sandbox.identity ? sandbox.identity->uid : getuid();
    if (max_processes > 0) sandbox.processes = max_processes;
    else if (!root || sandbox.identity) sandbox.processes = processes_of_user(uid) + kExtraProcesses;
    if (sandbox.processes > 0) fences.push_back("a process limit");
    else missing.push_back("no process limit (it does not bind root)");

    if (choice != SandboxChoice::none) {
        // One run of `true` inside tells whether bwrap is installed (the runner looks it up in PATH) and works here.
        std::string problem;
        sandbox.bubblewrap = true;
        sandbox.bwrap_prefix = bwrap_options("bwrap", paths);
        ProcessSpec probe = sandbox.wrap({{"/bin/true"}, {}, {}, {}, {}}, paths.out);
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
        if (sandbox.bubblewrap) fences.push_back("bubblewrap (no network; only the tests' scenes and images visible, read-only)");
        else missing.push_back("no bubblewrap: " + problem);
    } else {
        missing.push_back("no bubblewrap (--sandbox none)");
    }
    std::string text = std::string(sandbox.bubblewrap ? "sandbox" : "rlimits") + " mode: ";
    for (std::size_t i = 0; i < fences.size(); ++i) text += (i ? ", " : "") + fences[i];
    for (const std::string& gap : missing) text += "; " + gap;
    sandbox.description = text;
    return sandbox;
}

void give_folder(const Sandbox& sandbox, const fs::path& folder) {
    if (sandbox.identity && chown(folder.c_str(), sandbox.identity->uid, sandbox.identity->gid) != 0)
        throw std::runtime_error("cannot hand " + folder.string() + " to the tests' user");
}

} // namespace whitted::grade
