// `whitted grade SUBMISSION`: build a student's labs into workers, run every
// test as the instructor's checker talking to the student's worker, and grade
// them with the rubric; writes results.json (Gradescope) and report.html. Exit codes (framework/app/exit_codes.hpp):
// 0 full marks, 1 points lost, 2 usage error, 3 grader failure (the instructor tree does not build, the rubric is wrong).
#include "commands.hpp"
#include "exit_codes.hpp"
#include "grader/builder.hpp"
#include "grader/grade_all_command.hpp"
#include "grader/grading.hpp"
#include "grader/html_report.hpp"
#include "grader/output_marker.hpp"
#include "grader/path_inside.hpp"
#include "grader/results_json.hpp"
#include "grader/submission.hpp"
#include "grader/text.hpp"
#include "usage_error.hpp"

#include <algorithm>
#include <iterator>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <stdlib.h>

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace grade;

// A test's wall clock: this many seconds per CPU second of its limit (a machine busy enough to slow a test down
// ten times stops nothing), plus the shortest idle time.
constexpr double kWallPerCpuSecond = 10.0;
// A test that uses no CPU for this long is hung, however short its CPU limit (a busy machine still gives a
// running program some CPU within a fraction of a second).
constexpr double kShortestIdleSeconds = 2.0;

struct GradeOptions {
    std::string submission;
    std::string out = "grading";
    std::string instructor_tree = WHITTED_INSTRUCTOR_TREE;
    std::string instructor_build = WHITTED_INSTRUCTOR_BUILD;
    bool allow_exposed_answers = false;
    std::string rubric;
    int jobs = 2;
    double timeout = 20.0;
    double budget = 1800.0;
    int memory_mb = 2048;
    long max_processes = 0;
    std::string sandbox = "auto";
    std::string hidden_visibility = "hidden";
    bool quiet = false;
};

// A folder the grader writes must be new, empty or written by it before
// (it has `mark`), and hold nothing the grader reads.
void check_folder(const fs::path& folder, const char* mark, const std::string& option, const std::vector<fs::path>& precious) {
    for (const fs::path& path : precious)
        if (path_inside(path, folder)) throw UsageError(folder.string() + " holds " + path.string() + "; choose another " + option);
    if (fs::exists(folder) && (!fs::is_directory(folder) || (!fs::is_empty(folder) && !fs::exists(folder / mark))))
        throw UsageError(folder.string() + " exists and is not the grader's; choose a new or empty " + option);
}

// Written whole or not at all (a new name, then renamed): a grader killed mid-write leaves no half a results.json.
void write_file(const fs::path& file, const std::string& text) {
    const fs::path part = file.string() + ".part";
    {
        std::ofstream stream(part, std::ios::binary | std::ios::trunc);
        stream << text;
        if (!stream.flush()) throw GraderFailure("cannot write " + file.string());
    }
    fs::rename(part, file);
}

// A new folder of the grader's for the kit and the workers: private to others
// but enterable (0711), so that the student's code, as another user, reaches
// only the paths it is given.
fs::path make_work_folder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = (tmp && *tmp ? std::string(tmp) : std::string("/tmp")) + "/whitted-grade-XXXXXX";
    if (!mkdtemp(pattern.data())) throw GraderFailure("cannot make a folder in " + fs::path(pattern).parent_path().string());
    fs::permissions(pattern, fs::perms(0711));
    return pattern;
}

// The line naming the two reports (the folder's name may be a student's: printed as the terminal may show it).
void print_written(const fs::path& out) {
    print_line(stdout, "wrote " + (out / "results.json").string() + " and " + (out / "report.html").string());
}

void print_table(const GradingResult& result, const fs::path& out) {
    char line[160];
    std::snprintf(line, sizeof line, "%-17s %7s / %-7s %s", "lab", "points", "max", "tests");
    print_line(stdout, line);
    for (const LabResult& lab : result.labs) print_line(stdout, lab_summary_line(lab, Audience::instructor));
    std::snprintf(line, sizeof line, "%-17s %7s / %-7s", "total", format_points(result.score_cents).c_str(), format_points(result.max_cents).c_str());
    print_line(stdout, line);
    for (const LabResult& lab : result.labs)
        for (const std::string& note : lab.notes) print_line(stdout, "note: " + lab.lab + ": " + note);
    print_written(out);
}

// A grader failure: a block of lines (the instructor build's log, say), printed as the terminal may show it.
void print_failure(const std::string& message) { print_text(stderr, "whitted grade: grader failure: " + message + "\n"); }

