// `whitted grade-all FOLDER --csv FILE`: grade every student of a class, one
// subfolder of FOLDER each, by running `whitted grade` on it as a child
// process (N at a time), and write the class's CSV. Exit codes: 0 every
// student graded, 2 usage error, 3 a grading failed (the CSV lists it), 130 interrupted.
#include "grader/grade_all_command.hpp"
#include "grader/child_grading.hpp"
#include "grader/class_grades.hpp"
#include "grader/class_progress.hpp"
#include "grader/path_inside.hpp"
#include "grader/submission.hpp"
#include "grader/text.hpp"
#include "process/process_runner.hpp"
#include "usage_error.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <stdlib.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace grade;

// Set by SIGINT or SIGTERM: the one piece of mutable global state, as a signal handler can only set a flag.
volatile std::sig_atomic_t stop_signal = 0;

void on_stop(int signal) { stop_signal = signal; }

const char* kClassMarker = ".whitted-grade-all"; // marks a GRADES_DIR grade-all may write into again

struct GradeAllOptions {
    std::string folder;
    std::string csv;
    std::string out = "grades";
    int parallel = 1;
    bool quiet = false;
    std::map<std::string, std::string> passed_on; // grade's options given, by name ("--timeout" -> "5")
    bool allow_exposed_answers = false;
};

// The class: FOLDER's subfolders and links to folders (the students), sorted;
// hidden folders and __MACOSX skipped, files and other links noted.
std::vector<std::string> list_students(const fs::path& folder, bool quiet) {
    std::vector<std::string> students, ignored;
    try {
        for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
            const std::string name = entry.path().filename().string();
            if (name.starts_with(".") || name == "__MACOSX") continue;
            // A link to a folder is a student too, whom grade refuses (not graded): a link could lead to the solution.
            std::error_code unreadable; // a link in a loop leads nowhere: noted like a file
            if (entry.is_directory(unreadable)) students.push_back(name);
            else ignored.push_back(name + (entry.is_symlink(unreadable) ? " (a link)" : ""));
        }
    } catch (const fs::filesystem_error& error) {
        throw UsageError("cannot read " + folder.string() + ": " + error.code().message());
    }
    std::sort(students.begin(), students.end());
    std::sort(ignored.begin(), ignored.end());
    if (!quiet && !ignored.empty()) {
        std::string names;
        for (const std::string& name : ignored) names += (names.empty() ? "" : ", ") + name;
        print_line(stderr, "note: ignored what is not a student's folder in " + folder.string() + ": " + names);
    }
    if (students.empty()) throw UsageError(folder.string() + " has no student folders (one subfolder per student)");
    return students;
}

// GRADES_DIR must be new, empty or grade-all's (it has the marker), and apart from the class.
void prepare_grades_folder(const fs::path& out, const fs::path& folder) {
    if (path_inside(out, folder) || path_inside(folder, out))
        throw UsageError("--out " + out.string() + " and " + folder.string() + " must not be inside one another");
    if (fs::exists(out) && (!fs::is_directory(out) || (!fs::is_empty(out) && !fs::exists(out / kClassMarker))))
        throw UsageError(out.string() + " exists and is not grade-all's; choose a new or empty --out");
    fs::create_directories(out);
    fs::permissions(out, fs::perms::owner_all); // the gradings' copied labs and reports are the students'
    std::ofstream marker(out / kClassMarker, std::ios::binary);
    if (!(marker << "whitted grade-all output: one grading folder per student\n").flush())
        throw UsageError("cannot write in " + out.string());
}

// Writes the CSV beside FILE first and renames it, so FILE is never half written.
void write_atomically(const fs::path& file, const std::string& text) {
    std::string temporary = file.string() + ".XXXXXX";
    const int fd = mkstemp(temporary.data());
    if (fd < 0) throw std::runtime_error("cannot write " + file.string());
    const bool written = static_cast<std::size_t>(write(fd, text.data(), text.size())) == text.size() && fsync(fd) == 0;
    if (close(fd) != 0 || !written || std::rename(temporary.c_str(), file.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + file.string());
    }
    fs::permissions(file, fs::perms(0644)); // mkstemp made it private; a grade book is read by others too
}

