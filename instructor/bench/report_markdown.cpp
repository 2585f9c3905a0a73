// The Markdown report: the settings, then one row per scene with whitted's
// medians and ranges beside POV-Ray's and Embree's, then the scale section and
// the targets (see reports.hpp).
//
// Why this layout: the ratios are the point of the benchmark, so they sit next
// to the times they come from; a program that was not run leaves its cells
// empty, one that failed says "failed", so a gap is never mistaken for a zero.
#include "reports.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace whitted::bench {
namespace {

// "" when the program was not run, "failed", or the median with its range.
std::string cell(const Series& series, Metric metric, double scale = 1.0, const char* format = nullptr) {
    if (!series.attempted) return "";
    if (!series.failure.empty()) return "failed";
    const Summary s = summarize(series, metric);
    auto show = [&](double v) { return format ? format_number(v * scale, format) : format_seconds(v * scale); };
    if (!s.valid()) return "–";
    if (show(s.min) == show(s.max)) return show(s.median);
    return show(s.median) + " (" + show(s.min) + "–" + show(s.max) + ")";
}

std::string ratio_cell(const Series& a, const Series& b) {
    if (!a.attempted || !b.attempted) return "";
    return format_number(ratio(a, b, Metric::render), "%.2f×");
}

std::string rays_cell(const Series& series) {
    if (!series.attempted) return "";
    if (!series.ok()) return "failed";
    return format_count(series.samples.back().rays);
}

std::string row(const std::vector<std::string>& cells) {
    std::string text = "|";
    for (const std::string& c : cells) text += " " + c + " |";
    return text + "\n";
}

} // namespace

std::string results_table(const std::vector<SceneResult>& results) {
    const bool student = std::any_of(results.begin(), results.end(), [](const SceneResult& r) { return r.of(Tool::student).attempted; });
    std::vector<std::string> header{"scene", "primitives", "load+build s", "render s", "Mrays/s", "peak MB",
                                    "accel B/prim", "POV-Ray trace s", "whitted ÷ POV-Ray", "Embree s",
                                    "whitted ÷ Embree", "rays whitted", "rays Embree"};
    if (student) header.push_back("student render s");
    const bool rays_only = std::any_of(results.begin(), results.end(), [](const SceneResult& r) { return r.of(Tool::whitted_rays).attempted; });
    if (rays_only) header.insert(header.end(), {"whitted rays only s", "rays only ÷ Embree"});
    std::string text = row(header);
    text += row(std::vector<std::string>(header.size(), "---"));
    for (const SceneResult& r : results) {
        const Series& w = r.of(Tool::whitted);
        const Series& pov = r.of(Tool::povray);
        const Series& embree = r.of(Tool::embree);
        std::vector<std::string> cells{
            r.name + (r.failed() ? " (failed)" : ""),
            w.ok() ? format_count(w.primitives) : "–",
            cell(w, Metric::load_build),
            cell(w, Metric::render),
            cell(w, Metric::rays_per_second, 1e-6, "%.2f"),
            cell(w, Metric::peak_megabytes, 1.0, "%.0f"),
            format_number(bytes_per_primitive(w), "%.0f"),
            cell(pov, Metric::render),
            ratio_cell(w, pov),
            cell(embree, Metric::render),
            ratio_cell(w, embree),
            rays_cell(w),
            rays_cell(embree)};
        if (student) cells.push_back(cell(r.of(Tool::student), Metric::render));
        if (rays_only) cells.insert(cells.end(), {cell(r.of(Tool::whitted_rays), Metric::render), ratio_cell(r.of(Tool::whitted_rays), embree)});
        text += row(cells);
    }
    return text;
}

std::string markdown_report(const std::vector<SceneResult>& results, const BenchSettings& settings) {
    std::string text = "# whitted-bench results\n\n" + settings_line(settings) + ". Times in seconds: median " +
                       "(min–max). whitted: its own load + build and render times; POV-Ray: its trace time (without " +
                       "its start-up); Embree: the same rays without shading; whitted rays only: those rays shot into whitted's own " +
                       "scene, also without shading. Ratios below 1 mean whitted is faster.\n\n";
    text += results_table(results);
    std::string failures;
    for (const SceneResult& r : results)
        for (Tool tool : kTools)
            if (!r.of(tool).failure.empty()) failures += "- " + r.of(tool).failure + "\n";
    if (!failures.empty()) text += "\nFailed runs:\n\n" + failures;
    const std::string scale = scale_table(results);
    if (!scale.empty()) text.append("\n## Scale (sphereflake levels)\n\n").append(scale);
    text.append("\n").append(targets_section(results, settings));
    return text;
}

} // namespace whitted::bench
