// report.html: one self-contained page (styles inline, pictures as data: URIs)
// with the score per lab, compile errors, and every test, failures first; image
// tests show the student's picture, the reference, the difference and a heat map.
#pragma once

#include "grader/grading.hpp"
#include "grader/results_json.hpp"

#include <string>

namespace whitted::grade {

/// The page's HTML.
std::string html_report(const GradingResult& result, const GradingProblem& problem = {});

} // namespace whitted::grade