// A new folder for the gradings' kits (their TMPDIR), enterable by the student code's user like /tmp, so that
// what a killed grading staged is removed with it.
fs::path make_staging_folder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = (tmp && *tmp ? std::string(tmp) : std::string("/tmp")) + "/whitted-grade-all-XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a folder in " + fs::path(pattern).parent_path().string());
    fs::permissions(pattern, fs::perms(0711));
    return pattern;
}

struct Running {
    std::string student;
    std::chrono::steady_clock::time_point start;
};

int run_grade_all(const GradeAllOptions& options) {
    const fs::path folder = fs::weakly_canonical(fs::absolute(options.folder));
    const fs::path out = fs::weakly_canonical(fs::absolute(options.out));
    const fs::path csv = fs::weakly_canonical(fs::absolute(options.csv));
    if (!fs::is_directory(csv.parent_path())) throw UsageError("--csv: no such folder: " + csv.parent_path().string());
    if (fs::is_directory(csv)) throw UsageError("--csv: " + csv.string() + " is a folder");
    const std::vector<std::string> students = list_students(folder, options.quiet);
    prepare_grades_folder(out, folder);
    std::vector<std::string> passed_on;
    for (const auto& [name, value] : options.passed_on)
        if (!value.empty()) passed_on.insert(passed_on.end(), {name, value});
    if (options.allow_exposed_answers) passed_on.push_back("--allow-exposed-answers");
    const fs::path self = fs::read_symlink("/proc/self/exe");
    const fs::path staging = make_staging_folder();

    struct sigaction action {};
    action.sa_handler = on_stop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    // What a grading leaves behind when it is killed comes back to us, to be killed too.
    become_subreaper();

    ClassProgress progress(stderr, students.size(), options.parallel, isatty(STDERR_FILENO) != 0, options.quiet);
    std::vector<StudentGrade> grades;
    std::map<pid_t, Running> running;
    std::size_t next = 0;
    while (!stop_signal && (next < students.size() || !running.empty())) {
        while (!stop_signal && running.size() < static_cast<std::size_t>(options.parallel) && next < students.size()) {
            const std::string& student = students[next++];
            const fs::path student_out = out / student;
            try {
                prepare_grading_folder(student_out);
                running[start_grading(self, folder / student, student_out, passed_on, staging)] = {student, std::chrono::steady_clock::now()};
            } catch (const std::exception& error) {
                grades.push_back({student, GradeStatus::error, std::nullopt, error.what()});
                progress.finished(grades.back(), 0.0);
            }
        }
        int status = 0;
        const pid_t pid = waitpid(-1, &status, WNOHANG);
        const auto found = pid > 0 ? running.find(pid) : running.end();
        if (found == running.end()) { // nothing ended, or an orphan a grading left
            if (pid <= 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
            progress.tick();
            continue;
        }
        grades.push_back(finished_grading(found->second.student, status, out / found->second.student));
        progress.finished(grades.back(), std::chrono::duration<double>(std::chrono::steady_clock::now() - found->second.start).count());
        running.erase(found);
    }
    progress.clear();
    for (const auto& [pid, grading] : running) kill_grading(pid);
    kill_leftover_children();
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    if (stop_signal) {
        print_line(stderr, "whitted grade-all: interrupted: " + std::to_string(grades.size()) + " of " + std::to_string(students.size()) +
                               " students graded, " + std::to_string(running.size()) + " gradings killed; " + csv.string() + " not written");
        return 130;
    }
    std::vector<std::string> columns = lab_names();
    columns.push_back("integration");
    write_atomically(csv, class_csv(grades, columns));
    print_text(stdout, class_summary(grades));
    print_line(stdout, "wrote " + csv.string() + "; each student's grading is in " + out.string() + "/<student>/ (grade.log, results.json, report.html)");
    // A submission the student must fix (not_graded) is theirs to fix, not a failure of the grading.
    const bool all_graded = std::all_of(grades.begin(), grades.end(), [](const StudentGrade& g) {
        return g.status == GradeStatus::graded || g.status == GradeStatus::not_graded;
    });
    return all_graded ? 0 : 3;
}

} // namespace

