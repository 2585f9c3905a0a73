// The Gradescope results.json of a grading: the same bytes for the same
// submission (stable order, no times, no absolute paths, points in hundredths).
#pragma once

#include "grader/grading.hpp"

#include <string>

namespace whitted::grade {

/// Why a grading has no results (score 0): the grader failed, or the submission cannot be graded as it is.
struct GradingProblem {
    enum class Kind { grader, submission };
    Kind kind = Kind::grader;
    std::string message; // empty: no problem
};

/// When Gradescope shows the student a hidden test (its status and points only): "hidden" (never),
/// "after_due_date", "after_published" or "visible".
inline constexpr const char* kVisibilities[] = {"hidden", "after_due_date", "after_published", "visible"};

/// results.json's text; hidden tests get `hidden_visibility` (one of kVisibilities).
std::string results_json(const GradingResult& result, const GradingProblem& problem = {},
                         const std::string& hidden_visibility = "hidden");

/// Who reads a summary: the student sees hidden tests only as passed or failed (student_status).
enum class Audience { student, instructor };

/// "24/25 passed (1 crash)".
std::string status_counts(const LabResult& lab, Audience audience);

/// One line per lab: the top-level "output" (student) and the terminal table (instructor).
std::string lab_summary_line(const LabResult& lab, Audience audience);

} // namespace whitted::grade
