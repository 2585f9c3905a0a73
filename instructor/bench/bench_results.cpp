// Summaries and ratios over the samples of a benchmark (see bench_results.hpp).
#include "bench_results.hpp"

#include <algorithm>

namespace whitted::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double value_of(const Sample& sample, Metric metric) {
    switch (metric) {
    case Metric::load_build: return sample.load_build_seconds;
    case Metric::render: return sample.render_seconds;
    case Metric::rays_per_second:
        return sample.rays > 0 && sample.render_seconds > 0.0 ? static_cast<double>(sample.rays) / sample.render_seconds
                                                              : kNaN;
    case Metric::peak_megabytes: return sample.peak_megabytes;
    }
    return kNaN;
}

} // namespace

const ToolStyle& style(Tool tool) {
    static constexpr std::array<ToolStyle, kTools.size()> kStyles{{
        {"whitted", "whitted", "whitted render", "#2b6cb0"},
        {"POV-Ray", "povray", "POV-Ray trace", "#dd6b20"},
        {"Embree", "embree", "Embree (rays only)", "#38a169"},
        {"student", "student", "student build render", "#805ad5"},
        {"whitted rays only", "whitted_rays", "whitted (rays only)", "#90cdf4"},
    }};
    return kStyles[static_cast<std::size_t>(tool)];
}

Summary summarize(std::vector<double> values) {
    std::erase_if(values, [](double v) { return v != v; });
    Summary summary;
    if (values.empty()) return summary;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    summary.median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    summary.min = values.front();
    summary.max = values.back();
    return summary;
}

Summary summarize(const Series& series, Metric metric) {
    if (!series.ok()) return {};
    std::vector<double> values;
    for (const Sample& sample : series.samples) values.push_back(value_of(sample, metric));
    return summarize(std::move(values));
}

bool SceneResult::failed() const {
    return std::any_of(series.begin(), series.end(), [](const Series& s) { return s.attempted && !s.failure.empty(); });
}

double ratio(const Series& a, const Series& b, Metric metric) {
    const Summary top = summarize(a, metric), bottom = summarize(b, metric);
    if (!top.valid() || !bottom.valid() || bottom.median <= 0.0) return kNaN;
    return top.median / bottom.median;
}

double bytes_per_primitive(const Series& series) {
    if (!series.ok() || series.primitives == 0) return kNaN;
    return static_cast<double>(series.acceleration_bytes) / static_cast<double>(series.primitives);
}

} // namespace whitted::bench
