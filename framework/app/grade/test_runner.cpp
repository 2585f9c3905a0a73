#include "grade/test_runner.hpp"
#include "grade/test_report.hpp"
#include "grade/text.hpp"

namespace whitted::grade {

std::string folder_name(const std::string& test_name) {
    std::string name = test_name;
    for (char& c : name)
        if (c == '/' || c == '\\') c = '_';
    return name;
}

namespace {

// Runs the program in the sandbox with `folder` (made anew) as its writable folder and working directory.
ProcessRun run_fenced(const TestProgram& program, ProcessSpec spec, const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    give_folder(program.sandbox, folder);
    spec.working_directory = folder;
    const ProcessRun run = program.sandbox.unwrap(run_process(program.sandbox.wrap(std::move(spec), folder)));
    kill_leftover_children();
    return run;
}

} // namespace

std::vector<std::string> list_tests(const TestProgram& program, std::string& problem) {
    ProcessSpec spec{{program.program.string(), "--gtest_list_tests"}, {}, {}, program.limits, {}};
    spec.limits.output_bytes = 1 << 20;
    const ProcessRun run = run_fenced(program, spec, program.output / "listing");
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
    TestOutcome outcome;
    outcome.lab = program.lab;
    outcome.name = test_name;
    const std::filesystem::path folder = program.output / folder_name(test_name);
    std::filesystem::remove_all(folder);
    const std::filesystem::path report_file = folder / "gtest.json";
    ProcessSpec spec{{program.program.string(), "--gtest_filter=" + test_name, "--gtest_color=no",
                      "--gtest_output=json:" + report_file.string()},
                     folder,
                     {{"WHITTED_TEST_OUTPUT", folder.string()}, {"GTEST_COLOR", "no"}},
                     program.limits,
                     {}};
    const ProcessRun run = run_fenced(program, spec, folder);
    classify_run(outcome, run, program.limits, report_file);
    outcome.message = replace_paths(outcome.message, program.path_replacements);
    outcome.output = trim_text(replace_paths(outcome.output, program.path_replacements), 60);
    outcome.image = read_image_numbers(folder / "image.json");
    if (std::filesystem::exists(folder / "reference.png") || std::filesystem::exists(folder / "yours.png"))
        outcome.pictures = folder;
    return outcome;
}

std::filesystem::path fetch_reference_picture(const TestProgram& program, const std::string& test_name) {
    const std::filesystem::path folder = program.output / folder_name(test_name);
    std::filesystem::remove_all(folder);
    run_fenced(program,
               {{program.program.string(), "--gtest_filter=" + test_name},
                folder,
                {{"WHITTED_TEST_OUTPUT", folder.string()}, {"WHITTED_REFERENCE_ONLY", "1"}},
                program.limits,
                {}},
               folder);
    return std::filesystem::exists(folder / "reference.png") ? folder : std::filesystem::path();
}

} // namespace whitted::grade
