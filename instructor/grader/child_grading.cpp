#include "grader/child_grading.hpp"
#include "grader/output_marker.hpp"
#include "grader/text.hpp"
#include "process/process_runner.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <stdexcept>
#include <string_view>
#include <sys/wait.h>

extern char** environ;

namespace whitted::grade {
namespace fs = std::filesystem;
namespace {

// The first line of the log that says what went wrong: grade's own errors
// start with "whitted grade: ", a bad command line with "whitted: ".
std::string log_reason(const fs::path& log) {
    std::ifstream stream(log, std::ios::binary);
    std::string text(64 * 1024, '\0');
    stream.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(stream.gcount()));
    std::string first;
    for (const std::string& line : split_lines(text)) {
        if (line.rfind("whitted grade: ", 0) == 0) return line.substr(15);
        if (line.rfind("whitted: ", 0) == 0) return line.substr(9);
        if (first.empty() && line.find_first_not_of(" \t") != std::string::npos) first = line;
    }
    return first.empty() ? "grade.log is empty" : first;
}

std::string ending(int wait_status) {
    if (WIFEXITED(wait_status)) return "exit code " + std::to_string(WEXITSTATUS(wait_status));
    if (WIFSIGNALED(wait_status)) return "killed by " + signal_name(WTERMSIG(wait_status));
    return "ended in an unknown way";
}

} // namespace

void prepare_grading_folder(const fs::path& out) {
    if (!fs::exists(fs::symlink_status(out))) {
        fs::create_directory(out);
        fs::permissions(out, fs::perms::owner_all); // grade makes it so too: a grading's copied labs may be answers
        std::ofstream marker(out / kGradeOutputMarker, std::ios::binary);
        if (!(marker << kGradeOutputMarkerText).flush()) throw std::runtime_error("cannot write in " + out.string());
        return;
    }
    if (fs::is_symlink(out) || !fs::is_directory(out) || !fs::exists(out / kGradeOutputMarker))
        throw std::runtime_error(out.string() + " exists and is not a grading's folder");
    fs::remove(out / "results.json");
}

pid_t start_grading(const fs::path& program, const fs::path& submission, const fs::path& out, const std::vector<std::string>& options,
                    const fs::path& temporary) {
    std::vector<std::string> args = {program.string(), "grade", submission.string(), "--out", out.string(), "-q"};
    args.insert(args.end(), options.begin(), options.end());
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    std::vector<std::string> variables = {"TMPDIR=" + temporary.string()};
    for (char** variable = environ; *variable; ++variable)
        if (std::string_view(*variable).rfind("TMPDIR=", 0) != 0) variables.emplace_back(*variable);
    std::vector<char*> environment;
    for (std::string& variable : variables) environment.push_back(variable.data());
    environment.push_back(nullptr);
    const std::string log = (out / "grade.log").string();

    posix_spawn_file_actions_t files;
    posix_spawnattr_t attributes;
    posix_spawn_file_actions_init(&files);
    posix_spawnattr_init(&attributes);
    posix_spawn_file_actions_addopen(&files, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW, 0600);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    // A group of its own (Ctrl-C on the terminal reaches grade-all only, which kills the group),
    // with the default actions for the signals grade-all catches and no signal blocked.
    sigset_t defaults, none;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    sigaddset(&defaults, SIGPIPE);
    sigemptyset(&none);
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, program.c_str(), &files, &attributes, argv.data(), environment.data());
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    if (error != 0) throw std::runtime_error("cannot start " + program.string() + ": " + std::strerror(error));
    return pid;
}

StudentGrade finished_grading(const std::string& student, int wait_status, const fs::path& out) {
    StudentGrade grade;
    grade.student = student;
    const bool exited = WIFEXITED(wait_status);
    const int code = exited ? WEXITSTATUS(wait_status) : -1;
    if (!exited || code < 0 || code > 3) {
        grade.reason = ending(wait_status) + ": " + log_reason(out / "grade.log");
        return grade;
    }
    try {
        grade.points = read_results_points(out / "results.json");
    } catch (const std::exception& error) {
        grade.reason = ending(wait_status) + ", but " + error.what();
        return grade;
    }
    grade.status = code == 3 ? GradeStatus::grader_failure : code == 2 ? GradeStatus::not_graded : GradeStatus::graded;
    if (code == 2) grade.reason = log_reason(out / "grade.log");
    if (code == 3) {
        grade.reason = log_reason(out / "grade.log");
        if (grade.reason.rfind("grader failure: ", 0) == 0) grade.reason.erase(0, 16);
    }
    return grade;
}

void kill_grading(pid_t pid) {
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL); // in case it had not made its group yet
    while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
}

} // namespace whitted::grade
