// Small text helpers for what the grader shows: no absolute paths, bounded
// length, and nothing a submission wrote that could drive a terminal.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
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

/// Whether terminal_text keeps newlines (a block of lines) or shows them escaped (one line).
enum class Newlines { escaped, kept };

/// The text as a terminal may show it: every control character a terminal acts
/// on (C0 but tab and, with Newlines::kept, newline; DEL; the C1 code points
/// U+0080-U+009F) and every byte that is not part of valid UTF-8 shown as an
/// escape (`\x1b`, `\u009b`, `\xff`), so that a student's folder name, output
/// or message can neither drive the instructor's terminal (window title, OSC 52
/// clipboard, a cleared screen, a line overwritten by a carriage return) nor
/// hide that it tried. Printable text, valid UTF-8 included, is kept as it is,
/// so the result is unchanged by a second pass.
std::string terminal_text(std::string_view text, Newlines newlines = Newlines::escaped);

/// Writes the text to the stream as terminal_text shows it, newlines kept:
/// with print_line, the one way `whitted grade` and `grade-all` print.
void print_text(std::FILE* stream, std::string_view text);

/// Writes one line as terminal_text shows it (a newline in it escaped, so that
/// it stays one line and cannot forge the next), then a newline.
void print_line(std::FILE* stream, std::string_view line);

/// Points kept as whole hundredths: 1234 -> "12.34".
std::string format_points(long cents);

} // namespace whitted::grade
