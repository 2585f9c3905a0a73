// Running one program once and dispatching on the program (see tool_runs.hpp).
#include "tool_runs.hpp"

#include "process/process_runner.hpp"

namespace whitted::bench {
namespace {

// The first line of the program's output with text (and the next one when it ends
// with a colon), shortened: the likely reason it failed.
std::string first_line(const std::string& output) {
    std::string line;
    std::size_t start = 0;
    while (start < output.size() && (line.empty() || line.back() == ':')) {
        const std::size_t end = std::min(output.find_first_of("\r\n", start), output.size());
        const std::size_t text = output.find_first_not_of(" \t", start);
        if (text < end) {
            if (!line.empty()) line += ' ';
            line.append(output, text, end - text);
        }
        start = end + 1;
    }
    return line.size() > 240 ? line.substr(0, 240) + "..." : line;
}

} // namespace

std::string run_program(const std::vector<std::string>& argv, const std::filesystem::path& folder,
                        const std::string& what, Sample& sample) {
    grade::ProcessSpec spec;
    spec.argv = argv;
    spec.working_directory = folder;
    spec.limits.wall_seconds = 3600.0;
    spec.limits.output_bytes = std::size_t{4} << 20; // POV-Ray's statistics come last
    const grade::ProcessRun run = grade::run_process(spec);
    sample.peak_megabytes = static_cast<double>(run.peak_rss_bytes) / (1024.0 * 1024.0);
    if (run.end == grade::ProcessRun::End::exited && run.exit_code == 0) return run.output;
    const std::string line = first_line(run.output);
    throw RunFailure(what + " " + grade::describe(run, spec.limits) + (line.empty() ? "" : ": " + line));
}

void prepare_tool(Tool tool, const RunPlan& plan) {
    if (tool == Tool::povray) export_pov_scene(plan);
}

Sample run_tool(Tool tool, const RunPlan& plan, Series& series) {
    if (tool == Tool::povray) return run_povray(plan);
    return run_stats_json_program(tool, plan, series);
}

} // namespace whitted::bench
