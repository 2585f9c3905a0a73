// The scenes of a benchmark: sphereflakes and tetrahedra generated at the
// levels asked for, then the scene files given on the command line.
//
// Why: generated scenes are written to OUT/scenes/ so every program reads the
// same file, and the results can be reproduced from it; each scene gets a short
// unique name for file names and the report.
#pragma once

#include "bench_options.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace whitted::bench {

struct BenchScene {
    std::string name;           // "flake4", "teapot6"; unique
    std::filesystem::path path; // the file every program reads
    std::string generator;      // "sphereflake" or "tetra" when generated, else ""
    int level = -1;
    std::size_t generated_primitives = 0; // spheres or triangles written, when generated
};

/// Writes the generated scenes to `folder` and lists them before the given files.
/// Throws std::runtime_error (one line) for a file that is missing, unreadable or not .nff/.p3f.
std::vector<BenchScene> prepare_scenes(const BenchOptions& options, const std::filesystem::path& folder);

} // namespace whitted::bench
