#include "grader/builder.hpp"
#include "grader/folder_lock.hpp"
#include "grader/kit.hpp"
#include "process/process_runner.hpp"
#include "grader/text.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <sys/stat.h>
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

namespace {

// FNV-1a, over what the states below list.
struct Fingerprint {
    std::uint64_t value = 1469598103934665603ull;
    void add(std::string_view text) {
        for (const char c : text) value = (value ^ static_cast<unsigned char>(c)) * 1099511628211ull;
        value = (value ^ 0xff) * 1099511628211ull; // a separator no text holds
    }
    void add_file(const fs::path& file) {
        struct stat info {};
        add(file.string());
        if (::stat(file.c_str(), &info) != 0) return add("missing");
        add(std::to_string(info.st_size) + " " + std::to_string(info.st_mtim.tv_sec) + "." + std::to_string(info.st_mtim.tv_nsec));
    }
};

} // namespace

std::string source_state(const fs::path& tree) {
    std::vector<fs::path> files;
    std::error_code error;
    for (auto entry = fs::recursive_directory_iterator(tree, fs::directory_options::skip_permission_denied, error); !error && entry != fs::recursive_directory_iterator();
         entry.increment(error)) {
        const std::string name = entry->path().filename().string();
        if (entry->is_directory() &&
            (name.starts_with(".") || fs::exists(entry->path() / "CMakeCache.txt") || fs::exists(entry->path() / ".whitted-grade"))) {
            entry.disable_recursion_pending();
        } else if (entry->is_regular_file()) {
            files.push_back(entry->path());
        }
    }
    if (error) return "unreadable";
    std::sort(files.begin(), files.end());
    Fingerprint print;
    for (const fs::path& file : files) print.add_file(file);
    return std::to_string(print.value);
}

namespace {

// The build's cache, its kit and every file the kit names, by path, size and time.
std::string output_state(const fs::path& build) {
    Fingerprint print;
    print.add_file(build / "CMakeCache.txt");
    print.add_file(build / "grading-kit.txt");
    try {
        const WorkerKit kit = read_kit(build / "grading-kit.txt");
        for (const fs::path& file : {kit.compiler, kit.precompiled, kit.main_object}) print.add_file(file);
        for (const auto& [lab, file] : kit.remote_objects) print.add_file(file);
        for (const auto& [lab, file] : kit.checkers) print.add_file(file);
        for (const fs::path& file : kit.libraries) print.add_file(file);
    } catch (const std::exception&) {
        return "no kit";
    }
    return std::to_string(print.value);
}

} // namespace

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
    // Make takes seconds to find nothing to do; the state of the sources and of what the last update made
    // tells in a few milliseconds. Taken before the build: a file changed while it runs counts as changed.
    const fs::path state_file = build / "grading-parts.state";
    const std::string sources = source_state(instructor_tree);
    std::string recorded;
    if (std::ifstream in(state_file); in) std::getline(in, recorded);
    if (recorded == sources + " " + output_state(build)) return;
    fs::remove(state_file);
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
    std::ofstream(state_file) << sources << " " << output_state(build) << "\n";
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
