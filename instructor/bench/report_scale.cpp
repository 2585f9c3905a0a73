// The scale section: the sphereflake at several levels, to show how load +
// build and render time grow with the number of spheres (see reports.hpp).
//
// Why these columns: with a good acceleration structure, building grows about
// like n and tracing like log n. "render growth ÷ log growth" near 1 says the
// render time follows log n; well above 1 says it grows faster.
#include "reports.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace whitted::bench {
std::string scale_table(const std::vector<SceneResult>& results) {
    std::vector<const SceneResult*> flakes;
    for (const SceneResult& r : results)
        if (r.generator == "sphereflake" && r.of(Tool::whitted).ok()) flakes.push_back(&r);
    if (flakes.size() < 2) return {};
    std::sort(flakes.begin(), flakes.end(), [](const SceneResult* a, const SceneResult* b) { return a->level < b->level; });

    const SceneResult& first = *flakes.front();
    const double first_render = median_render(first, Tool::whitted);
    const double first_log = std::log(static_cast<double>(first.of(Tool::whitted).primitives));
    std::string text = "| level | primitives | load+build s | load+build µs per primitive | render s | render growth | "
                       "log n growth | render growth ÷ log growth | accel B/prim |\n"
                       "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const SceneResult* r : flakes) {
        const Series& w = r->of(Tool::whitted);
        const double n = static_cast<double>(w.primitives);
        const double load = summarize(w, Metric::load_build).median;
        const double render_growth = median_render(*r, Tool::whitted) / first_render;
        const double log_growth = std::log(n) / first_log;
        text += "| " + std::to_string(r->level) + " | " + format_count(w.primitives) + " | " + format_seconds(load) +
                " | " + format_number(load / n * 1e6, "%.2f") + " | " + format_seconds(median_render(*r, Tool::whitted)) +
                " | " + format_number(render_growth, "%.2f×") + " | " + format_number(log_growth, "%.2f×") + " | " +
                format_number(render_growth / log_growth, "%.2f") + " | " + format_number(bytes_per_primitive(w), "%.0f") + " |\n";
    }
    text += "\nGrowth is relative to level " + std::to_string(first.level) + " (n = primitives, ground included).\n";
    return text;
}

} // namespace whitted::bench
