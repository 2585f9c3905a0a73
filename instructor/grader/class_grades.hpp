// A class's grades (`whitted grade-all`): each student's grading read back
// from its results.json, one CSV row per student, and the closing summary.
//
// Why: an instructor grading a class wants one table for the grade book, the
// same bytes for the same gradings (no times), and the students whose grading
// failed named with the reason, so that none is silently missing.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace whitted::grade {

/// How a student's grading ended: `graded` (grade exited 0 or 1 with a
/// results.json), `not_graded` (exit 2 with a results.json: the submission
/// cannot be graded as it is, e.g. lab files in two places; the student is told
/// why), `grader_failure` (exit 3, with a results.json), `error` (anything
/// else: no or an unreadable results.json, killed, another exit code).
enum class GradeStatus { graded, not_graded, grader_failure, error };

/// "graded", "not_graded", "grader_failure" or "error", as the CSV says it.
const char* grade_status_name(GradeStatus status);

/// The points of one results.json, in hundredths.
struct ResultsPoints {
    long score_cents = 0;               // the top-level "score"
    long max_cents = 0;                 // the tests' "max_score" summed
    std::map<std::string, long> labs;   // each test's "score" summed by its extra_data.lab
};

/// Reads a Gradescope results.json as `whitted grade` writes it; throws
/// std::runtime_error with a one-line reason when it is missing or malformed.
ResultsPoints read_results_points(const std::filesystem::path& results_json);

/// One student's row of the class.
struct StudentGrade {
    std::string student;                 // the submission's folder name
    GradeStatus status = GradeStatus::error;
    std::optional<ResultsPoints> points; // when results.json was read
    std::string reason;                  // unless graded: the first line of why
};

/// Points without trailing zeros: 10000 -> "100", 8750 -> "87.5", 1234 -> "12.34".
std::string compact_points(long cents);

/// A CSV field quoted as RFC 4180 asks when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

/// The class's CSV: the header `student,score,max_score,status,<lab>...`, then
/// one row per student sorted by name (bytes, so the order is the same
/// everywhere), lines ended by LF. A lab with no test in a student's
/// results.json (or no results.json) is an empty field.
std::string class_csv(std::vector<StudentGrade> grades, const std::vector<std::string>& labs);

/// The closing summary: how many were graded, their mean and median score,
/// and every student whose grading failed, by name, with the reason (each as
/// terminal_text shows it: one line, no control characters).
std::string class_summary(std::vector<StudentGrade> grades);

} // namespace whitted::grade
