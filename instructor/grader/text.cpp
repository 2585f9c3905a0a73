#include "grader/text.hpp"

#include <algorithm>
#include <cstdio>

namespace whitted::grade {

std::string replace_paths(std::string text, std::vector<std::pair<std::string, std::string>> replacements) {
    std::stable_sort(replacements.begin(), replacements.end(),
                     [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    for (const auto& [from, to] : replacements) {
        if (from.empty()) continue;
        std::string result;
        std::size_t position = 0;
        for (std::size_t found; (found = text.find(from, position)) != std::string::npos; position = found + from.size())
            result.append(text, position, found - position).append(to);
        text = result + text.substr(position);
    }
    return text;
}

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = end + 1;
    }
    return lines;
}

std::string trim_text(const std::string& text, std::size_t max_lines, std::size_t max_line_length, std::size_t max_chars) {
    std::vector<std::string> lines = split_lines(text);
    while (!lines.empty() && lines.back().find_first_not_of(" \t") == std::string::npos) lines.pop_back();
    std::string result;
    const std::size_t shown = std::min(lines.size(), max_lines);
    for (std::size_t i = 0; i < shown; ++i) {
        std::string line = lines[i];
        if (line.size() > max_line_length) line = line.substr(0, max_line_length) + " [...]";
        if (result.size() + line.size() + 1 > max_chars) {
            result += "[... output cut at " + std::to_string(max_chars) + " characters]\n";
            return result;
        }
        result += line + "\n";
    }
    if (lines.size() > shown) result += "[... " + std::to_string(lines.size() - shown) + " more lines]\n";
    return result;
}

std::string first_lines(const std::string& text, std::size_t max_lines) {
    const std::vector<std::string> lines = split_lines(text);
    if (lines.size() <= max_lines) return text;
    std::string kept;
    for (std::size_t i = 0; i < max_lines; ++i) kept += lines[i] + "\n";
    return kept + "\u2026 " + std::to_string(lines.size() - max_lines) + " more lines like these\n";
}

std::string format_points(long cents) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%ld.%02ld", cents < 0 ? "-" : "", std::labs(cents) / 100, std::labs(cents) % 100);
    return text;
}

} // namespace whitted::grade
