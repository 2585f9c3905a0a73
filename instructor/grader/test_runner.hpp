// Runs one GoogleTest test of a lab as two processes: the instructor's checker
// (the test, the reference, the verdict) and the student's worker (the lab
// code), joined by the grading link (instructor/link/), and tells how it ended.
//
// Why two: a test program that links the student's code lets that code decide
// its own grade (rewrite GoogleTest's report, register tests of its own, call
// the reference linked beside it). Here the student's code only answers calls;
// the checker, a program built from the instructor's tree alone that the
// worker can neither read nor signal, writes the report the grader reads.
#pragma once

#include "grader/outcome.hpp"
#include "process/process_runner.hpp"
#include "grader/sandbox.hpp"

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace whitted::grade {

struct TestProgram {
    std::string lab;                    // the lab its tests belong to
    std::filesystem::path checker;      // check_<lab>, from the instructor build, absolute
    std::vector<std::string> worker;    // the student's worker and its arguments (run inside the sandbox)
    std::filesystem::path output;       // test folders go in <output>/<test folder>/, written by the checker only
    Limits limits;
    std::vector<std::pair<std::string, std::string>> path_replacements; // absolute -> shown
    Sandbox sandbox; // the fences of the worker
    double linger_seconds = 2.0; // how long the worker may take to end once the checker has
};

/// The test names ("Suite.Test") the checker lists, in its order; empty when
/// listing failed, with the reason in `problem`.
std::vector<std::string> list_tests(const TestProgram& program, std::string& problem);

/// Runs one test: the checker with the test's folder, the worker in the sandbox,
/// a new link between them; then kills whatever either left running.
TestOutcome run_test(const TestProgram& program, const std::string& test_name);

/// Runs the tests in one checker and worker pair, under the limits of one test
/// but at most `wall_seconds`, and returns the names of those that passed.
/// Why: starting a pair costs about 30 ms, more than most tests; a lab's unit
/// tests run together in a tenth of the time. What only a test run on its own
/// tells (why it failed, what the student's code printed, its pictures) is not
/// read here: the caller runs every test not returned on its own. So a run that
/// did not end cleanly (a crash, a timeout, a broken link, code left running,
/// a test that wrote files, a test GoogleTest did not report) returns nothing.
std::set<std::string> passed_together(const TestProgram& program, const std::vector<std::string>& test_names, double wall_seconds);

/// Asks the checker alone for an image test's reference picture (nothing is
/// rendered); returns the folder holding reference.png, or empty.
std::filesystem::path fetch_reference_picture(const TestProgram& program, const std::string& test_name);

/// The folder name for a test: its name with '/' (parameterised tests) as '_', never "." or "..".
std::string folder_name(const std::string& test_name);

} // namespace whitted::grade
