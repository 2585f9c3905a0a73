// Reading what one test run left behind: how the test ended (from its process
// and GoogleTest's JSON report) and, for image tests, the gate's numbers.
#pragma once

#include "grader/outcome.hpp"
#include "process/process_runner.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace whitted::grade {

/// Sets the outcome's status, one-line message and details (failure messages
/// and the test's own output, without GoogleTest's timings). `report_file` is
/// GoogleTest's JSON report; a test that never wrote it crashed.
void classify_run(TestOutcome& outcome, const ProcessRun& run, const Limits& limits, const std::filesystem::path& report_file);

/// The same for a test run as a checker and a worker (test_runner.hpp): the
/// worker's ending comes first (a crash, a timeout, code that went on running
/// or exited early is never a pass, whatever the checker says), then the
/// checker's verdict. The worker's output follows the details, marked as such.
/// `link_file` is where the checker wrote why the link broke, if it did.
void classify_pair(TestOutcome& outcome, const ProcessRun& checker, const ProcessRun& worker, const Limits& limits,
                   const std::filesystem::path& report_file, const std::filesystem::path& link_file);

/// Every test GoogleTest's JSON report records, with true for those that passed
/// (no failure); empty if the file is missing, unreadable or not a report.
std::optional<std::map<std::string, bool>> read_test_results(const std::filesystem::path& report_file);

/// Reads tests/support's image.json; empty if the file is missing or unreadable.
std::optional<ImageNumbers> read_image_numbers(const std::filesystem::path& file);

} // namespace whitted::grade
