// Building the student's workers from the grading kit, inside the fences.
//
// Why: compiling is running the student's code too: #include and
// asm(".incbin") read any file the compiler can, and a file without end
// (/dev/zero) or a template explosion can eat the machine. So the compiler
// runs as the student code's user, in the sandbox, under limits, seeing the
// system, the kit (public headers and the worker's parts, kit.hpp) and the
// build folder, nothing else; the include path is the kit's alone.
#pragma once

#include "grader/builder.hpp"
#include "grader/kit.hpp"
#include "grader/sandbox.hpp"

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace whitted::grade {

/// The address space of one compiler or linker of the student's code.
constexpr std::size_t kCompilerMemory = std::size_t{2} << 30;

struct WorkerBuild {
    const WorkerKit& kit;       // staged
    const Sandbox& sandbox;
    std::filesystem::path folder; // writable by the student code's user; labs/<lab>.cpp are the sources
    int jobs = 2;
    std::chrono::steady_clock::time_point deadline; // the grading's budget: no step runs past it
};

/// Compiles labs/<lab>.cpp to <lab>.o for each lab, `jobs` at a time; returns each lab's step.
std::map<std::string, BuildStep> compile_labs(const WorkerBuild& build, const std::vector<std::string>& labs);

/// A worker program: what it is for and the labs whose student objects it links.
struct WorkerParts {
    std::string name;                  // a lab ("03_blinn_phong") or "integration"; the program is worker_<name>
    std::vector<std::string> own_labs; // the rest of `all_labs` comes from the kit's remote objects
};

/// Links each worker to worker_<name> in the build folder, `jobs` at a time; returns each one's step by name.
std::map<std::string, BuildStep> link_workers(const WorkerBuild& build, const std::vector<WorkerParts>& workers,
                                              const std::vector<std::string>& all_labs);

/// Copies the program the student's user built (`built`) to `destination`, which
/// that user cannot change, reading it without following links or blocking.
void take_program(const std::filesystem::path& built, const std::filesystem::path& destination);

} // namespace whitted::grade