// The seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run_grade(const GradeOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    GradingSetup setup;
    setup.instructor_tree = fs::weakly_canonical(fs::absolute(options.instructor_tree));
    if (!fs::is_regular_file(setup.instructor_tree / "CMakeLists.txt") || !fs::is_directory(setup.instructor_tree / "solution") ||
        !fs::is_regular_file(setup.instructor_tree / "instructor" / "rubric.json"))
        throw UsageError(setup.instructor_tree.string() + " is not an instructor tree (no CMakeLists.txt, solution/ or instructor/rubric.json)");
    const std::vector<std::string> labs = lab_names();
    // A submission that is a link is not followed (nor resolved: its folder is the link's).
    const std::optional<std::string> linked = linked_submission(options.submission);
    const fs::path submission = linked ? fs::absolute(options.submission).lexically_normal() : fs::weakly_canonical(fs::absolute(options.submission));
    GradingProblem problem;
    if (linked) problem = {GradingProblem::Kind::submission, *linked};
    try {
        if (!linked) setup.submission_labs = find_lab_folder(submission, labs);
    } catch (const AmbiguousSubmission& error) {
        problem = {GradingProblem::Kind::submission, error.what()};
    }
    if (!problem.message.empty()) setup.submission_labs = {submission, "", 0};
    setup.out = fs::weakly_canonical(fs::absolute(options.out));
    setup.instructor_build = fs::weakly_canonical(fs::absolute(options.instructor_build));
    check_folder(setup.out, kGradeOutputMarker, "--out", {submission, setup.submission_labs.folder, setup.instructor_tree, setup.instructor_build});
    fs::create_directories(setup.out);
    // The grader's user alone: the copied labs and the report of an earlier grading (of the solution, say) are answers.
    fs::permissions(setup.out, fs::perms::owner_all);
    write_file(setup.out / kGradeOutputMarker, kGradeOutputMarkerText);
    fs::remove_all(setup.out / "build"); // left by graders before the checker/worker split
    // An earlier grading's results must never pass for this one's, whatever happens below.
    fs::remove(setup.out / "results.json");
    fs::remove(setup.out / "report.html");
    setup.allow_exposed_answers = options.allow_exposed_answers;
    // The verdict is CPU time, which a machine's load does not change; a test that sleeps is caught by using no CPU
    // for as long; the wall clock, far beyond both, only ends what neither catches (process_runner.hpp).
    setup.test_limits.cpu_seconds = options.timeout;
    setup.test_limits.idle_seconds = std::max(options.timeout, kShortestIdleSeconds);
    setup.test_limits.wall_seconds = kWallPerCpuSecond * options.timeout + kShortestIdleSeconds;
    setup.test_limits.address_space = static_cast<std::size_t>(options.memory_mb) << 20;
    setup.test_limits.file_size = 64 << 20;
    setup.max_processes = options.max_processes;
    setup.budget_seconds = options.budget;
    setup.sandbox = options.sandbox == "bubblewrap" ? SandboxChoice::bubblewrap
                    : options.sandbox == "none"     ? SandboxChoice::none
                                                    : SandboxChoice::automatic;
    // Orphans of a test (a process that left its group) come back to us, to be killed.
    become_subreaper();
    setup.jobs = options.jobs;
    // Each line with the seconds since the start: where a grading spends its time.
    if (!options.quiet)
        setup.progress = [start](const std::string& line) {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "grade: %5.1f s  ", seconds_since(start));
            print_line(stderr, seconds + line);
        };

    GradingResult result;
    int code = 0;
    if (!problem.message.empty()) {
        // The student's to fix: results.json says what was found, and nothing is built or run.
        write_file(setup.out / "results.json", results_json(result, problem, options.hidden_visibility));
        write_file(setup.out / "report.html", html_report(result, problem));
        print_line(stderr, "whitted grade: " + problem.message);
        print_written(setup.out);
        return exit_code::bad_input;
    }
    try {
        std::vector<std::string> known = labs;
        known.push_back("integration");
        setup.rubric = load_rubric(options.rubric.empty() ? setup.instructor_tree / "instructor" / "rubric.json" : fs::path(options.rubric), known);
        setup.work = make_work_folder();
        result = grade_submission(setup);
        code = result.max_cents > 0 && result.score_cents == result.max_cents ? exit_code::success : exit_code::negative;
    } catch (const std::exception& error) { // RubricError, GraderFailure, file system errors
        problem = {GradingProblem::Kind::grader, replace_paths(error.what(), shown_paths(setup))};
        code = exit_code::tool_failure;
    }
    if (!setup.work.empty()) {
        std::error_code ignored;
        fs::remove_all(setup.work, ignored);
    }
    write_file(setup.out / "results.json", results_json(result, problem, options.hidden_visibility));
    write_file(setup.out / "report.html", html_report(result, problem));
    if (!problem.message.empty()) print_failure(problem.message);
    print_table(result, setup.out);
    // For the instructor only: results.json and report.html are the student's to see.
    if (!result.fences.empty()) print_line(stdout, "student code ran in " + result.fences);
    if (!options.quiet) {
        char done[48];
        std::snprintf(done, sizeof done, "grade: done in %.1f s", seconds_since(start));
        print_line(stderr, done);
    }
    return code;
}

