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

namespace {

// The length (2 to 4) of the well-formed UTF-8 sequence at text[at] (no overlong form, surrogate or code point past
// U+10FFFF), or 0 when the bytes there are not one.
std::size_t utf8_length(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
    const unsigned char lead = byte(0);
    const std::size_t length = lead >= 0xc2 && lead <= 0xdf ? 2 : lead >= 0xe0 && lead <= 0xef ? 3 : lead >= 0xf0 && lead <= 0xf4 ? 4 : 0;
    if (length == 0 || at + length > text.size()) return 0;
    // The second byte's range: 0x80-0xbf, narrower after the leads whose full range would be overlong or out of Unicode.
    const unsigned char low = lead == 0xe0 ? 0xa0 : lead == 0xf0 ? 0x90 : 0x80;
    const unsigned char high = lead == 0xed ? 0x9f : lead == 0xf4 ? 0x8f : 0xbf;
    if (byte(1) < low || byte(1) > high) return 0;
    for (std::size_t k = 2; k < length; ++k)
        if (byte(k) < 0x80 || byte(k) > 0xbf) return 0;
    return length;
}

// `\x1b` for a byte, `\u009b` for a C1 code point.
std::string escaped(const char* prefix, unsigned value, int digits) {
    char text[16];
    std::snprintf(text, sizeof text, "%s%0*x", prefix, digits, value);
    return text;
}

// Appends what terminal_text shows of the character at text[at]; returns how many bytes it took.
std::size_t append_shown(std::string& shown, std::string_view text, std::size_t at, Newlines newlines) {
    const auto c = static_cast<unsigned char>(text[at]);
    if (c < 0x80) {
        const bool plain = (c >= 0x20 && c < 0x7f) || c == '\t' || (c == '\n' && newlines == Newlines::kept);
        shown += plain ? std::string(1, static_cast<char>(c)) : escaped("\\x", c, 2);
        return 1;
    }
    const std::size_t length = utf8_length(text, at);
    if (length == 0) shown += escaped("\\x", c, 2); // not UTF-8 (a lone 0x9b is CSI to an 8-bit terminal)
    else if (c == 0xc2 && static_cast<unsigned char>(text[at + 1]) < 0xa0)
        shown += escaped("\\u", static_cast<unsigned char>(text[at + 1]), 4); // C1: U+0080-U+009F is 0xc2 0x80-0x9f
    else shown.append(text, at, length);
    return std::max<std::size_t>(length, 1);
}

} // namespace

std::string terminal_text(std::string_view text, Newlines newlines) {
    std::string shown;
    shown.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) at += append_shown(shown, text, at, newlines);
    return shown;
}

void print_text(std::FILE* stream, std::string_view text) {
    const std::string shown = terminal_text(text, Newlines::kept);
    std::fwrite(shown.data(), 1, shown.size(), stream);
}

void print_line(std::FILE* stream, std::string_view line) { print_text(stream, terminal_text(line) + "\n"); }

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
