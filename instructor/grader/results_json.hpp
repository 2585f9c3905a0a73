// The Gradescope results.json of a grading: the same bytes for the same
// submission (stable order, no times, no absolute paths, points in hundredths).
#pragma once

#include "grader/grading.hpp"

#include <string>

namespace whitted::grade {

/// results.json's text. `problem` is a grader failure to report instead of results (score 0).
std::string results_json(const GradingResult& result, const std::string& problem = {});

/// Who reads a summary: the student sees hidden tests only as passed or failed (student_status).
enum class Audience { student, instructor };

/// "24/25 passed (1 crash)".
std::string status_counts(const LabResult& lab, Audience audience);

/// One line per lab: the top-level "output" (student) and the terminal table (instructor).
std::string lab_summary_line(const LabResult& lab, Audience audience);

} // namespace whitted::grade
