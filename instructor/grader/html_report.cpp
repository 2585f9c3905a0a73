#include "grader/html_report.hpp"
#include "grader/results_json.hpp"
#include "grader/submission.hpp"
#include "grader/text.hpp"

#include <array>
#include <fstream>
#include <sstream>

namespace whitted::grade {
namespace {

// The text as HTML, control characters and bytes that are not UTF-8 shown as escapes (terminal_text): what the
// student's code printed and the compiler said may hold any bytes, and the page stays valid UTF-8.
std::string escape(const std::string& text) {
    std::string out;
    for (char c : terminal_text(text, Newlines::kept)) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        unsigned value = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) value |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) value |= static_cast<unsigned char>(bytes[i + 2]);
        out += digits[(value >> 18) & 63];
        out += digits[(value >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(value >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[value & 63] : '=';
    }
    return out;
}

// <figure> with the picture inlined, or nothing when it is not there or not a
// regular file of at most 16 MiB (read without following links or blocking).
std::string figure(const std::filesystem::path& file, const std::string& caption) {
    std::string bytes;
    try {
        bytes = read_regular_file(file, std::size_t{16} << 20);
    } catch (const std::exception&) {
        return {};
    }
    return "<figure><img alt=\"" + caption + "\" src=\"data:image/png;base64," + base64(bytes) +
           "\"><figcaption>" + caption + "</figcaption></figure>";
}

const char* kStyle = R"(
body{font-family:system-ui,sans-serif;margin:2em;color:#222;max-width:1200px}
table{border-collapse:collapse}td,th{padding:.3em .8em;border-bottom:1px solid #ddd;text-align:left}
.test{border:1px solid #ccc;border-radius:6px;margin:1em 0;padding:.6em 1em}
.badge{display:inline-block;padding:.1em .6em;border-radius:1em;color:#fff;font-size:.85em;margin-right:.5em}
.passed{background:#2a7d2e}.failed{background:#c0392b}.not_implemented{background:#7f8c8d}.exception{background:#8e44ad}
.crash{background:#000}.timeout{background:#d35400}.compile_error{background:#a93226}.missing{background:#95a5a6}
.skipped{background:#b7950b}
pre{background:#f6f6f6;padding:.6em;overflow-x:auto;white-space:pre-wrap}
figure{display:inline-block;margin:.3em}figure img{image-rendering:pixelated;width:240px;border:1px solid #999}
figcaption{text-align:center;font-size:.85em}.points{float:right;font-weight:bold}
.scale{display:inline-block;width:1.2em;height:1em;vertical-align:middle;border:1px solid #999}
)";

std::string heat_legend() {
    const std::array<std::pair<const char*, const char*>, 7> stops = {{{"#000000", "0"},
                                                                       {"#00008c", "4 (tolerance)"},
                                                                       {"#00cc00", "5"},
                                                                       {"#ffff00", "16"},
                                                                       {"#ff0000", "64"},
                                                                       {"#ffffff", "255"},
                                                                       {"#ff00ff", "NaN/Inf"}}};
    std::string html = "<p>Heat map scale (largest channel error in 8-bit steps): ";
    for (const auto& [color, label] : stops)
        html += std::string("<span class=\"scale\" style=\"background:") + color + "\"></span> " + label + " &nbsp; ";
    return html + "</p>\n";
}

// One test; its id is the test's number in results.json ("test-2.5").
std::string test_card(const LabResult& lab, const ScoredTest& test, const std::string& number) {
    const TestOutcome& o = test.outcome;
    const Status shown = student_status(o);
    std::string html = "<div class=\"test\" id=\"test-" + number + "\"><span class=\"points\">" + format_points(test.score_cents) + " / " +
                       format_points(test.max_cents) + "</span><span class=\"badge " + std::string(status_name(shown)) +
                       "\">" + std::string(status_label(shown)) + "</span><b>" + escape(o.name) + "</b> &middot; " +
                       escape(lab.title) + (is_hidden(o.name) ? " &middot; <i>hidden test</i>" : "") + "\n";
    // The student sees this page: a hidden test's message, output, image numbers or pictures would tell its
    // inputs, its expected values or its reference picture.
    if (is_hidden(o.name)) {
        if (o.status != Status::passed) html += "<p>The details of hidden tests are not shown.</p>\n";
        return html + "</div>\n";
    }
    if (!o.message.empty()) html += "<p>" + escape(o.message) + "</p>\n";
    if (o.image) html += "<p>" + escape(image_summary(*o.image)) + "</p>\n";
    if (!o.pictures.empty()) {
        html += "<div>" + figure(o.pictures / "yours.png", "yours") + figure(o.pictures / "reference.png", "reference") +
                figure(o.pictures / "diff.png", "difference &times;16") + figure(o.pictures / "heat.png", "heat map") + "</div>\n";
    }
    if (o.status == Status::compile_error && !lab.compile_errors.empty())
        html += "<p>The compiler's errors are above, under &ldquo;" + escape(lab.title) + " does not compile&rdquo;.</p>\n";
    else if (o.status != Status::passed && !o.output.empty())
        html += "<pre>" + escape(o.output) + "</pre>\n";
    return html + "</div>\n";
}

} // namespace

std::string html_report(const GradingResult& result, const GradingProblem& problem) {
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Grading report</title><style>" +
                       std::string(kStyle) + "</style></head><body>\n<h1>Grading report: " +
                       format_points(result.score_cents) + " / " + format_points(result.max_cents) + "</h1>\n";
    if (!problem.message.empty())
        html += std::string(problem.kind == GradingProblem::Kind::grader ? "<h2>The grader failed</h2><pre>" : "<h2>Your submission was not graded</h2><pre>") +
                escape(problem.message) + "</pre>\n";
    html += "<table><tr><th>lab</th><th>points</th><th>tests</th></tr>\n";
    for (const LabResult& lab : result.labs) {
        html += "<tr><td>" + escape(lab.title) + "</td><td>" + format_points(lab.score_cents) + " / " +
                format_points(lab.max_cents) + "</td><td>" + escape(status_counts(lab, Audience::student)) + "</td></tr>\n";
    }
    html += "</table>\n";
    std::string notes;
    for (const LabResult& lab : result.labs)
        for (const std::string& note : lab.notes) notes += "<li>" + escape(lab.lab + ": " + note) + "</li>\n";
    if (!notes.empty()) html += "<details><summary>Rubric notes (for instructors)</summary><ul>\n" + notes + "</ul></details>\n";
    for (const LabResult& lab : result.labs)
        if (!lab.compile_errors.empty())
            html += "<h2>" + escape(lab.title) + " does not compile</h2><pre>" + escape(lab.compile_errors) + "</pre>\n";

    std::string failed, passed;
    for (std::size_t l = 0; l < result.labs.size(); ++l)
        for (std::size_t t = 0; t < result.labs[l].tests.size(); ++t) {
            const ScoredTest& test = result.labs[l].tests[t];
            (test.outcome.status == Status::passed ? passed : failed) +=
                test_card(result.labs[l], test, std::to_string(l + 1) + "." + std::to_string(t + 1));
        }
    html += heat_legend() + "<h2>Tests that did not pass</h2>\n";
    html += failed.empty() ? "<p>None: every test passed.</p>\n" : failed;
    return html + "<h2>Tests that passed</h2>\n" + passed + "</body></html>\n";
}

} // namespace whitted::grade
