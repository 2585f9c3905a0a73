// The render times as bars of Unicode block characters, printed after the
// table so that the proportions show in a terminal (see reports.hpp).
//
// Why linear: in a terminal the eye compares bar lengths directly; the SVG
// chart uses a log scale for the wide range, this one shows plain proportions.
// Eighth-blocks give the bars a resolution of 1/8 of a character.
#include "reports.hpp"

#include <algorithm>
#include <array>

namespace whitted::bench {
namespace {

constexpr int kWidth = 48; // characters of the longest bar

std::string bar(double value, double longest) {
    static constexpr std::array<const char*, 8> kEighths{"", "▏", "▎", "▍", "▌", "▋", "▊", "▉"};
    const int eighths = std::max(1, static_cast<int>(value / longest * kWidth * 8.0 + 0.5));
    std::string text;
    for (int i = 0; i < eighths / 8; ++i) text += "█";
    text += kEighths[static_cast<std::size_t>(eighths % 8)];
    return text;
}

std::string padded(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

} // namespace

std::string terminal_chart(const std::vector<SceneResult>& results) {
    double longest = 0.0;
    std::size_t name_width = 5;
    for (const SceneResult& r : results) {
        name_width = std::max(name_width, r.name.size());
        for (Tool tool : kTools)
            if (r.of(tool).ok()) longest = std::max(longest, median_render(r, tool));
    }
    std::string text = "Render time per image (median seconds; whitted render, POV-Ray trace, Embree ray traffic)\n";
    if (longest <= 0.0) return text + "  (nothing was measured)\n";
    for (const SceneResult& r : results) {
        std::string name = r.name;
        for (Tool tool : kTools) {
            const Series& series = r.of(tool);
            if (!series.attempted) continue;
            text += padded(name, name_width + 2) + padded(std::string(tool_label(tool)), 9);
            if (series.ok()) {
                const double seconds = median_render(r, tool);
                text += bar(seconds, longest) + " " + format_seconds(seconds) + "\n";
            } else {
                text += "failed\n";
            }
            name.clear();
        }
    }
    return text;
}

} // namespace whitted::bench
