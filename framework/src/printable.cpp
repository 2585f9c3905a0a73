#include "printable.hpp"

namespace whitted::detail {

std::string quoted_printable(std::string_view word) {
    constexpr std::size_t kMostShown = 60;
    std::string shown = "'";
    for (const char c : word.substr(0, kMostShown)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            shown += c;
        } else {
            static const char digits[] = "0123456789abcdef";
            shown += "\\x";
            shown += digits[byte >> 4];
            shown += digits[byte & 15];
        }
    }
    if (word.size() > kMostShown) shown += "...";
    return shown + "'";
}

} // namespace whitted::detail
