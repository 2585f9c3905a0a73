// `whitted-bench` (make bench): renders each benchmark scene with whitted, and
// pair by pair with POV-Ray 3.7 and the Embree 3 harness when they are there,
// then prints a Markdown table and a bar chart and writes results.md,
// results.json and chart.svg to the output folder.
//
// Why a separate program: the benchmark runs every renderer as its own process,
// so each one's times and peak memory are its own, and a crash in one of them
// costs a row of the table, not the benchmark. Exit code: 0 when every run
// succeeded (and, with --baseline, nothing got slower), 1 when some failed or a
// regression was flagged, 2 for bad input.
#include "bench_options.hpp"
#include "bench_scenes.hpp"
#include "bench_tools.hpp"
#include "reports.hpp"
#include "tool_runs.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>

namespace {

using namespace whitted::bench;

void write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
    file.close();
    if (!file) throw std::runtime_error("cannot write " + path.string());
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (!file && !file.eof()) throw std::runtime_error("cannot read " + path.string());
    return text;
}

int run(const BenchOptions& options) {
    // A baseline that is not a results.json stops the benchmark before it runs, not after.
    const std::string baseline = options.baseline.empty() ? "" : read_file(options.baseline);
    if (!options.baseline.empty()) check_baseline({}, options.settings, baseline); // an empty file too
    const BenchTools tools = find_tools(options);
    const std::filesystem::path out = std::filesystem::absolute(options.out).lexically_normal();
    for (const char* folder : {"scenes", "images", "pov", "runs"}) std::filesystem::create_directories(out / folder);
    if (!tools.povray_skipped.empty()) std::printf("POV-Ray comparison skipped: %s\n", tools.povray_skipped.c_str());
    if (!tools.embree_skipped.empty()) std::printf("Embree comparison skipped: %s\n", tools.embree_skipped.c_str());
    std::fflush(stdout);

    const std::vector<BenchScene> scenes = prepare_scenes(options, out / "scenes");
    std::vector<SceneResult> results;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        std::fprintf(stderr, "[%zu/%zu] %s (%s)\n", i + 1, scenes.size(), scenes[i].name.c_str(), scenes[i].path.c_str());
        results.push_back(measure_scene(scenes[i], options.settings, tools, out));
    }

    std::string report = markdown_report(results, options.settings);
    std::optional<BaselineCheck> check;
    if (!options.baseline.empty()) {
        check = check_baseline(results, options.settings, baseline);
        report += "\n" + baseline_section(*check, options.baseline.string());
    }
    std::printf("\n%s\n%s", report.c_str(), terminal_chart(results).c_str());
    write_file(out / "results.md", report);
    write_file(out / "results.json", results_json(results, options.settings));
    write_file(out / "chart.svg", svg_chart(results, options.settings));
    std::printf("\nwrote %s/results.md, results.json and chart.svg\n", out.c_str());
    if (check && !check->regressions.empty()) {
        std::fprintf(stderr, "whitted-bench: %zu regression%s against %s:\n", check->regressions.size(),
                     check->regressions.size() == 1 ? "" : "s", options.baseline.c_str());
        for (const Regression& r : check->regressions)
            std::fprintf(stderr, "  %s %s: %s\n", r.scene.c_str(), r.what.c_str(), r.change.c_str());
    }
    for (const SceneResult& r : results)
        if (r.failed()) return 1;
    return check && !check->regressions.empty() ? 1 : 0;
}

} // namespace

int main(int argc, char** argv) {
    const CommandLine command_line = parse_command_line(argc, argv);
    if (command_line.exit_code) return *command_line.exit_code;
    try {
        return run(command_line.options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "whitted-bench: %s\n", error.what());
        return 2;
    }
}