Command add_grade_all_command(CLI::App& app) {
    auto options = std::make_shared<GradeAllOptions>();
    CLI::App* command = app.add_subcommand("grade-all", "Grade every student's submission in a folder and write the class's CSV (instructors).");
    command->footer(
        "Each subfolder of FOLDER is one student, named by the folder (hidden folders and __MACOSX are skipped; a link to a "
        "folder is listed not_graded, as grade refuses it); each is graded "
        "by `whitted grade` in a child process, its output in GRADES_DIR/<student>/grade.log.\n"
        "The CSV: student,score,max_score,status,<one column per lab>,integration; status is graded, not_graded (a submission the student must fix, e.g. lab files in two places), grader_failure or error.\n"
        "Exit code: 0 every student graded (whatever their points) or not_graded, 2 usage error, 3 a grading failed or could not finish "
        "(the CSV is still written and lists it), 130 interrupted (no CSV written).");
    command->add_option("folder", options->folder, "The class: one subfolder per student, each a tree, its labs/ or the lab files")
        ->required()
        ->check(CLI::ExistingDirectory);
    command->add_option("--csv", options->csv, "The class's CSV, one row per student sorted by name")->required();
    command->add_option("--out", options->out, "Folder for each student's grading, GRADES_DIR/<student>/ (default ./grades)");
    command->add_option("--parallel", options->parallel,
                        "Gradings at once (default 1: on 2 cores a class of 20 took 318 s one at a time and 1509 s two "
                        "at a time, as each grading already compiles with 2 jobs and runs its tests as a pair of processes "
                        "that call each other; with more cores, try cores / 2)")
        ->check(CLI::Range(1, 64));
    command->add_flag("-q,--quiet", options->quiet, "Print only errors and the closing summary");
    // grade's own options, passed on to every grading when given.
    auto& passed = options->passed_on;
    command->add_option("--instructor-tree", passed["--instructor-tree"], "Passed on to grade")->check(CLI::ExistingDirectory);
    command->add_option("--instructor-build", passed["--instructor-build"], "Passed on to grade")->check(CLI::ExistingDirectory);
    command->add_option("--rubric", passed["--rubric"], "Passed on to grade")->check(CLI::ExistingFile);
    command->add_option("-j,--jobs", passed["--jobs"], "Passed on to grade: lab files compiled at once (default 2)")->check(CLI::Range(1, 64));
    command->add_option("--timeout", passed["--timeout"], "Passed on to grade: CPU seconds per test (default 20)")->check(CLI::Range(0.5, 3600.0));
    command->add_option("--budget", passed["--budget"], "Passed on to grade: seconds per grading (default 1800)")->check(CLI::Range(10.0, 86400.0));
    command->add_option("--memory", passed["--memory"], "Passed on to grade: MiB per test (default 2048)")->check(CLI::Range(64, 1 << 20));
    command->add_option("--max-processes", passed["--max-processes"], "Passed on to grade")->check(CLI::Range(0L, 1L << 20));
    command->add_option("--sandbox", passed["--sandbox"], "Passed on to grade: auto, bubblewrap or none")
        ->check(CLI::IsMember({"auto", "bubblewrap", "none"}));
    command->add_flag("--allow-exposed-answers", options->allow_exposed_answers, "Passed on to grade (see whitted grade --help)");
    return Command{command, [options] {
                       try {
                           return run_grade_all(*options);
                       } catch (const UsageError& error) {
                           print_line(stderr, std::string("whitted grade-all: ") + error.what());
                           return 2;
                       } catch (const std::exception& error) {
                           print_line(stderr, std::string("whitted grade-all: ") + error.what());
                           return 3;
                       }
                   }};
}

} // namespace whitted
