// Runs the GoogleTest tests of one grading program, each in its own process,
// and tells how each one ended (outcome.hpp).
#pragma once

#include "grade/outcome.hpp"
#include "grade/process_runner.hpp"
#include "grade/sandbox.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace whitted::grade {

struct TestProgram {
    std::string lab;                // the lab its tests belong to
    std::filesystem::path program;  // grade_<lab>, absolute
    std::filesystem::path output;   // test folders go in <output>/<test name>/
    Limits limits;
    std::vector<std::pair<std::string, std::string>> path_replacements; // absolute -> shown
    Sandbox sandbox; // the fences every run of the program goes through
};

/// The test names ("Suite.Test") the program lists, in its order; empty when
/// listing failed, with the reason in `problem`.
std::vector<std::string> list_tests(const TestProgram& program, std::string& problem);

/// Runs one test in its own process group under the program's limits and
/// sandbox, then kills whatever it left running.
TestOutcome run_test(const TestProgram& program, const std::string& test_name);

/// Asks an image test for its reference picture only (it does not render);
/// returns the folder holding reference.png, or empty.
std::filesystem::path fetch_reference_picture(const TestProgram& program, const std::string& test_name);

/// The folder name for a test: its name with '/' (parameterised tests) as '_'.
std::string folder_name(const std::string& test_name);

} // namespace whitted::grade
