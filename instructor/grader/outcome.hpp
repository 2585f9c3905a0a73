// What grading found out about one test, before and after the rubric.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace whitted::grade {

/// How a test ended, from best to worst; the names are those of results.json and the report.
enum class Status {
    passed,          // the test passed
    failed,          // wrong answer: an assertion failed
    not_implemented, // a lab function still throws NotImplemented
    exception,       // another C++ exception escaped the test
    crash,           // killed by a signal (SIGSEGV, SIGABRT, ...)
    timeout,         // over the wall-clock or CPU-time limit
    compile_error,   // the lab did not compile or link
    missing,         // the submission has no file for the lab
    skipped,         // not run: a prerequisite failed
};

/// "not_implemented" and so on.
std::string_view status_name(Status status);
/// "not implemented" and so on, for people.
std::string_view status_label(Status status);
/// Every status, in declaration order.
const std::vector<Status>& all_statuses();

/// The numbers of the image gate for one image test (tests/support/image_pictures.hpp).
struct ImageNumbers {
    bool passed = false;
    double failing_fraction = 1.0;
    double mean_error = 1.0; // fractions of full scale
    double max_error = 1.0;
    int worst_x = 0, worst_y = 0;
    std::optional<double> psnr; // empty for identical images
    long long non_finite_pixels = 0;
};

/// One line with the gate's numbers, for people.
std::string image_summary(const ImageNumbers& image);

/// One test of one lab as it ran (or did not).
struct TestOutcome {
    std::string lab;  // "03_blinn_phong", or "integration"
    std::string name; // "Suite.Test" as GoogleTest lists it
    Status status = Status::skipped;
    std::string message;                 // one line: why it did not pass (empty when it passed)
    std::string output;                  // failure details and the test's own output, trimmed
    std::optional<ImageNumbers> image;   // for tests that compared an image
    std::filesystem::path pictures;      // folder with yours/reference/diff/heat.png, if any
};

/// True for tests of suites whose names start with "Hidden".
bool is_hidden(const std::string& test_name);

/// The status a student is shown. Of a hidden test only passed or failed (or
/// what the files decided: compile_error, missing, skipped): the student's
/// code chooses among crash, timeout, exception, not_implemented and failed,
/// so showing which would tell it something of the hidden inputs each time.
Status student_status(const TestOutcome& outcome);

} // namespace whitted::grade
