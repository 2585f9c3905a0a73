#include "grade/prebuilt.hpp"
#include "grade/builder.hpp"
#include "grade/folder_lock.hpp"
#include "grade/text.hpp"

namespace whitted::grade {

namespace fs = std::filesystem;

PrebuiltCheck update_prebuilt(const fs::path& build, const fs::path& instructor_tree, int jobs) {
    const fs::path source = configured_source(build);
    if (source.empty()) return {false, build.string() + " is not a CMake build folder"};
    std::error_code error;
    if (!fs::equivalent(source, instructor_tree, error))
        return {false, build.string() + " was configured from " + source.string() + ", not from " + instructor_tree.string()};
    if (const std::string type = cache_entry(build, "CMAKE_BUILD_TYPE"); type != grading_build_type)
        return {false, build.string() + " is a " + (type.empty() ? "build without a build type" : type + " build") + ", grading builds are " +
                           grading_build_type};
    if (!fs::is_regular_file(build / "whitted-grading-prebuilt.cmake"))
        return {false, build.string() + " exports no grading parts (configured without tests?)"};
    const FolderLock lock(build);
    BuildFolder folder;
    folder.instructor_tree = instructor_tree;
    folder.build = build;
    folder.jobs = jobs;
    const BuildStep built = build_targets(folder, {"grading_shared_parts"});
    if (!built.ok) return {false, "its target grading_shared_parts does not build:\n" + trim_text(built.log, 20)};
    return {true, {}};
}

std::string prebuilt_notes(const std::string& configure_log) {
    const std::string mark = "whitted grading: ";
    std::string notes;
    for (const std::string& line : split_lines(configure_log))
        if (const std::size_t at = line.find(mark); at != std::string::npos) notes += line.substr(at + mark.size()) + "\n";
    return notes;
}

} // namespace whitted::grade
