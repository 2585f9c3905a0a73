// The command line of `whitted-bench`: which scenes, how they are rendered,
// how often, where the results go and which comparisons to leave out.
//
// Why: the driver's other parts take their settings from this one struct, and
// all checking of the user's input happens while parsing, so that a bad flag or
// level stops the benchmark with one line before anything runs.
#pragma once

#include "bench_results.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace whitted::bench {

struct BenchOptions {
    std::vector<std::filesystem::path> scenes; // NFF or P3F files given on the command line
    std::vector<int> flake_levels{4};          // generated sphereflakes
    std::vector<int> tetra_levels;             // generated fractal tetrahedra
    std::vector<int> soup_levels;              // generated random triangle soups (scenes the renderer is not tuned to)
    BenchSettings settings;
    std::filesystem::path out = "bench-results";
    bool povray = true, embree = true;
    std::filesystem::path whitted;         // empty: `whitted` next to the driver
    std::filesystem::path student_whitted; // empty: the student build is not measured
    std::filesystem::path baseline;        // an earlier results.json to flag regressions against; empty: none
};

/// The options, or the exit code when the driver must stop now (0 after --help, 2 for bad input).
struct CommandLine {
    BenchOptions options;
    std::optional<int> exit_code;
};

/// Parses the driver's arguments; errors are printed as one line on stderr.
CommandLine parse_command_line(int argc, char** argv);

/// Parses "4,5,6" (or "none") into levels of the named generator; throws std::invalid_argument.
std::vector<int> parse_levels(const std::string& generator, const std::string& text);

} // namespace whitted::bench
