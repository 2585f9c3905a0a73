// The benchmark's reports: the Markdown results (main table, scale section,
// targets), the terminal bar chart, the SVG chart and results.json.
//
// Why together: each report reads the same SceneResults and none of them
// measures anything, so the driver can print and write them in any order; the
// formatting helpers they share are declared here too.
#pragma once

#include "bench_results.hpp"

#include <string>
#include <vector>

namespace whitted::bench {

/// The whole Markdown report: settings, results table, scale section, targets.
std::string markdown_report(const std::vector<SceneResult>& results, const BenchSettings& settings);

/// The results table: one row per scene, medians with their range, ratios and ray counts.
std::string results_table(const std::vector<SceneResult>& results);

/// How the sphereflake's costs grow with its size; "" with fewer than two levels measured.
std::string scale_table(const std::vector<SceneResult>& results);

/// One target of issue 4 and how the benchmark did against it.
struct TargetCheck {
    std::string scene, what; // "flake4", "whitted render ÷ POV-Ray trace"
    double measured = 0.0, limit = 0.0;
    std::string unit; // "s", "×", "B"
    bool met() const { return measured <= limit; }
};

/// The targets the measured scenes have, checked (only at 512×512, 2 threads, depth 5).
std::vector<TargetCheck> check_targets(const std::vector<SceneResult>& results, const BenchSettings& settings);

/// The targets as a Markdown section.
std::string targets_section(const std::vector<SceneResult>& results, const BenchSettings& settings);

/// A figure of whitted's that got worse than in the baseline.
struct Regression {
    std::string scene, what, change; // "flake6", "load + build", "0.35 s → 0.52 s (1.49×)"
};

/// What comparing with a baseline found: the regressions, or a note why nothing was compared.
struct BaselineCheck {
    std::vector<Regression> regressions;
    int compared = 0; // scenes found in both
    std::string note; // why nothing was compared, else empty
};

/// Beyond this factor over the baseline (and this many seconds slower) a time is a regression;
/// a render's ratio to Embree, beyond kRatioMargin and that many seconds over what the baseline's
/// ratio gives (Embree's run takes the machine's drift out of it).
inline constexpr double kRegressionMargin = 1.25;
inline constexpr double kRegressionFloorSeconds = 0.005;
inline constexpr double kRatioMargin = 1.15;

/// Compares whitted's load + build and render times with the baseline's (an earlier results.json),
/// scene by scene by name; a baseline of other settings is not compared. Throws std::invalid_argument
/// when the baseline is not JSON.
BaselineCheck check_baseline(const std::vector<SceneResult>& results, const BenchSettings& settings,
                             const std::string& baseline_text);

/// The check as a Markdown section.
std::string baseline_section(const BaselineCheck& check, const std::string& baseline_name);

/// Render times as horizontal bars of Unicode blocks, for the terminal.
std::string terminal_chart(const std::vector<SceneResult>& results);

/// A picture of the render times: grouped horizontal bars per scene on a log scale.
std::string svg_chart(const std::vector<SceneResult>& results, const BenchSettings& settings);

/// Every sample and summary, the settings and the targets as JSON.
std::string results_json(const std::vector<SceneResult>& results, const BenchSettings& settings);

/// Seconds with three significant digits: "0.0105", "0.387", "12.3".
std::string format_seconds(double seconds);

/// `value` printed with a printf format ("%.2f×"); "–" for NaN.
std::string format_number(double value, const char* printf_format);

/// "7,381": thousands separated by commas.
std::string format_count(std::uint64_t count);

/// The value a tool's bar or cell shows: its median render time, NaN when missing.
double median_render(const SceneResult& result, Tool tool);

/// The one-line settings: "512×512, 1 ray per pixel, depth 5, 2 threads, median of 5 runs after 1 warm-up".
std::string settings_line(const BenchSettings& settings);

} // namespace whitted::bench
