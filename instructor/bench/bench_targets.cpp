// The performance targets of issue 4, checked against a benchmark's medians.
//
// Why here: the targets are what `make bench` exists for; listing each one with
// its measured value and limit says at a glance which ones are met. They were
// set for 512×512, 1 ray per pixel, depth 5 and 2 threads, so they are only
// checked with those settings.
#include "reports.hpp"

#include <array>
#include <string_view>

namespace whitted::bench {
namespace {

enum class Measure { render, load_build, over_povray, over_embree, student_render };

struct Target {
    std::string_view scene; // the scene's name in the benchmark
    Measure measure;
    double limit;
};

// flake4 is the project's own balls4: both names get balls4's targets.
constexpr std::array<Target, 11> kTargets{{
    {"flake4", Measure::over_povray, 0.2},   {"flake4", Measure::over_embree, 1.3},
    {"balls4", Measure::over_povray, 0.2},   {"balls4", Measure::over_embree, 1.3},
    {"flake4", Measure::student_render, 1.0}, {"balls4", Measure::student_render, 1.0},
    {"teapot6", Measure::render, 0.045},     {"mount6", Measure::render, 0.10},
    {"tetra6", Measure::render, 0.015},      {"flake5", Measure::load_build, 0.1},
    {"flake6", Measure::load_build, 1.0},
}};

constexpr double kMaxBytesPerPrimitive = 100.0;

std::string describe(Measure measure) {
    switch (measure) {
    case Measure::render: return "whitted render";
    case Measure::load_build: return "whitted load + build";
    case Measure::over_povray: return "whitted render ÷ POV-Ray trace";
    case Measure::over_embree: return "whitted render ÷ Embree";
    case Measure::student_render: return "student build render";
    }
    return "?";
}

double measured(const SceneResult& r, Measure measure) {
    const Series& w = r.of(Tool::whitted);
    switch (measure) {
    case Measure::render: return median_render(r, Tool::whitted);
    case Measure::load_build: return summarize(w, Metric::load_build).median;
    case Measure::over_povray: return ratio(w, r.of(Tool::povray), Metric::render);
    case Measure::over_embree: return ratio(w, r.of(Tool::embree), Metric::render);
    case Measure::student_render: return median_render(r, Tool::student);
    }
    return 0.0;
}

} // namespace

std::vector<TargetCheck> check_targets(const std::vector<SceneResult>& results, const BenchSettings& s) {
    std::vector<TargetCheck> checks;
    if (s.size != 512 || s.threads != 2 || s.depth != 5) return checks;
    for (const SceneResult& r : results) {
        for (const Target& target : kTargets) {
            const double value = r.name == target.scene ? measured(r, target.measure) : -1.0;
            if (value == value && value >= 0.0) {
                const bool is_ratio = target.measure == Measure::over_povray || target.measure == Measure::over_embree;
                checks.push_back({r.name, describe(target.measure), value, target.limit, is_ratio ? "×" : " s"});
            }
        }
        const double bytes = bytes_per_primitive(r.of(Tool::whitted));
        if (bytes == bytes) checks.push_back({r.name, "acceleration structure per primitive", bytes, kMaxBytesPerPrimitive, " B"});
    }
    return checks;
}

std::string targets_section(const std::vector<SceneResult>& results, const BenchSettings& settings) {
    const std::vector<TargetCheck> checks = check_targets(results, settings);
    std::string text = "## Targets (issue 4)\n\n";
    if (checks.empty()) return text + "None of the measured scenes has a target at these settings (targets are set for "
                                      "512×512, 2 threads, depth 5).\n";
    text += "| scene | target | measured | limit | met |\n| --- | --- | --- | --- | --- |\n";
    for (const TargetCheck& c : checks) {
        const bool seconds = c.unit == " s";
        const std::string shown = seconds ? format_seconds(c.measured) : format_number(c.measured, c.unit == "×" ? "%.2f" : "%.0f");
        const std::string limit = seconds ? format_seconds(c.limit) : format_number(c.limit, c.unit == "×" ? "%.2f" : "%.0f");
        text += "| " + c.scene + " | " + c.what + " | " + shown + c.unit + " | ≤ " + limit + c.unit + " | " +
                (c.met() ? "yes" : "**no**") + " |\n";
    }
    return text;
}

} // namespace whitted::bench
