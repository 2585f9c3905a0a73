#include "grade/builder.hpp"
#include "grade/process_runner.hpp"
#include "grade/text.hpp"

#include <fstream>
#include <regex>

namespace whitted::grade {
namespace {

BuildStep run_cmake(const BuildFolder& folder, std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), "cmake");
    Limits limits;
    limits.wall_seconds = folder.timeout_seconds;
    limits.output_bytes = 256 * 1024; // the first errors come first
    const ProcessRun run = run_process({arguments, {}, {{"CLICOLOR_FORCE", "0"}, {"LC_ALL", "C"}}, limits, {}});
    BuildStep step;
    step.ok = run.end == ProcessRun::End::exited && run.exit_code == 0;
    step.log = run.output;
    if (!step.ok) step.log.append("\n").append(describe(run, limits)).append("\n");
    return step;
}

bool has_ninja() {
    Limits limits;
    limits.wall_seconds = 10;
    const ProcessRun run = run_process({{"ninja", "--version"}, {}, {}, limits, {}});
    return run.end == ProcessRun::End::exited && run.exit_code == 0;
}

} // namespace

std::string cache_entry(const std::filesystem::path& build, const std::string& name) {
    std::ifstream cache(build / "CMakeCache.txt");
    for (std::string line; std::getline(cache, line);) {
        // NAME:TYPE=VALUE
        const std::size_t colon = line.find(':'), equals = line.find('=');
        if (colon == name.size() && equals != std::string::npos && equals > colon && line.compare(0, colon, name) == 0)
            return line.substr(equals + 1);
    }
    return {};
}

std::filesystem::path configured_source(const std::filesystem::path& build) { return cache_entry(build, "CMAKE_HOME_DIRECTORY"); }

BuildStep configure(const BuildFolder& folder) {
    std::vector<std::string> arguments = {"-S", folder.instructor_tree.string(), "-B", folder.build.string(),
                                          std::string("-DCMAKE_BUILD_TYPE=") + grading_build_type, "-DWHITTED_GRADING=ON", "-DBUILD_TESTING=OFF",
                                          "-DWHITTED_LABS_DIR=" + folder.labs.string(),
                                          "-DWHITTED_GRADING_PREBUILT=" + folder.prebuilt.string()};
    if (configured_source(folder.build).empty() && has_ninja()) arguments.insert(arguments.begin(), {"-G", "Ninja"});
    return run_cmake(folder, arguments);
}

BuildStep build_targets(const BuildFolder& folder, const std::vector<std::string>& targets) {
    std::vector<std::string> arguments = {"--build", folder.build.string(), "-j", std::to_string(folder.jobs), "--target"};
    arguments.insert(arguments.end(), targets.begin(), targets.end());
    return run_cmake(folder, arguments);
}

std::string first_compiler_errors(const std::string& log, const std::vector<std::pair<std::string, std::string>>& paths) {
    // Lines of the build tools, and the compiler's command lines, are noise for a student.
    static const std::regex noise(R"(^(\[\d+/\d+\]|\[ *\d+%\]|FAILED:|ninja:|g?make(\[\d+\])?:|gmake|/usr/bin/(c\+\+|g\+\+|cc)|\S*(c\+\+|g\+\+) ).*|^compilation terminated\.|^\S+ did not finish within .*|^exited with code .*)");
    std::string kept;
    bool seen_error = false;
    for (const std::string& line : split_lines(log)) {
        if (line.empty() || std::regex_match(line, noise)) continue;
        static const std::regex start(R"(.*(error|[Ii]n function|In file included|: In |undefined reference|multiple definition).*)");
        if (!seen_error && !std::regex_match(line, start)) continue;
        seen_error = true;
        kept += line + "\n";
    }
    if (kept.empty()) kept = log; // unexpected format: show it all rather than nothing
    return trim_text(replace_paths(kept, paths), 30, 300, 4000);
}

} // namespace whitted::grade
