#include "grader/results_json.hpp"
#include "grader/outcome.hpp"
#include "grader/text.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <map>

namespace whitted::grade {
namespace {

using nlohmann::ordered_json;

// Points as a JSON number made from whole hundredths (so 1/3 of a point never appears).
double points(long cents) { return static_cast<double>(cents) / 100.0; }

std::string test_output(const LabResult& lab, const ScoredTest& test) {
    const TestOutcome& o = test.outcome;
    if (is_hidden(o.name))
        return std::string(status_label(student_status(o))) +
               (o.status == Status::passed ? "\n" : "\nThe details of hidden tests are not shown.\n");
    std::string text = std::string(status_label(o.status));
    // Said once, at the top: not in each of the lab's tests.
    if (is_lab_wide(lab, o)) return text + ": not run; why is said once for " + lab.lab + ", at the top\n";
    if (!o.message.empty()) text += ": " + o.message;
    text += "\n";
    if (o.image) text += image_summary(*o.image) + "\n";
    if (o.status == Status::failed && o.image && test.score_cents > 0 && test.score_cents < test.max_cents)
        text += "partial credit for the image: " + format_points(test.score_cents) + " of " + format_points(test.max_cents) + "\n";
    if (!o.output.empty() && o.status != Status::passed) text += "\n" + o.output;
    return text;
}

// JSON escapes C0 but leaves DEL and the C1 controls (U+0080-U+009F) raw: written as \u escapes (the same text), so that
// results.json shown on a terminal cannot drive it. The dump is valid UTF-8: a 0xc2 byte before 0x80-0x9f is such a control.
std::string escape_raw_controls(const std::string& json) {
    std::string text;
    text.reserve(json.size());
    for (std::size_t i = 0; i < json.size(); ++i) {
        const auto c = static_cast<unsigned char>(json[i]);
        const unsigned next = i + 1 < json.size() ? static_cast<unsigned char>(json[i + 1]) : 0u;
        if (c != 0x7f && !(c == 0xc2 && next >= 0x80 && next < 0xa0)) {
            text += json[i];
            continue;
        }
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04x", c == 0x7f ? 0x7fu : next);
        text += escape;
        i += c == 0xc2; // the control's second byte
    }
    return text;
}

} // namespace

std::string status_counts(const LabResult& lab, Audience audience) {
    std::map<Status, int> counts;
    for (const ScoredTest& test : lab.tests)
        ++counts[audience == Audience::student ? student_status(test.outcome) : test.outcome.status];
    std::string text = std::to_string(counts[Status::passed]) + "/" + std::to_string(lab.tests.size()) + " passed";
    std::string others;
    for (Status status : all_statuses())
        if (status != Status::passed && counts[status])
            others += (others.empty() ? "" : ", ") + std::to_string(counts[status]) + " " + std::string(status_label(status));
    return others.empty() ? text : text + " (" + others + ")";
}

std::string lab_summary_line(const LabResult& lab, Audience audience) {
    char line[512];
    std::snprintf(line, sizeof line, "%-17s %7s / %-7s %s", lab.lab.c_str(), format_points(lab.score_cents).c_str(),
                  format_points(lab.max_cents).c_str(), status_counts(lab, audience).c_str());
    return line;
}

std::string results_json(const GradingResult& result, const GradingProblem& problem, const std::string& hidden_visibility) {
    ordered_json root;
    const bool failed = !problem.message.empty();
    root["score"] = points(failed ? 0 : result.score_cents);
    std::string output;
    if (failed && problem.kind == GradingProblem::Kind::grader)
        output = "The grader failed; this is not your fault. Please tell your instructor.\n" + problem.message + "\n";
    else if (failed)
        output = "Your submission was not graded: " + problem.message + "\n";
    for (const LabResult& lab : result.labs) output += lab_summary_line(lab, Audience::student) + "\n";
    if (!failed) output += "total: " + format_points(result.score_cents) + " / " + format_points(result.max_cents) + "\n";
    for (const LabResult& lab : result.labs)
        if (!lab.problem.empty()) output += "\n" + lab.lab + ": " + lab.problem + "\n" + lab.compile_errors;
    root["output"] = output;
    root["output_format"] = "text";
    root["visibility"] = "visible";
    root["stdout_visibility"] = "hidden";
    root["tests"] = ordered_json::array();
    int lab_number = 0;
    for (const LabResult& lab : result.labs) {
        ++lab_number;
        int test_number = 0;
        for (const ScoredTest& test : lab.tests) {
            const TestOutcome& o = test.outcome;
            ordered_json entry;
            entry["name"] = lab.title + ": " + o.name;
            entry["number"] = std::to_string(lab_number) + "." + std::to_string(++test_number);
            entry["score"] = points(test.score_cents);
            entry["max_score"] = points(test.max_cents);
            entry["status"] = o.status == Status::passed ? "passed" : "failed";
            entry["output"] = test_output(lab, test);
            entry["output_format"] = "text";
            const std::string shown = std::string(status_name(student_status(o)));
            entry["tags"] = {lab.lab, test.rule.empty() ? "unscored" : test.rule, shown};
            entry["visibility"] = is_hidden(o.name) ? hidden_visibility : "visible";
            entry["extra_data"] = {{"lab", lab.lab}, {"status", shown}, {"image", test.image_test}};
            root["tests"].push_back(entry);
        }
    }
    // What the student's code printed and the compiler said may hold any bytes: invalid UTF-8 becomes U+FFFD.
    return escape_raw_controls(root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace)) + "\n";
}

} // namespace whitted::grade
