#include "grader/test_report.hpp"
#include "grader/submission.hpp"
#include "grader/text.hpp"

#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <set>

namespace whitted::grade {
namespace {

using nlohmann::json;

const std::string kNotImplemented = "is not implemented yet";
// What a failing test shows of GoogleTest's report (with the test's own output), and of what the student's code printed.
constexpr std::size_t kReportLines = 40, kPrintedLines = 20;

// A JSON file the checker wrote, read as a regular file of at most 4 MiB without following links or blocking.
std::optional<json> read_json(const std::filesystem::path& file) {
    std::string text;
    try {
        text = read_regular_file(file, std::size_t{4} << 20);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    json value = json::parse(text, nullptr, false);
    if (value.is_discarded()) return std::nullopt;
    return value;
}

// Every test GoogleTest's report records, with its failure messages; empty if there is no readable report.
std::optional<std::map<std::string, std::vector<std::string>>> recorded_tests(const std::filesystem::path& report_file) {
    const std::optional<json> report = read_json(report_file);
    if (!report || !report->is_object()) return std::nullopt;
    std::map<std::string, std::vector<std::string>> tests;
    for (const json& suite : report->value("testsuites", json::array()))
        for (const json& test : suite.value("testsuite", json::array())) {
            std::vector<std::string>& failures = tests[suite.value("name", "") + "." + test.value("name", "")];
            for (const json& failure : test.value("failures", json::array())) failures.push_back(failure.value("failure", ""));
        }
    return tests;
}

// The failure messages GoogleTest recorded for the test, or empty if it did not record the test.
std::optional<std::vector<std::string>> recorded_failures(const std::filesystem::path& report_file, const std::string& name) {
    const auto tests = recorded_tests(report_file);
    if (!tests) return std::nullopt;
    const auto test = tests->find(name);
    if (test == tests->end()) return std::nullopt;
    return test->second;
}

// The test's own output without GoogleTest's banner lines (which hold durations) and without repeated failures.
std::string own_output(const std::string& output, const std::vector<std::string>& failures) {
    static const std::regex banner(R"(^(\[ *(RUN|OK|FAILED|PASSED|SKIPPED|==========|----------) *\]|Running main\(\)|Note: Google Test filter).*)");
    std::set<std::string> failure_lines;
    for (const std::string& failure : failures)
        for (const std::string& line : split_lines(failure)) failure_lines.insert(line);
    std::string kept;
    for (const std::string& line : split_lines(output)) {
        if (std::regex_match(line, banner) || failure_lines.count(line) || line.ends_with(": Failure")) continue;
        kept += line + "\n";
    }
    return kept;
}

// The description of an exception GoogleTest caught, if the message reports one.
std::optional<std::string> caught_exception(const std::string& failure) {
    static const std::regex described(R"re(C\+\+ exception with description "([\s\S]*)" thrown in)re");
    std::smatch match;
    if (std::regex_search(failure, match, described)) return match[1].str();
    if (failure.find("Unknown C++ exception thrown") != std::string::npos) return "an exception of unknown type";
    return std::nullopt;
}

// The line of the output that names the unfinished function, from "labs/" on.
std::string not_implemented_line(const std::string& text) {
    for (const std::string& line : split_lines(text)) {
        const std::size_t end = line.find(kNotImplemented);
        if (end == std::string::npos) continue;
        std::size_t begin = line.rfind("labs/", end);
        if (begin == std::string::npos) begin = line.find_first_not_of(" \t");
        return line.substr(begin, end + kNotImplemented.size() - begin);
    }
    return "a lab function " + kNotImplemented;
}

void classify_failures(TestOutcome& outcome, const std::vector<std::string>& failures) {
    outcome.status = Status::failed;
    for (const std::string& failure : failures) {
        const std::optional<std::string> exception = caught_exception(failure);
        if (exception && exception->find(kNotImplemented) != std::string::npos) {
            outcome.status = Status::not_implemented;
            outcome.message = not_implemented_line(*exception);
            return;
        }
        if (exception && outcome.status != Status::exception) {
            outcome.status = Status::exception;
            outcome.message = "exception: " + split_lines(*exception).front();
        }
    }
    if (outcome.status == Status::failed) {
        // The first line that says something: not GoogleTest's "file:line" or a bare "Failed".
        static const std::regex location(R"(^\S+:\d+$|^Failed$|^Failure$|^\s*$)");
        outcome.message = "an assertion failed";
        for (const std::string& failure : failures)
            for (const std::string& line : split_lines(failure))
                if (!std::regex_match(line, location)) {
                    outcome.message = line;
                    return;
                }
    }
}

// The worker's output under its heading, at most kPrintedLines lines of it.
std::string what_the_code_printed(const ProcessRun& worker, const Limits& limits) {
    std::string printed = worker.output;
    if (worker.output_truncated) printed += "[... output cut at " + std::to_string(limits.output_bytes) + " bytes]\n";
    return "--- what your code printed ---\n" + first_lines(printed, kPrintedLines);
}

// Whether the run was ended by its CPU limit: SIGXCPU, or SIGKILL at the hard limit when SIGXCPU was caught.
bool stopped_by_rlimit_cpu(const ProcessRun& run, const Limits& limits) {
    return run.end == ProcessRun::End::signalled &&
           (run.signal == SIGXCPU || (run.signal == SIGKILL && limits.cpu_seconds > 0 && run.cpu_seconds >= limits.cpu_seconds));
}

std::string cpu_limit_text(const Limits& limits) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", limits.cpu_seconds);
    return std::string("used more than ") + seconds + " s of CPU time and was killed";
}

} // namespace

void classify_run(TestOutcome& outcome, const ProcessRun& run, const Limits& limits, const std::filesystem::path& report_file) {
    const std::optional<std::vector<std::string>> failures = recorded_failures(report_file, outcome.name);
    if (run.end == ProcessRun::End::timed_out) {
        outcome.status = Status::timeout;
        outcome.message = describe(run, limits);
    } else if (stopped_by_rlimit_cpu(run, limits)) {
        outcome.status = Status::timeout;
        outcome.message = cpu_limit_text(limits);
    } else if (run.end == ProcessRun::End::signalled && run.output.find(kNotImplemented) != std::string::npos) {
        outcome.status = Status::not_implemented; // thrown where nothing caught it: std::terminate
        outcome.message = not_implemented_line(run.output);
    } else if (run.end != ProcessRun::End::exited) {
        outcome.status = Status::crash;
        outcome.message = describe(run, limits);
    } else if (!failures) {
        outcome.status = Status::crash;
        outcome.message = "the test program " + describe(run, limits) + " before reporting a result";
    } else if (failures->empty() && run.exit_code == 0) {
        outcome.status = Status::passed;
    } else {
        classify_failures(outcome, *failures);
    }
    std::string details;
    if (failures)
        for (const std::string& failure : *failures) details += failure + "\n";
    details += own_output(run.output, failures.value_or(std::vector<std::string>{}));
    if (run.output_truncated) details += "[... output cut at " + std::to_string(limits.output_bytes) + " bytes]\n";
    outcome.output = first_lines(details, kReportLines);
}

void classify_pair(TestOutcome& outcome, const ProcessRun& checker, const ProcessRun& worker, const Limits& limits,
                   const std::filesystem::path& report_file, const std::filesystem::path& link_file) {
    // What the checker said about the link, when it broke: its own file, not its output (which carries the worker's words);
    // its second line names the call to the worker that was in progress ("during box_entry() (labs/10_bvh.cpp)").
    std::string link_problem, crashed_in;
    try {
        const std::vector<std::string> lines = split_lines(read_regular_file(link_file, 4096));
        if (!lines.empty()) link_problem = lines.front();
        if (lines.size() > 1 && lines[1].starts_with("during ")) crashed_in = lines[1].substr(7);
    } catch (const std::exception&) {
    }
    if (checker.end == ProcessRun::End::timed_out || worker.end == ProcessRun::End::timed_out) {
        outcome.status = Status::timeout;
        outcome.message = describe(worker.end == ProcessRun::End::timed_out ? worker : checker, limits);
    } else if (stopped_by_rlimit_cpu(worker, limits)) {
        outcome.status = Status::timeout;
        outcome.message = "your code " + cpu_limit_text(limits);
    } else if (stopped_by_rlimit_cpu(checker, limits)) {
        outcome.status = Status::timeout;
        outcome.message = "the test " + cpu_limit_text(limits) + " (answering your code's calls)";
    } else if (worker.outlived) {
        outcome.status = Status::crash;
        outcome.message = "your code went on running after the test was over (a thread or a process left behind?) and was killed";
    } else if (worker.end == ProcessRun::End::signalled && worker.output.find(kNotImplemented) != std::string::npos) {
        outcome.status = Status::not_implemented; // thrown where nothing caught it: std::terminate
        outcome.message = not_implemented_line(worker.output);
    } else if (worker.end == ProcessRun::End::signalled) {
        outcome.status = Status::crash;
        outcome.message = (crashed_in.empty() ? "your code was " : "your code crashed in " + crashed_in + ": ") + describe(worker, limits);
    } else if (worker.end == ProcessRun::End::failed_to_start) {
        outcome.status = Status::crash;
        outcome.message = "your program " + describe(worker, limits);
    } else if (worker.exit_code != 0 || (checker.end == ProcessRun::End::exited && checker.exit_code == 3)) {
        outcome.status = Status::crash;
        outcome.message = "your code ended the program (exit code " + std::to_string(worker.exit_code) + ") before the test was over";
        if (worker.exit_code == 0 && !link_problem.empty() && link_problem.find("closed") == std::string::npos &&
            link_problem.find("gone") == std::string::npos)
            outcome.message = "the grading link broke: " + link_problem;
    } else {
        classify_run(outcome, checker, limits, report_file);
        if (outcome.status == Status::passed && checker.exit_code != 0) {
            outcome.status = Status::crash;
            outcome.message = "the checker " + describe(checker, limits);
        }
        if (!worker.output.empty() || worker.output_truncated) outcome.output += what_the_code_printed(worker, limits);
        return;
    }
    // A worker that died closed the link: the checker's words for that ("the other side of the link closed it",
    // the exception it made in the test) would only repeat the message above.
    const auto says_link_closed = [](const std::string& text) {
        return text.find("link closed it") != std::string::npos || text.find("other side of the link is gone") != std::string::npos;
    };
    const bool died = worker.end == ProcessRun::End::signalled;
    std::string details = link_problem.empty() || (died && says_link_closed(link_problem)) ? "" : "grading link: " + link_problem + "\n";
    const std::optional<std::vector<std::string>> failures = recorded_failures(report_file, outcome.name);
    if (failures) {
        std::string reported;
        for (const std::string& failure : *failures)
            if (!(died && says_link_closed(failure))) reported += failure + "\n";
        details += first_lines(reported, kReportLines);
    }
    outcome.output = details;
    if (!worker.output.empty() || worker.output_truncated) outcome.output += what_the_code_printed(worker, limits);
}

std::optional<std::map<std::string, bool>> read_test_results(const std::filesystem::path& report_file) {
    const auto tests = recorded_tests(report_file);
    if (!tests) return std::nullopt;
    std::map<std::string, bool> results;
    for (const auto& [name, failures] : *tests) results[name] = failures.empty();
    return results;
}

std::optional<ImageNumbers> read_image_numbers(const std::filesystem::path& file) {
    const std::optional<json> value = read_json(file);
    if (!value || !value->is_object()) return std::nullopt;
    ImageNumbers numbers;
    numbers.passed = value->value("passed", false);
    numbers.failing_fraction = value->value("failing_fraction", 1.0);
    numbers.mean_error = value->value("mean_error", 1.0);
    numbers.max_error = value->value("max_error", 1.0);
    numbers.worst_x = value->value("worst_x", 0);
    numbers.worst_y = value->value("worst_y", 0);
    numbers.non_finite_pixels = value->value("non_finite_pixels", 0LL);
    if (value->contains("psnr") && (*value)["psnr"].is_number()) numbers.psnr = (*value)["psnr"].get<double>();
    return numbers;
}

} // namespace whitted::grade
