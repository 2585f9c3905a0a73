#include "printable.hpp"

namespace whitted::detail {

std::string escaped_bytes(std::string_view text, bool keep_line_breaks) {
    std::string shown;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte >= 0x20 && byte < 0x7f) || (keep_line_breaks && (c == '\n' || c == '\t'))) {
            shown += c;
        } else {
            static const char digits[] = "0123456789abcdef";
            shown += "\\x";
            shown += digits[byte >> 4];
            shown += digits[byte & 15];
        }
    }
    return shown;
}

std::string quoted_printable(std::string_view word) {
    constexpr std::size_t kMostShown = 60;
    // Appended, not "'" + a string: GCC 12 warns, wrongly, that the latter may overlap (-Wrestrict).
    std::string quoted = "'";
    quoted += escaped_bytes(word.substr(0, kMostShown));
    quoted += word.size() > kMostShown ? "...'" : "'";
    return quoted;
}

} // namespace whitted::detail
