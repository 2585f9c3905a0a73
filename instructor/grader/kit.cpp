#include "grader/kit.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace whitted::grade {
namespace fs = std::filesystem;

WorkerKit read_kit(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot read it (build the target grading_parts in the instructor build)");
    WorkerKit kit;
    int number = 0;
    auto fail = [&](const std::string& why) { throw std::runtime_error(file.string() + ":" + std::to_string(number) + ": " + why); };
    auto existing = [&](const std::string& path) {
        if (!fs::exists(path)) fail(path + " does not exist (build the target grading_parts in the instructor build)");
        return fs::path(path);
    };
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        const std::size_t space = line.find(' ');
        const std::string key = line.substr(0, space);
        const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
        auto lab_and_path = [&] {
            const std::size_t gap = value.find(' ');
            if (gap == std::string::npos) fail("expected '" + key + " LAB PATH'");
            return std::pair<std::string, fs::path>(value.substr(0, gap), existing(value.substr(gap + 1)));
        };
        if (key == "compile") {
            if (!value.empty()) kit.compile_arguments.push_back(value);
        } else if (key == "define") {
            if (!value.empty()) kit.compile_arguments.push_back("-D" + value);
        } else if (key == "link") {
            if (!value.empty()) kit.link_arguments.push_back(value);
        } else if (key == "compiler") {
            kit.compiler = existing(value);
        } else if (key == "headers") {
            kit.headers = existing(value);
        } else if (key == "precompiled") {
            kit.precompiled = existing(value);
        } else if (key == "main") {
            kit.main_object = existing(value);
        } else if (key == "library") {
            kit.libraries.push_back(existing(value));
        } else if (key == "remote") {
            kit.remote_objects.insert(lab_and_path());
        } else if (key == "checker") {
            kit.checkers.insert(lab_and_path());
        } else if (key != "build-type") {
            fail("unknown item '" + key + "'");
        }
    }
    if (kit.compiler.empty() || kit.headers.empty() || kit.main_object.empty() || kit.libraries.empty())
        throw std::runtime_error(file.string() + ": incomplete (no compiler, headers, main or libraries)");
    return kit;
}

WorkerKit stage_kit(const WorkerKit& kit, const fs::path& folder) {
    fs::remove_all(folder);
    fs::create_directories(folder / "include" / "whitted");
    fs::create_directories(folder / "lib");
    WorkerKit staged = kit;
    staged.root = folder;
    // Every header, engine/ included (the reference lab 1 includes engine/hit_distances.hpp).
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kit.headers)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".hpp") continue;
        const fs::path to = folder / "include" / "whitted" / fs::relative(entry.path(), kit.headers);
        fs::create_directories(to.parent_path());
        fs::copy_file(entry.path(), to);
    }
    staged.headers = folder / "include" / "whitted";
    // GCC uses whitted/labs.hpp.gch in place of the header when it is valid for the compilation, else the header.
    if (!kit.precompiled.empty()) {
        staged.precompiled = staged.headers / "labs.hpp.gch";
        fs::copy_file(kit.precompiled, staged.precompiled);
    }
    auto copy = [&](const fs::path& from, const std::string& name) {
        const fs::path to = folder / "lib" / name;
        fs::copy_file(from, to, fs::copy_options::overwrite_existing);
        return to;
    };
    staged.main_object = copy(kit.main_object, "worker_main.o");
    for (auto& [lab, path] : staged.remote_objects) path = copy(kit.remote_objects.at(lab), "remote_" + lab + ".o");
    staged.libraries.clear();
    for (const fs::path& library : kit.libraries) staged.libraries.push_back(copy(library, library.filename().string()));
    // Everyone may read and enter: the student's code runs as another user.
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder))
        fs::permissions(entry.path(), entry.is_directory() ? fs::perms(0755) : fs::perms(0644));
    fs::permissions(folder, fs::perms(0755));
    return staged;
}

} // namespace whitted::grade
