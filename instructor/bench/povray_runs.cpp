// POV-Ray's side of the comparison: export the scene with whitted-pov-export,
// run `povray` without antialiasing or display, and read its own statistics.
//
// Why its own trace time: POV-Ray spends most of a second starting up, which
// says nothing about tracing; it prints "Trace Time: ... (0.480 seconds)" and
// the parse and bounding times, which are the fair counterparts of whitted's
// render and load + build times.
#include "tool_runs.hpp"

#include <cstdlib>

namespace whitted::bench {
namespace {

// The seconds in brackets after `label` ("Trace Time:  0 hours ... (0.480 seconds)"), or -1.
double seconds_after(const std::string& output, const std::string& label) {
    const std::size_t at = output.rfind(label);
    if (at == std::string::npos) return -1.0;
    const std::size_t open = output.find('(', at), end = output.find('\n', at);
    if (open == std::string::npos || open > end) return -1.0;
    char* stop = nullptr;
    const double seconds = std::strtod(output.c_str() + open + 1, &stop);
    return stop != output.c_str() + open + 1 && std::string_view(stop).starts_with(" second") ? seconds : -1.0;
}

std::filesystem::path pov_folder(const RunPlan& plan) { return plan.out / "pov"; }

} // namespace

std::optional<Sample> parse_povray_output(const std::string& output) {
    const double trace = seconds_after(output, "Trace Time:");
    if (trace < 0.0) return std::nullopt;
    Sample sample;
    sample.render_seconds = trace;
    for (const char* label : {"Parse Time:", "Bounding Time:"}) sample.load_build_seconds += std::max(0.0, seconds_after(output, label));
    return sample;
}

void export_pov_scene(const RunPlan& plan) {
    const std::string size = std::to_string(plan.settings.size);
    Sample ignored;
    run_program({plan.tools.pov_export.string(), plan.scene.path.string(), "-o",
                 (pov_folder(plan) / (plan.scene.name + ".pov")).string(), "--width", size, "--height", size},
                {}, "whitted-pov-export on " + plan.scene.name, ignored);
}

Sample run_povray(const RunPlan& plan) {
    const BenchSettings& s = plan.settings;
    // Relative names inside pov/: POV-Ray's I/O restrictions allow the working folder.
    const std::vector<std::string> argv{plan.tools.povray.string(), "+I" + plan.scene.name + ".pov",
                                        "+O" + plan.scene.name + ".png", "+W" + std::to_string(s.size),
                                        "+H" + std::to_string(s.size), "-A", "+WT" + std::to_string(s.threads), "-D", "+FN"};
    const std::string what = "POV-Ray on " + plan.scene.name;
    Sample sample;
    const std::string output = run_program(argv, pov_folder(plan), what, sample);
    const std::optional<Sample> times = parse_povray_output(output);
    if (!times) throw RunFailure(what + " printed no trace time");
    sample.load_build_seconds = times->load_build_seconds;
    sample.render_seconds = times->render_seconds;
    return sample;
}

} // namespace whitted::bench
