#include "explore/compiler_messages.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

namespace whitted {
namespace {

// A line number or a column: 1 to 9 digits, the whole of `text`.
std::optional<int> small_number(std::string_view text) {
    int value = 0;
    if (text.empty() || text.size() > 9) return std::nullopt;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// The text after the first of `markers` in `line`, and the text before it.
std::optional<std::pair<std::string_view, std::string_view>> split_at(std::string_view line,
                                                                     std::initializer_list<std::string_view> markers) {
    for (std::string_view marker : markers)
        if (const std::size_t at = line.find(marker); at != std::string_view::npos)
            return std::pair{line.substr(0, at), line.substr(at + marker.size())};
    return std::nullopt;
}

// `text` without its leading spaces (MSBuild indents the lines it passes on, and its summary).
std::string_view without_indent(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    return text;
}

// `line` without the " [C:\...\x.vcxproj]" that MSBuild adds to every error line it passes on (its path, absolute,
// may hold " [" too).
std::string_view without_project(std::string_view line) {
    if (!line.ends_with(".vcxproj]")) return line;
    const auto absolute = [](std::string_view path) {
        return path.starts_with("\\\\") || path.starts_with("/") ||
               (path.size() > 2 && std::isalpha(static_cast<unsigned char>(path[0])) && path.substr(1, 2) == ":\\");
    };
    for (std::size_t open = line.rfind(" ["); open != std::string_view::npos && open > 0; open = line.rfind(" [", open - 1))
        if (absolute(line.substr(open + 2))) return line.substr(0, open);
    return line;
}

// GCC and Clang: "file:line:column: error: message" (column optional; file may hold ':', as in C:\...).
std::optional<CompilerError> gnu_error(std::string_view line) {
    const auto parts = split_at(line, {": fatal error: ", ": error: "});
    if (!parts) return std::nullopt;
    std::string_view place = parts->first;
    CompilerError error;
    std::size_t colon = place.rfind(':');
    if (colon == std::string_view::npos) return std::nullopt;
    std::optional<int> last = small_number(place.substr(colon + 1));
    if (!last) return std::nullopt;
    place = place.substr(0, colon);
    colon = place.rfind(':');
    std::optional<int> before = colon == std::string_view::npos ? std::nullopt : small_number(place.substr(colon + 1));
    if (before) { // file:line:column
        error.line = *before;
        error.column = *last;
        place = place.substr(0, colon);
    } else { // file:line
        error.line = *last;
    }
    if (place.empty()) return std::nullopt;
    error.file = place;
    error.message = parts->second;
    return error;
}

// MSVC: "file(line,column): error C2143: message" (column optional).
std::optional<CompilerError> msvc_error(std::string_view line) {
    const auto parts = split_at(line, {"): fatal error ", "): error "});
    if (!parts) return std::nullopt;
    const std::string_view place = parts->first;
    const std::size_t open = place.rfind('(');
    if (open == std::string_view::npos || open == 0) return std::nullopt;
    std::string_view numbers = place.substr(open + 1);
    CompilerError error;
    const std::size_t comma = numbers.find(',');
    const std::optional<int> line_number = small_number(numbers.substr(0, comma));
    const std::optional<int> column = comma == std::string_view::npos ? std::optional(0) : small_number(numbers.substr(comma + 1));
    if (!line_number || !column) return std::nullopt;
    error.line = *line_number;
    error.column = *column;
    error.file = without_indent(place.substr(0, open));
    std::string_view message = without_project(parts->second); // "C2143: syntax error: ..."
    if (const std::size_t code = message.find(": "); code != std::string_view::npos && message.front() == 'C')
        message.remove_prefix(code + 2);
    error.message = message;
    return error;
}

// MSBuild's summary line "    1 Error(s)" (or "Warning(s)"): a count, not an error.
bool is_count_line(std::string_view line) {
    line = without_indent(line);
    const std::size_t space = line.find(' ');
    return space != std::string_view::npos && small_number(line.substr(0, space)) &&
           (line.substr(space) == " Error(s)" || line.substr(space) == " Warning(s)");
}

// Adds `error` to `errors` unless it is there already (MSBuild repeats every error in its summary).
void add_new(std::vector<CompilerError>& errors, CompilerError error) {
    if (std::find(errors.begin(), errors.end(), error) == errors.end()) errors.push_back(std::move(error));
}

// Calls `take(line)` on each line of `output` (without its "\r\n" or "\n") while it returns true.
template <typename Take>
void for_each_line(std::string_view output, Take take) {
    std::size_t start = 0;
    while (start < output.size()) {
        std::size_t end = output.find('\n', start);
        if (end == std::string_view::npos) end = output.size();
        std::string_view line = output.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        start = end + 1;
        if (!take(line)) return;
    }
}

} // namespace

std::vector<CompilerError> compiler_errors(std::string_view output, std::size_t limit) {
    std::vector<CompilerError> errors;
    for_each_line(output, [&](std::string_view line) {
        if (std::optional<CompilerError> error = gnu_error(line)) add_new(errors, std::move(*error));
        else if (std::optional<CompilerError> msvc = msvc_error(line)) add_new(errors, std::move(*msvc));
        return errors.size() < limit;
    });
    return errors;
}

std::vector<CompilerError> build_errors(std::string_view output) {
    std::vector<CompilerError> errors = compiler_errors(output);
    if (!errors.empty()) return errors;
    for_each_line(output, [&](std::string_view line) {
        line = without_project(line);
        if (is_count_line(line)) return true;
        std::string lower(line);
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        for (const char* word : {"error", "undefined reference", "undefined symbol"}) // GNU ld, lld, Apple's ld, MSVC's link
            if (lower.find(word) != std::string::npos) {
                add_new(errors, CompilerError{"", 0, 0, std::string(without_indent(line))});
                break;
            }
        return errors.size() < 10;
    });
    return errors;
}

} // namespace whitted
