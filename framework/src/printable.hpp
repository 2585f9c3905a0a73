// Internal to the scene and image readers: a word of a file as an error message shows it.
#pragma once

#include <string>
#include <string_view>

namespace whitted::detail {

/// The word between single quotes, at most 60 characters of it (then "..."),
/// with control and non-ASCII bytes as \xNN: a message stays one readable line
/// whatever bytes the file holds.
std::string quoted_printable(std::string_view word);

/// The text with control and non-ASCII bytes as \xNN; with `keep_line_breaks`,
/// newlines and tabs stay as they are.
std::string escaped_bytes(std::string_view text, bool keep_line_breaks = false);

} // namespace whitted::detail
