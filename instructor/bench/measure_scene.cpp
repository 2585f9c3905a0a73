// Measuring one scene with every program, pair by pair (see tool_runs.hpp).
//
// Why interleaved: each round runs whitted, then POV-Ray, then Embree, so that
// a slow spell of a shared machine hits all programs alike instead of one
// program's whole series; the warm-up rounds fill the file cache first.
#include "tool_runs.hpp"

#include "reports.hpp"

#include <cstdio>

namespace whitted::bench {
namespace {

bool available(Tool tool, const BenchTools& tools) {
    switch (tool) {
    case Tool::whitted: return true;
    case Tool::povray: return !tools.povray.empty();
    case Tool::embree: return !tools.embree.empty();
    case Tool::student: return !tools.student.empty();
    case Tool::whitted_rays: return !tools.embree.empty(); // the Embree harness, --engine whitted
    }
    return false;
}

void fail(Series& series, const std::string& why) {
    series.failure = why;
    std::fprintf(stderr, "whitted-bench: %s\n", why.c_str());
}

} // namespace

SceneResult measure_scene(const BenchScene& scene, const BenchSettings& settings, const BenchTools& tools,
                          const std::filesystem::path& out) {
    SceneResult result;
    result.name = scene.name;
    result.path = scene.path;
    result.generator = scene.generator;
    result.level = scene.level;
    const RunPlan plan{scene, settings, tools, out};
    for (Tool tool : kTools) {
        if (!available(tool, tools)) continue;
        Series& series = result.of(tool);
        series.attempted = true;
        try {
            prepare_tool(tool, plan);
        } catch (const RunFailure& failure) {
            fail(series, failure.what());
        }
    }
    for (int round = 0; round < settings.warmup + settings.runs; ++round) {
        for (Tool tool : kTools) {
            Series& series = result.of(tool);
            if (!series.attempted || !series.failure.empty()) continue;
            try {
                const Sample sample = run_tool(tool, plan, series);
                if (round >= settings.warmup) series.samples.push_back(sample);
            } catch (const RunFailure& failure) {
                fail(series, failure.what());
            }
        }
    }
    std::string line = "  " + scene.name + ":";
    for (Tool tool : kTools)
        if (result.of(tool).attempted) {
            line.append(" ").append(tool_label(tool)).append(" ");
            line.append(result.of(tool).ok() ? format_seconds(median_render(result, tool)) + " s," : "failed,");
        }
    line.back() = '\n';
    std::fputs(line.c_str(), stderr);
    return result;
}

} // namespace whitted::bench
