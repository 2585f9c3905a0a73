// Finding the benchmark's programs (see bench_tools.hpp).
#include "bench_tools.hpp"

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace whitted::bench {
namespace {

bool is_executable(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error) && access(path.c_str(), X_OK) == 0;
}

// The helper `name` beside the driver, or "".
std::filesystem::path beside_driver(const std::string& name) {
    const std::filesystem::path folder = own_folder();
    if (folder.empty() || !is_executable(folder / name)) return {};
    return folder / name;
}

} // namespace

std::filesystem::path own_folder() {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path{} : self.parent_path();
}

std::filesystem::path find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');)
        if (!folder.empty() && is_executable(std::filesystem::path(folder) / name))
            return std::filesystem::path(folder) / name;
    return {};
}

BenchTools find_tools(const BenchOptions& options) {
    BenchTools tools;
    tools.whitted = options.whitted.empty() ? beside_driver("whitted") : options.whitted;
    if (tools.whitted.empty() || !is_executable(tools.whitted))
        throw std::runtime_error("cannot find the whitted program beside whitted-bench; build it, or give --whitted PATH");
    if (!options.student_whitted.empty()) {
        if (!is_executable(options.student_whitted))
            throw std::runtime_error("--student-whitted: not an executable program: " + options.student_whitted.string());
        tools.student = options.student_whitted;
    }

    if (!options.povray) {
        tools.povray_skipped = "--no-povray";
    } else if (tools.povray = find_on_path("povray"); tools.povray.empty()) {
        tools.povray_skipped = "povray is not on PATH (Debian: apt-get install povray)";
    } else if (tools.pov_export = beside_driver("whitted-pov-export"); tools.pov_export.empty()) {
        tools.povray_skipped = "whitted-pov-export is not built beside whitted-bench";
    }
    if (!tools.povray_skipped.empty()) {
        tools.povray.clear();
        tools.pov_export.clear();
    }

    if (!options.embree) {
        tools.embree_skipped = "--no-embree";
    } else if (tools.embree = beside_driver("whitted-embree-rays"); tools.embree.empty()) {
        tools.embree_skipped = "whitted-embree-rays is not built beside whitted-bench (it needs Embree 3: apt-get install "
                               "libembree-dev, then configure again)";
    }
    return tools;
}

} // namespace whitted::bench
