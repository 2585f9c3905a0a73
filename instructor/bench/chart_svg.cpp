// The chart: for each scene a group of horizontal bars (whitted render,
// POV-Ray trace, Embree ray traffic), on a labelled log-scale time axis, with
// a legend and each value written at the end of its bar (see reports.hpp).
//
// Why a log scale: the scenes span milliseconds (tetra6) to seconds (a level-6
// flake); on a log axis equal ratios are equal distances, so "five times
// faster than POV-Ray" looks the same on every scene. Written by hand as SVG:
// a few rectangles and texts need no library.
#include "reports.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace whitted::bench {
namespace {

constexpr double kWidth = 960, kLeft = 150, kRight = 100, kTop = 96, kBottom = 64;
constexpr double kBar = 18, kBarGap = 4, kGroupGap = 20;

std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
    return out;
}

std::string px(double v) { return format_number(v, "%.1f"); }

std::string text_at(double x, double y, const std::string& body, const std::string& style = "") {
    return "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"" + (style.empty() ? "" : " " + style) + ">" + body + "</text>\n";
}

// The log axis: from a power of ten below the smallest value to one above the largest.
struct Axis {
    double low_exp = -2, high_exp = 0, plot_width = kWidth - kLeft - kRight;
    double x(double seconds) const {
        return kLeft + (std::log10(seconds) - low_exp) / (high_exp - low_exp) * plot_width;
    }
};

Axis axis_for(const std::vector<SceneResult>& results) {
    double low = 1e300, high = 0.0;
    for (const SceneResult& r : results)
        for (Tool tool : kTools)
            if (const double v = median_render(r, tool); v > 0.0) low = std::min(low, v), high = std::max(high, v);
    Axis axis;
    if (high <= 0.0) return axis;
    axis.low_exp = std::floor(std::log10(low));
    axis.high_exp = std::max(axis.low_exp + 1.0, std::ceil(std::log10(high) + 1e-9));
    return axis;
}

std::string grid(const Axis& axis, double top, double bottom) {
    std::string svg;
    const bool label_minor = axis.high_exp - axis.low_exp <= 2.0;
    for (double e = axis.low_exp; e <= axis.high_exp; ++e) {
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, e);
            if (std::log10(v) > axis.high_exp + 1e-9) break;
            const double x = axis.x(v);
            const bool major = m == 1.0;
            svg += "<line x1=\"" + px(x) + "\" y1=\"" + px(top) + "\" x2=\"" + px(x) + "\" y2=\"" + px(bottom) +
                   "\" stroke=\"" + (major ? "#bbb" : "#e2e2e2") + "\"" + (major ? "" : " stroke-dasharray=\"3 3\"") + "/>\n";
            if (major || label_minor)
                svg += text_at(x, bottom + 16, format_number(v, "%g"), "text-anchor=\"middle\" fill=\"#444\"");
        }
    }
    return svg;
}

} // namespace

std::string svg_chart(const std::vector<SceneResult>& results, const BenchSettings& settings) {
    std::vector<Tool> tools{Tool::whitted, Tool::povray, Tool::embree};
    for (Tool optional : {Tool::whitted_rays, Tool::student})
        if (std::any_of(results.begin(), results.end(), [&](const SceneResult& r) { return r.of(optional).attempted; }))
            tools.push_back(optional);
    const double group = tools.size() * (kBar + kBarGap) - kBarGap;
    const double plot_bottom = kTop + results.size() * (group + kGroupGap);
    const double height = plot_bottom + kBottom;
    const Axis axis = axis_for(results);

    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(kWidth) + "\" height=\"" + px(height) +
                      "\" viewBox=\"0 0 " + px(kWidth) + " " + px(height) +
                      "\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"12\">\n"
                      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += text_at(kLeft, 24, "whitted-bench: time per image, median of the runs", "font-size=\"17\" font-weight=\"bold\"");
    svg += text_at(kLeft, 44, escaped(settings_line(settings)), "fill=\"#444\"");
    double legend_x = kLeft;
    for (Tool tool : tools) {
        const std::string legend(style(tool).legend), colour(style(tool).colour);
        svg += "<rect x=\"" + px(legend_x) + "\" y=\"58\" width=\"14\" height=\"14\" fill=\"" + colour + "\"/>\n";
        svg += text_at(legend_x + 20, 70, legend);
        legend_x += 40 + 7.0 * legend.size();
    }
    svg += grid(axis, kTop - 8, plot_bottom - kGroupGap + 8);
    for (std::size_t i = 0; i < results.size(); ++i) {
        const SceneResult& r = results[i];
        const double top = kTop + i * (group + kGroupGap);
        svg += text_at(kLeft - 10, top + group / 2 + 5, escaped(r.name), "text-anchor=\"end\" font-weight=\"bold\"");
        for (std::size_t k = 0; k < tools.size(); ++k) {
            const Series& series = r.of(tools[k]);
            const double y = top + k * (kBar + kBarGap);
            if (!series.ok()) {
                const char* note = !series.attempted ? "skipped" : "failed";
                svg += text_at(kLeft + 6, y + 13, note, series.attempted ? "fill=\"#c53030\"" : "fill=\"#999\"");
                continue;
            }
            const double seconds = median_render(r, tools[k]);
            const double end = std::max(kLeft + 1.0, axis.x(seconds));
            svg += "<rect x=\"" + px(kLeft) + "\" y=\"" + px(y) + "\" width=\"" + px(end - kLeft) + "\" height=\"" +
                   px(kBar) + "\" fill=\"" + std::string(style(tools[k]).colour) + "\"><title>" +
                   std::string(tool_label(tools[k])) + " on " +
                   escaped(r.name) + ": " + format_seconds(seconds) + " s</title></rect>\n";
            svg += text_at(end + 5, y + 13, format_seconds(seconds) + " s");
        }
    }
    svg += "<line x1=\"" + px(kLeft) + "\" y1=\"" + px(kTop - 8) + "\" x2=\"" + px(kLeft) + "\" y2=\"" +
           px(plot_bottom - kGroupGap + 8) + "\" stroke=\"#333\"/>\n";
    svg += text_at(kLeft + axis.plot_width / 2, height - 18, "seconds per image (log scale)", "text-anchor=\"middle\"");
    return svg + "</svg>\n";
}

} // namespace whitted::bench
