// What `whitted-bench` measures: for each scene and each program, one sample
// per run, and the median, minimum and maximum that the reports show.
//
// Why: timings on a shared machine wobble, so every number is reported as the
// median of several runs with its range; keeping the raw samples lets the
// Markdown table, the JSON, the charts and the target checks all derive their
// numbers the same way from one place.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace whitted::bench {

/// One run of one program on one scene.
struct Sample {
    double load_build_seconds = 0.0; // reading the scene and building the acceleration structure
    double render_seconds = 0.0;     // tracing the rays (POV-Ray: its own trace time)
    std::uint64_t rays = 0;          // every ray cast; 0 when the program does not say
    double peak_megabytes = 0.0;     // the process's peak resident memory
};

/// The programs a benchmark compares, in the order of the reports.
/// whitted_rays is Embree's ray traffic shot into whitted's own scene: traversal
/// without shading, to set against Embree's.
enum class Tool { whitted, povray, embree, student, whitted_rays };
inline constexpr std::array<Tool, 5> kTools{Tool::whitted, Tool::povray, Tool::embree, Tool::student, Tool::whitted_rays};

/// How the reports name and draw a program.
struct ToolStyle {
    std::string_view label;  // in tables and messages: "POV-Ray"
    std::string_view key;    // in results.json and file names: "povray"
    std::string_view legend; // in the chart: "POV-Ray trace"
    std::string_view colour; // of its bars: "#dd6b20"
};

/// The names and colour of `tool`.
const ToolStyle& style(Tool tool);

/// The name a report shows: "whitted", "POV-Ray", "Embree", "student", "whitted rays only".
inline std::string_view tool_label(Tool tool) { return style(tool).label; }

/// The key in results.json: "whitted", "povray", "embree", "student", "whitted_rays".
inline std::string_view tool_key(Tool tool) { return style(tool).key; }

/// Every run of one program on one scene.
struct Series {
    bool attempted = false;      // false when the program is not part of this benchmark
    std::string failure;         // one line once a run failed; the remaining runs are skipped
    std::vector<Sample> samples; // the measured runs, warm-up excluded
    std::size_t primitives = 0, acceleration_bytes = 0;

    /// True when the program ran every time without failing.
    bool ok() const { return attempted && failure.empty() && !samples.empty(); }
};

/// What is summarised over the runs.
enum class Metric { load_build, render, rays_per_second, peak_megabytes };

struct Summary {
    double median = std::numeric_limits<double>::quiet_NaN();
    double min = std::numeric_limits<double>::quiet_NaN();
    double max = std::numeric_limits<double>::quiet_NaN();

    /// True when there was at least one value.
    bool valid() const { return median == median; }
};

/// The median (mean of the middle two for an even count), minimum and maximum.
Summary summarize(std::vector<double> values);

/// The summary of one metric over the series' runs; invalid when the series is not ok().
Summary summarize(const Series& series, Metric metric);

/// A scene of the benchmark and what each program measured on it.
struct SceneResult {
    std::string name;           // "flake4", "teapot6": unique within a benchmark
    std::filesystem::path path; // the scene file
    std::string generator;      // "sphereflake" or "tetra" when generated, else empty
    int level = -1;             // the generator's level
    std::array<Series, kTools.size()> series;

    /// The series of one program.
    Series& of(Tool tool) { return series[static_cast<std::size_t>(tool)]; }
    const Series& of(Tool tool) const { return series[static_cast<std::size_t>(tool)]; }

    /// True when any program that was run on this scene failed.
    bool failed() const;
};

/// Median of `a` over median of `b` for the metric; NaN when either is missing.
double ratio(const Series& a, const Series& b, Metric metric);

/// Acceleration-structure bytes per primitive as whitted reports them; NaN without a count.
double bytes_per_primitive(const Series& series);

/// The settings shared by every scene of a benchmark.
struct BenchSettings {
    int size = 512, threads = 2, depth = 5, runs = 5, warmup = 1;
};

} // namespace whitted::bench
