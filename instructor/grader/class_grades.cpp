#include "grader/class_grades.hpp"
#include "grader/submission.hpp"
#include "grader/text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace whitted::grade {
namespace {

// A results.json is at most this long: 189 tests with their outputs and compile errors take about 200 KiB.
constexpr std::size_t kMaxResultsBytes = 64 << 20;

long to_cents(const nlohmann::json& value, const std::string& what) {
    if (!value.is_number()) throw std::runtime_error("results.json: " + what + " is not a number");
    const double points = value.get<double>();
    if (!std::isfinite(points) || std::fabs(points) > 1e12) throw std::runtime_error("results.json: " + what + " is out of range");
    return std::lround(points * 100.0);
}

std::string rounded_points(double cents) { return compact_points(std::lround(cents)); }

} // namespace

const char* grade_status_name(GradeStatus status) {
    switch (status) {
    case GradeStatus::graded: return "graded";
    case GradeStatus::not_graded: return "not_graded";
    case GradeStatus::grader_failure: return "grader_failure";
    case GradeStatus::error: break;
    }
    return "error";
}

ResultsPoints read_results_points(const std::filesystem::path& results_json) {
    std::string text;
    try {
        text = read_regular_file(results_json, kMaxResultsBytes);
    } catch (const std::exception& error) {
        throw std::runtime_error("results.json " + std::string(error.what()));
    }
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception&) {
        throw std::runtime_error("results.json is not valid JSON");
    }
    if (!root.is_object() || !root.contains("score") || !root.contains("tests") || !root["tests"].is_array())
        throw std::runtime_error("results.json has no score or no tests[]");
    ResultsPoints points;
    points.score_cents = to_cents(root["score"], "score");
    for (const nlohmann::json& test : root["tests"]) {
        if (!test.is_object() || !test.contains("score") || !test.contains("max_score"))
            throw std::runtime_error("results.json has a test without score or max_score");
        const long score = to_cents(test["score"], "a test's score");
        points.max_cents += to_cents(test["max_score"], "a test's max_score");
        const nlohmann::json* lab = test.contains("extra_data") && test["extra_data"].is_object() && test["extra_data"].contains("lab")
                                        ? &test["extra_data"]["lab"]
                                        : nullptr;
        if (!lab || !lab->is_string()) throw std::runtime_error("results.json has a test without extra_data.lab");
        points.labs[lab->get<std::string>()] += score;
    }
    return points;
}

std::string compact_points(long cents) {
    const long whole = std::labs(cents) / 100, part = std::labs(cents) % 100;
    std::string text = cents < 0 ? "-" : "";
    text += std::to_string(whole);
    if (part == 0) return text;
    if (part % 10 == 0) return text + "." + std::to_string(part / 10);
    return text + (part < 10 ? ".0" : ".") + std::to_string(part);
}

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string class_csv(std::vector<StudentGrade> grades, const std::vector<std::string>& labs) {
    std::sort(grades.begin(), grades.end(), [](const StudentGrade& a, const StudentGrade& b) { return a.student < b.student; });
    std::string csv = "student,score,max_score,status";
    for (const std::string& lab : labs) csv.append(",").append(csv_field(lab));
    csv += "\n";
    for (const StudentGrade& grade : grades) {
        csv += csv_field(grade.student) + ",";
        if (grade.points) csv += compact_points(grade.points->score_cents) + "," + compact_points(grade.points->max_cents);
        else csv += ",";
        csv += std::string(",") + grade_status_name(grade.status);
        for (const std::string& lab : labs) {
            csv += ",";
            if (!grade.points) continue;
            const auto found = grade.points->labs.find(lab);
            if (found != grade.points->labs.end()) csv += compact_points(found->second);
        }
        csv += "\n";
    }
    return csv;
}

std::string class_summary(std::vector<StudentGrade> grades) {
    std::sort(grades.begin(), grades.end(), [](const StudentGrade& a, const StudentGrade& b) { return a.student < b.student; });
    std::vector<long> scores;
    long max_cents = 0;
    for (const StudentGrade& grade : grades)
        if (grade.status == GradeStatus::graded && grade.points) {
            scores.push_back(grade.points->score_cents);
            max_cents = std::max(max_cents, grade.points->max_cents);
        }
    std::string text = "graded " + std::to_string(scores.size()) + " of " + std::to_string(grades.size()) + " students";
    if (!scores.empty()) {
        std::sort(scores.begin(), scores.end());
        double sum = 0;
        for (const long score : scores) sum += static_cast<double>(score);
        const std::size_t middle = scores.size() / 2;
        const double median = scores.size() % 2 ? static_cast<double>(scores[middle])
                                                : (static_cast<double>(scores[middle - 1]) + static_cast<double>(scores[middle])) / 2.0;
        text += ": mean " + rounded_points(sum / static_cast<double>(scores.size())) + ", median " + rounded_points(median) + " of " +
                compact_points(max_cents);
    }
    text += "\n";
    std::string failures;
    int failed = 0;
    for (const StudentGrade& grade : grades) {
        if (grade.status == GradeStatus::graded) continue;
        ++failed;
        failures += "  " + terminal_text(grade.student) + ": " +
                    (grade.status == GradeStatus::grader_failure ? "grader failure: "
                     : grade.status == GradeStatus::not_graded   ? "not graded: "
                                                                 : "error: ") +
                    terminal_text(grade.reason) + "\n";
    }
    if (failed) text += "not graded (" + std::to_string(failed) + "):\n" + failures;
    return text;
}

} // namespace whitted::grade
