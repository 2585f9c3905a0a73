// Finding the programs a benchmark runs: whitted (and the student build), the
// POV-Ray scene writer with POV-Ray itself, and the Embree harness.
//
// Why: the comparisons are optional. The helpers live next to the driver in
// the build folder and POV-Ray is found on PATH; whatever is missing is
// skipped with one line saying why, and the rest of the benchmark still runs.
#pragma once

#include "bench_options.hpp"

#include <filesystem>
#include <string>

namespace whitted::bench {

struct BenchTools {
    std::filesystem::path whitted;    // always there
    std::filesystem::path student;    // empty: not measured
    std::filesystem::path pov_export; // whitted-pov-export; empty when POV-Ray is skipped
    std::filesystem::path povray;     // the povray program; empty when skipped
    std::filesystem::path embree;     // whitted-embree-rays; empty when skipped
    std::string povray_skipped, embree_skipped; // why, when skipped ("" otherwise)
};

/// Looks the programs up; throws std::runtime_error (one line) when whitted itself is missing.
BenchTools find_tools(const BenchOptions& options);

/// The folder of the running program (from /proc/self/exe), or "" when unknown.
std::filesystem::path own_folder();

/// The first executable called `name` in the folders of PATH, or "".
std::filesystem::path find_on_path(const std::string& name);

} // namespace whitted::bench
