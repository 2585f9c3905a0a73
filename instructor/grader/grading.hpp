// Grading one submission: build the student's workers from the grading kit,
// list every lab's tests (the checkers alone), then in two passes, every lab's
// visible tests and then every lab's hidden tests (scoring.hpp's Pass: a
// hidden test's time cannot decide which visible tests run), lab by lab in
// rubric order: run the pass's tests all in one checker and worker pair, run
// each that did not pass there in a pair of its own unless a prerequisite
// failed, and score them with the rubric.
#pragma once

#include "process/process_runner.hpp"
#include "grader/rubric.hpp"
#include "grader/sandbox.hpp"
#include "grader/scoring.hpp"
#include "grader/submission.hpp"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted::grade {

/// Grading cannot go on, and not because of the submission (exit code 3).
struct GraderFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct GradingSetup {
    std::filesystem::path instructor_tree;  // absolute
    std::filesystem::path instructor_build; // absolute; its checkers and grading kit are used (brought up to date first)
    LabFolder submission_labs;              // where the submission's lab files are (find_lab_folder)
    std::filesystem::path out;              // absolute; labs/ and tests/ are written here
    std::filesystem::path work;             // absolute; a new private folder for the kit and the workers (removed after)
    Rubric rubric;
    Limits test_limits;
    SandboxChoice sandbox = SandboxChoice::automatic;
    bool allow_exposed_answers = false; // grade even where the student's code could read the answers
    long max_processes = 0; // RLIMIT_NPROC for the student's code; 0: chosen by make_sandbox
    int jobs = 2;
    double budget_seconds = 1800; // the whole grading's wall clock: tests not started by then are not run (timeout)
    std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct LabResult {
    std::string lab;
    std::string title;
    std::vector<ScoredTest> tests; // in the order the program lists them
    std::string compile_errors;    // the compiler's first errors, when the lab did not build
    std::string problem;           // why none of its tests ran (missing, refused, not built): said once for the lab
    std::vector<std::string> notes; // rubric notes: unmatched tests, unknown names
    long score_cents = 0;
    long max_cents = 0;
};

/// Whether the outcome is the lab's own problem (LabResult::problem), not one of this test's.
inline bool is_lab_wide(const LabResult& lab, const TestOutcome& outcome) {
    return !lab.problem.empty() && outcome.message == lab.problem;
}

struct GradingResult {
    std::vector<LabResult> labs;
    long score_cents = 0;
    long max_cents = 0;
    std::string fences; // for the instructor only: which fences the student's code ran behind (Sandbox::description)
};

/// Grades the submission. Throws GraderFailure when the instructor tree does not configure or build.
GradingResult grade_submission(const GradingSetup& setup);

/// Absolute path prefixes and what to show instead, for everything the student sees.
std::vector<std::pair<std::string, std::string>> shown_paths(const GradingSetup& setup);

} // namespace whitted::grade
