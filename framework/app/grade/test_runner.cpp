#include "grade/test_runner.hpp"
#include "grade/test_report.hpp"
#include "grade/text.hpp"

#include "channel.hpp"

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

TestOutcome run_test(const TestProgram& program, const std::string& test_name) {
    const fs::path folder = program.output / folder_name(test_name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    // The descriptors go to the two programs: the grader keeps none, so each sees when the other has gone.
    const link::ChannelPair channel = link::make_channel_pair();
    ProcessSpec check = checker_spec(program,
                                     {"--worker-fds=3,4,5", "--gtest_filter=" + test_name, "--gtest_color=no",
                                      "--gtest_output=json:" + (folder / "gtest.json").string()},
                                     folder);
    check.descriptors = {channel.checker.memory, channel.checker.wake_in, channel.checker.wake_out};
    ProcessSpec work;
    work.argv = program.worker;
    work.working_directory = fs::path(program.worker.front()).parent_path();
    work.limits = program.limits;
    work.limits.file_size = 1; // the worker writes no file: what it has to say crosses the link
    work.descriptors = {channel.worker.memory, channel.worker.wake_in, channel.worker.wake_out};
    const auto [checker, worker] =
        run_pair({std::move(check), program.sandbox.wrap(std::move(work), {fs::path(program.worker.front())}, std::nullopt)},
                 program.linger_seconds);
    program.sandbox.end_runs();

    TestOutcome outcome;
    outcome.lab = program.lab;
    outcome.name = test_name;
    classify_pair(outcome, checker, program.sandbox.unwrap(worker), program.limits, folder / "gtest.json");
    outcome.message = replace_paths(outcome.message, program.path_replacements);
    outcome.output = trim_text(replace_paths(outcome.output, program.path_replacements), 60);
    outcome.image = read_image_numbers(folder / "image.json");
    if (fs::exists(folder / "reference.png") || fs::exists(folder / "yours.png")) outcome.pictures = folder;
    return outcome;
}

fs::path fetch_reference_picture(const TestProgram& program, const std::string& test_name) {
    const fs::path folder = program.output / folder_name(test_name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    ProcessSpec spec = checker_spec(program, {"--gtest_filter=" + test_name}, folder);
    spec.environment.emplace_back("WHITTED_REFERENCE_ONLY", "1");
    run_process(spec);
    return fs::exists(folder / "reference.png") ? folder : fs::path();
}

} // namespace whitted::grade
