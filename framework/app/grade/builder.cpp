#include "grade/builder.hpp"
#include "grade/folder_lock.hpp"
#include "grade/process_runner.hpp"
#include "grade/text.hpp"

#include <fstream>
#include <regex>
#include <stdexcept>

namespace whitted::grade {

namespace fs = std::filesystem;

std::string cache_entry(const fs::path& build, const std::string& name) {
    std::ifstream cache(build / "CMakeCache.txt");
    for (std::string line; std::getline(cache, line);) {
        // NAME:TYPE=VALUE
        const std::size_t colon = line.find(':'), equals = line.find('=');
        if (colon == name.size() && equals != std::string::npos && equals > colon && line.compare(0, colon, name) == 0)
            return line.substr(equals + 1);
    }
    return {};
}

fs::path configured_source(const fs::path& build) { return cache_entry(build, "CMAKE_HOME_DIRECTORY"); }

void update_instructor_build(const fs::path& build, const fs::path& instructor_tree, int jobs) {
    const std::string hint = " (build the instructor tree first: make build, or pass --instructor-build)";
    const fs::path source = configured_source(build);
    if (source.empty()) throw std::runtime_error(build.string() + " is not a CMake build folder" + hint);
    std::error_code error;
    if (!fs::equivalent(source, instructor_tree, error))
        throw std::runtime_error(build.string() + " was configured from " + source.string() + ", not from " + instructor_tree.string());
    if (const std::string type = cache_entry(build, "CMAKE_BUILD_TYPE"); type != grading_build_type)
        throw std::runtime_error(build.string() + " is a " + (type.empty() ? "build without a build type" : type + " build") +
                                 "; grading needs a " + grading_build_type + " build" + hint);
    if (cache_entry(build, "BUILD_TESTING") == "OFF") throw std::runtime_error(build.string() + " was configured without tests (-DBUILD_TESTING=OFF)");
    const FolderLock lock(build);
    Limits limits;
    limits.wall_seconds = 1800;
    limits.output_bytes = 256 * 1024;
    ProcessSpec spec;
    spec.argv = {"cmake", "--build", build.string(), "-j", std::to_string(jobs), "--target", "grading_parts"};
    spec.environment = {{"CLICOLOR_FORCE", "0"}, {"LC_ALL", "C"}};
    spec.limits = limits;
    const ProcessRun run = run_process(spec);
    if (run.end != ProcessRun::End::exited || run.exit_code != 0)
        throw std::runtime_error("the instructor build's target grading_parts does not build (" + describe(run, limits) + "):\n" +
                                 trim_text(run.output, 30));
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
