// The Gradescope results.json of a grading: the same bytes for the same
// submission (stable order, no times, no absolute paths, points in hundredths).
#pragma once

#include "grade/grading.hpp"

#include <string>

namespace whitted::grade {

/// results.json's text. `problem` is a grader failure to report instead of results (score 0).
std::string results_json(const GradingResult& result, const std::string& problem = {});

/// "24/25 passed: 24 passed, 1 crash".
std::string status_counts(const LabResult& lab);

/// One line per lab, as in the top-level "output" and the terminal table.
std::string lab_summary_line(const LabResult& lab);

} // namespace whitted::grade
