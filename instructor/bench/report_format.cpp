// Number formats shared by the reports (see reports.hpp).
#include "reports.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace whitted::bench {

std::string format_seconds(double seconds) {
    if (seconds != seconds) return "–";
    // Three significant digits without an exponent: 0.0000830, 0.0105, 0.387, 12.3, 1234.
    const int magnitude = seconds > 0.0 ? static_cast<int>(std::floor(std::log10(seconds))) : 0;
    const int decimals = std::clamp(2 - magnitude, 0, 9);
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, seconds);
    return text;
}

std::string format_number(double value, const char* printf_format) {
    if (value != value) return "–";
    char text[48];
    std::snprintf(text, sizeof text, printf_format, value);
    return text;
}

std::string format_count(std::uint64_t count) {
    std::string digits = std::to_string(count), text;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
        text += digits[i];
    }
    return text;
}

double median_render(const SceneResult& result, Tool tool) { return summarize(result.of(tool), Metric::render).median; }

std::string settings_line(const BenchSettings& s) {
    return std::to_string(s.size) + "×" + std::to_string(s.size) + ", 1 ray per pixel, depth " + std::to_string(s.depth) +
           " (eye ray = 1), " + std::to_string(s.threads) + (s.threads == 1 ? " thread" : " threads") + ", median of " +
           std::to_string(s.runs) + (s.runs == 1 ? " run" : " runs") + " after " + std::to_string(s.warmup) +
           (s.warmup == 1 ? " warm-up" : " warm-ups");
}

} // namespace whitted::bench
