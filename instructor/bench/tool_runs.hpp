// Running the compared programs once on a scene, each as its own process, and
// turning what it reports into a Sample.
//
// Why: every program is timed by itself (its own parse, build and trace times,
// not the driver's clock, which would include start-up), and its peak memory
// comes from the kernel when it is reaped. A program that fails yields one
// line naming the program, the scene and what went wrong, never a crash.
#pragma once

#include "bench_results.hpp"
#include "bench_scenes.hpp"
#include "bench_tools.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted::bench {

/// One line saying why a run failed.
struct RunFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Everything one scene's runs need; `out` holds images/, pov/ and runs/.
struct RunPlan {
    const BenchScene& scene;
    const BenchSettings& settings;
    const BenchTools& tools;
    std::filesystem::path out;
};

/// Measures one scene: every available program, warm-up rounds first, then the runs, program after
/// program in each round. A failing program is reported on stderr and skipped for the rest of the scene.
SceneResult measure_scene(const BenchScene& scene, const BenchSettings& settings, const BenchTools& tools,
                          const std::filesystem::path& out);

/// Does what `tool` needs once per scene before its runs (POV-Ray: export the scene). Throws RunFailure.
void prepare_tool(Tool tool, const RunPlan& plan);

/// Runs `tool` once; returns its sample and records sizes in `series`. Throws RunFailure.
Sample run_tool(Tool tool, const RunPlan& plan, Series& series);

/// Runs argv without a shell in `folder` ("" = here); throws RunFailure naming `what` unless it exits with 0.
/// Returns the captured output and the peak memory through `sample`.
std::string run_program(const std::vector<std::string>& argv, const std::filesystem::path& folder,
                        const std::string& what, Sample& sample);

/// Runs whitted, the student build or the Embree harness, which all write whitted's --stats-json.
Sample run_stats_json_program(Tool tool, const RunPlan& plan, Series& series);

/// Writes OUT/pov/NAME.pov with whitted-pov-export. Throws RunFailure.
void export_pov_scene(const RunPlan& plan);

/// Runs POV-Ray on the exported scene; its own parse, bounding and trace times make the sample.
Sample run_povray(const RunPlan& plan);

/// Reads POV-Ray's statistics (parse + bounding time, trace time); nullopt without a trace time.
std::optional<Sample> parse_povray_output(const std::string& output);

} // namespace whitted::bench
