#include "grader/outcome.hpp"

#include "whitted/image_compare.hpp"

#include <cstdio>

namespace whitted::grade {

std::string_view status_name(Status status) {
    switch (status) {
    case Status::passed: return "passed";
    case Status::failed: return "failed";
    case Status::not_implemented: return "not_implemented";
    case Status::exception: return "exception";
    case Status::crash: return "crash";
    case Status::timeout: return "timeout";
    case Status::compile_error: return "compile_error";
    case Status::missing: return "missing";
    case Status::skipped: return "skipped";
    }
    return "unknown";
}

std::string_view status_label(Status status) {
    switch (status) {
    case Status::not_implemented: return "not implemented";
    case Status::compile_error: return "compile error";
    default: return status_name(status);
    }
}

const std::vector<Status>& all_statuses() {
    static const std::vector<Status> statuses = {Status::passed,    Status::failed,  Status::not_implemented,
                                                 Status::exception, Status::crash,   Status::timeout,
                                                 Status::compile_error, Status::missing, Status::skipped};
    return statuses;
}

std::string image_summary(const ImageNumbers& image) {
    char psnr[32] = "inf";
    if (image.psnr) std::snprintf(psnr, sizeof psnr, "%.1f", *image.psnr);
    const ImageGate gate;
    char line[320];
    std::snprintf(line, sizeof line,
                  "image gate %s: %.3f %% of the pixels off by more than %.0f/255 (limit %g %%), mean error %.2f/255 "
                  "(limit %g), max error %.0f/255 at (%d, %d), PSNR %s dB, %lld NaN/Inf pixels",
                  image.passed ? "passed" : "failed", 100.0 * image.failing_fraction, 255.0 * gate.pixel_tolerance,
                  100.0 * gate.max_failing_fraction, 255.0 * image.mean_error, 255.0 * gate.max_mean_error,
                  255.0 * image.max_error, image.worst_x, image.worst_y, psnr, image.non_finite_pixels);
    return line;
}

bool is_hidden(const std::string& test_name) { return test_name.rfind("Hidden", 0) == 0; }

Status student_status(const TestOutcome& outcome) {
    if (!is_hidden(outcome.name)) return outcome.status;
    switch (outcome.status) {
    case Status::passed:
    case Status::compile_error:
    case Status::missing:
    case Status::skipped: return outcome.status;
    default: return Status::failed;
    }
}

} // namespace whitted::grade
