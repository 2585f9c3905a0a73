#include "grader/test_runner.hpp"
#include "grader/test_report.hpp"
#include "grader/text.hpp"

#include "channel.hpp"

#include <map>
#include <optional>
#include <tuple>
#include <utility>

namespace whitted::grade {

std::string folder_name(const std::string& test_name) {
    std::string name = test_name;
    for (char& c : name)
        if (c == '/' || c == '\\' || c == '\0') c = '_';
    if (name.empty() || name == "." || name == "..") name = "_" + name;
    return name;
}

namespace {

namespace fs = std::filesystem;

// The folder of a run of several tests: a name without a dot, which no test's folder has ("Suite.Test").
const char* const kTogetherFolder = "together";

ProcessSpec checker_spec(const TestProgram& program, std::vector<std::string> arguments, const fs::path& folder) {
    arguments.insert(arguments.begin(), program.checker.string());
    ProcessSpec spec;
    spec.argv = std::move(arguments);
    spec.working_directory = folder;
    spec.environment = {{"WHITTED_TEST_OUTPUT", folder.string()}, {"GTEST_COLOR", "no"}};
    spec.limits = program.limits;
    spec.limits.output_bytes = std::max<std::size_t>(spec.limits.output_bytes, 64 * 1024);
    return spec;
}

} // namespace

std::vector<std::string> list_tests(const TestProgram& program, std::string& problem) {
    fs::create_directories(program.output);
    ProcessSpec spec = checker_spec(program, {"--gtest_list_tests"}, program.output);
    spec.limits.output_bytes = 1 << 20;
    const ProcessRun run = run_process(spec);
    std::vector<std::string> names;
    if (run.end != ProcessRun::End::exited || run.exit_code != 0) {
        problem = "listing the tests: " + describe(run, spec.limits) + "\n" + trim_text(run.output, 20);
        return names;
    }
    std::string suite;
    for (std::string line : split_lines(run.output)) {
        if (const std::size_t comment = line.find("  #"); comment != std::string::npos) line.erase(comment);
        if (line.empty()) continue;
        if (line[0] != ' ') {
            suite = line.substr(0, line.find_last_not_of(". ") + 1);
        } else {
            names.push_back(suite + "." + line.substr(line.find_first_not_of(' ')));
        }
    }
    return names;
}

namespace {

// A fresh folder for one run of the checker.
fs::path fresh_folder(const fs::path& folder) {
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// Runs the checker on the tests `filter` names (`together`: several, image tests failing at once), with the
// worker in the sandbox and a new link between them; then kills whatever either left running. Returns
// (checker, worker).
std::pair<ProcessRun, ProcessRun> run_checked(const TestProgram& program, const std::string& filter, const fs::path& folder,
                                              const Limits& limits, bool together) {
    // The descriptors go to the two programs: the grader keeps none, so each sees when the other has gone.
    const link::ChannelPair channel = link::make_channel_pair();
    ProcessSpec check = checker_spec(program,
                                     {"--worker-fds=3,4,5", "--gtest_filter=" + filter, "--gtest_color=no",
                                      "--gtest_output=json:" + (folder / "gtest.json").string()},
                                     folder);
    check.limits = limits;
    if (together) check.environment = {{"WHITTED_TOGETHER", "1"}, {"GTEST_COLOR", "no"}}; // image tests fail at once
    check.environment.emplace_back("WHITTED_LINK_REPORT", (folder / "link.txt").string());
    check.limits.output_bytes = std::max<std::size_t>(limits.output_bytes, 64 * 1024);
    check.descriptors = {channel.checker.memory, channel.checker.wake_in, channel.checker.wake_out};
    ProcessSpec work;
    work.argv = program.worker;
    work.working_directory = fs::path(program.worker.front()).parent_path();
    work.limits = limits;
    work.limits.file_size = 1; // the worker writes no file: what it has to say crosses the link
    work.descriptors = {channel.worker.memory, channel.worker.wake_in, channel.worker.wake_out};
    auto [checker, worker] =
        run_pair({std::move(check), program.sandbox.wrap(std::move(work), {fs::path(program.worker.front())}, std::nullopt)},
                 program.linger_seconds);
    program.sandbox.end_runs();
    return {std::move(checker), program.sandbox.unwrap(std::move(worker))};
}

} // namespace

TestOutcome run_test(const TestProgram& program, const std::string& test_name) {
    const fs::path folder = fresh_folder(program.output / folder_name(test_name));
    auto [checker, worker] = run_checked(program, test_name, folder, program.limits, false);
    // Out of wall time while still using the CPU, within its limit: the machine was too busy to tell. Once more.
    const auto slowed = [](const ProcessRun& run) { return run.end == ProcessRun::End::timed_out && !run.hung && !run.out_of_cpu; };
    if (slowed(checker) || slowed(worker)) std::tie(checker, worker) = run_checked(program, test_name, fresh_folder(folder), program.limits, false);
    TestOutcome outcome;
    outcome.lab = program.lab;
    outcome.name = test_name;
    classify_pair(outcome, checker, worker, program.limits, folder / "gtest.json", folder / "link.txt");
    outcome.message = replace_paths(outcome.message, program.path_replacements);
    // first_lines() has cut the report and the printed output; this bounds what is left (long lines, the link's line).
    outcome.output = trim_text(replace_paths(outcome.output, program.path_replacements), 70, 300, 8000);
    outcome.image = read_image_numbers(folder / "image.json");
    if (fs::exists(folder / "reference.png") || fs::exists(folder / "yours.png")) outcome.pictures = folder;
    return outcome;
}

std::set<std::string> passed_together(const TestProgram& program, const std::vector<std::string>& test_names, double wall_seconds) {
    if (test_names.empty()) return {};
    std::string filter;
    for (const std::string& name : test_names) {
        if (name.find_first_of(":*?-") != std::string::npos) return {}; // not a plain name in a filter: each on its own
        filter += (filter.empty() ? "" : ":") + name;
    }
    const fs::path folder = fresh_folder(program.output / kTogetherFolder);
    Limits limits = program.limits;
    limits.wall_seconds = std::min(limits.wall_seconds, wall_seconds);
    limits.cpu_seconds = std::min(limits.cpu_seconds, limits.wall_seconds);
    const auto [checker, worker] = run_checked(program, filter, folder, limits, true);
    // Only a clean run counts: both programs exited by themselves, the checker with GoogleTest's 0 or 1, the
    // worker with 0 after the checker's goodbye.
    const bool clean = checker.end == ProcessRun::End::exited && (checker.exit_code == 0 || checker.exit_code == 1) &&
                       worker.end == ProcessRun::End::exited && worker.exit_code == 0 && !worker.outlived;
    std::set<std::string> passed;
    if (!clean) return passed;
    // Files of image tests would belong to no test: those tests run on their own.
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        if (entry.path().filename() != "gtest.json") return passed;
    const std::optional<std::map<std::string, bool>> report = read_test_results(folder / "gtest.json");
    if (!report) return passed;
    for (const std::string& name : test_names) {
        const auto result = report->find(name);
        if (result == report->end()) return {}; // GoogleTest did not run every test asked for: none counts
        if (result->second) passed.insert(name);
    }
    return passed;
}

fs::path fetch_reference_picture(const TestProgram& program, const std::string& test_name) {
    const fs::path folder = fresh_folder(program.output / folder_name(test_name));
    ProcessSpec spec = checker_spec(program, {"--gtest_filter=" + test_name}, folder);
    spec.environment.emplace_back("WHITTED_REFERENCE_ONLY", "1");
    run_process(spec);
    return fs::exists(folder / "reference.png") ? folder : fs::path();
}

} // namespace whitted::grade