/// `whitted grade SUBMISSION ...`
Command add_grade_command(CLI::App& app) {
    auto options = std::make_shared<GradeOptions>();
    CLI::App* command = app.add_subcommand("grade", "Grade a student's labs against the instructor tree (instructors).");
    command->footer("Exit code: 0 full marks, 1 points lost, 2 usage error (a bad option, a submission or output folder "
                    "that cannot be used, lab files in two places), 3 grader failure (whitted itself failed).");
    command->add_option("submission", options->submission,
                        "The student's submission: the lab files (NN_*.cpp) at its top, in its labs/, or one folder down "
                        "(my-project/ or my-project/labs/); a folder, not a link to one")
        ->required()
        ->check(CLI::ExistingDirectory);
    command->add_option("--out", options->out, "Folder for results.json, report.html, the copied labs and each test's files (default ./grading)");
    command->add_option("--instructor-tree", options->instructor_tree, "The tree with solution/ and the tests (default: the one whitted was built from)")
        ->check(CLI::ExistingDirectory);
    command->add_option("--instructor-build", options->instructor_build,
                        "The Release build of the instructor tree whose checkers and grading kit are used, brought up to date "
                        "first (default: the one whitted was built in)")
        ->check(CLI::ExistingDirectory);
    command->add_option("--rubric", options->rubric, "Rubric file (default: <instructor tree>/instructor/rubric.json)")->check(CLI::ExistingFile);
    command->add_option("-j,--jobs", options->jobs, "Lab files compiled at once (default 2)")->check(CLI::Range(1, 64));
    command->add_option("--timeout", options->timeout, "CPU seconds per test, for the student's code and the checker each; a test whose programs use no CPU for as long "
                        "(asleep) also times out (default 20)")
        ->check(CLI::Range(0.5, 3600.0));
    command->add_option("--budget", options->budget,
                        "Wall-clock seconds for the whole grading: tests not started by then count as timed out, and "
                        "results.json is still written (default 1800)")
        ->check(CLI::Range(10.0, 86400.0));
    command->add_option("--memory", options->memory_mb, "Address space of the student's code per test in MiB (default 2048)")->check(CLI::Range(64, 1 << 20));
    command->add_option("--max-processes", options->max_processes,
                        "RLIMIT_NPROC per test: the processes and threads of the tests' user in all (default: what it runs now "
                        "plus 256; a grader running as root runs them as a user id of its own)")
        ->check(CLI::Range(0L, 1L << 20));
    command->add_option("--sandbox", options->sandbox,
                        "auto: bubblewrap when it works, else other users and permissions (refused where they leave the answers readable); bubblewrap: fail without it; none: never")
        ->check(CLI::IsMember({"auto", "bubblewrap", "none"}));
    command->add_flag("--allow-exposed-answers", options->allow_exposed_answers,
                      "Grade even where the student's code could read the answers (no bubblewrap, and not root or the "
                      "instructor files readable to other users); the grades can then be forged");
    command->add_option("--hidden-visibility", options->hidden_visibility,
                        "When Gradescope shows the student a hidden test's status and points: hidden (never, the default), "
                        "after_due_date, after_published or visible; its details are never shown")
        ->check(CLI::IsMember(std::vector<std::string>(std::begin(kVisibilities), std::end(kVisibilities))));
    command->add_flag("-q,--quiet", options->quiet, "Print only the table");
    return Command{command, [options] {
                       try {
                           return run_grade(*options);
                       } catch (const UsageError& error) {
                           print_line(stderr, std::string("whitted grade: ") + error.what());
                           return exit_code::bad_input;
                       } catch (const fs::filesystem_error& error) { // the submission or --out folder, before grading
                           print_line(stderr, std::string("whitted grade: ") + error.what());
                           return exit_code::bad_input;
                       } catch (const GraderFailure& error) {
                           print_failure(error.what());
                           return exit_code::tool_failure;
                       }
                   }};
}

} // namespace

std::vector<Command> add_instructor_commands(CLI::App& app) { return {add_grade_command(app), add_grade_all_command(app)}; }

} // namespace whitted
