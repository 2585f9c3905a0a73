// The grading kit: what a worker is built from, without the instructor tree.
//
// Why: the compiler runs the student's code too (#include, asm(".incbin")), so
// it must see nothing secret. The instructor build lists in grading-kit.txt
// (instructor/cmake/WhittedSplit.cmake) the compiler and its arguments for a lab file,
// the framework's public headers, the objects and libraries a worker links
// (none holds reference code) and each lab's checker. The grader copies the
// worker's parts into a folder of its own, readable by the student's code and
// holding nothing else, and builds there.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace whitted::grade {

struct WorkerKit {
    std::filesystem::path compiler;
    std::vector<std::string> compile_arguments; // flags and -D definitions; the include folder is added by the builder
    std::vector<std::string> link_arguments;
    std::filesystem::path headers;              // the folder whitted/ of public headers
    std::filesystem::path precompiled;          // whitted/labs.hpp precompiled with the kit's arguments, or empty
    std::filesystem::path main_object;          // the worker's main()
    std::map<std::string, std::filesystem::path> remote_objects; // lab -> the object answering it over the link
    std::vector<std::filesystem::path> libraries; // in link order
    std::map<std::string, std::filesystem::path> checkers;       // lab or "integration" -> checker program (instructor side)
    std::filesystem::path root;                 // the staged kit's folder (empty before stage_kit)
};

/// Reads BUILD/grading-kit.txt. Throws std::runtime_error naming file:line on a bad line or a missing file.
WorkerKit read_kit(const std::filesystem::path& file);

/// Copies the headers, objects and libraries into `folder` (made anew, readable
/// by everyone) and returns the kit naming the copies; the checkers stay where they are.
WorkerKit stage_kit(const WorkerKit& kit, const std::filesystem::path& folder);

/// The include folder of a staged kit (holds whitted/).
inline std::filesystem::path kit_include(const WorkerKit& kit) { return kit.root / "include"; }

} // namespace whitted::grade
