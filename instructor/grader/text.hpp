// Small text helpers for what the grader shows: no absolute paths, bounded length.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace whitted::grade {

/// Replaces each `from` prefix with its `to` everywhere in the text, the
/// longest `from` first (so a build folder inside the output folder wins).
std::string replace_paths(std::string text, std::vector<std::pair<std::string, std::string>> replacements);

/// At most `max_lines` lines of at most `max_line_length` characters, then at
/// most `max_chars` in all; says what was cut. Trailing blank lines go.
std::string trim_text(const std::string& text, std::size_t max_lines, std::size_t max_line_length = 300,
                      std::size_t max_chars = 4000);

/// The text's first `max_lines` lines and, when it has more, one line "… N more lines like these":
/// a mistake that fails every input alike says so thousands of times.
std::string first_lines(const std::string& text, std::size_t max_lines);

/// The lines of a text (without their newlines).
std::vector<std::string> split_lines(const std::string& text);

/// Points kept as whole hundredths: 1234 -> "12.34".
std::string format_points(long cents);

} // namespace whitted::grade
