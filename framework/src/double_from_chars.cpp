#include "double_from_chars.hpp"

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <string_view>

namespace whitted::detail {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// True when [p, last) starts with `word`, in upper or lower case.
bool starts_with_word(const char* p, const char* last, std::string_view word) {
    if (static_cast<std::size_t>(last - p) < word.size()) return false;
    for (const char letter : word) {
        const char c = *p++;
        if (c != letter && c != letter - 'a' + 'A') return false;
    }
    return true;
}

/// What the front of some text holds, written as std::from_chars reads it.
struct NumberText {
    const char* end = nullptr; ///< just past the number; nullptr when the text starts with none
    bool infinity = false;     ///< "inf" or "infinity"
    bool non_zero = false;     ///< a digit other than 0 (a number that is not zero)
};

/// The number at the front of [first, last) in std::from_chars's general format:
/// [-] then inf, infinity, nan, nan(letters, digits and _), or decimal digits
/// with at most one '.' and an optional exponent (e, an optional sign, digits).
NumberText scan_number(const char* first, const char* last) {
    NumberText number;
    const char* p = first;
    if (p != last && *p == '-') ++p;
    if (starts_with_word(p, last, "inf")) {
        number.infinity = true;
        number.end = starts_with_word(p, last, "infinity") ? p + 8 : p + 3;
        return number;
    }
    if (starts_with_word(p, last, "nan")) {
        number.end = p + 3;
        const char* q = number.end;
        if (q != last && *q == '(') {
            ++q;
            while (q != last && (is_digit(*q) || *q == '_' || (*q >= 'a' && *q <= 'z') || (*q >= 'A' && *q <= 'Z'))) ++q;
            if (q != last && *q == ')') number.end = q + 1;
        }
        return number;
    }
    int digits = 0;
    bool point = false;
    for (; p != last && (is_digit(*p) || (*p == '.' && !point)); ++p) {
        if (*p == '.') {
            point = true;
            continue;
        }
        ++digits;
        if (*p != '0') number.non_zero = true;
    }
    if (digits == 0) return number;
    number.end = p;
    if (p != last && (*p == 'e' || *p == 'E')) {
        const char* q = p + 1;
        if (q != last && (*q == '+' || *q == '-')) ++q;
        if (q != last && is_digit(*q)) {
            while (q != last && is_digit(*q)) ++q;
            number.end = q;
        }
    }
    return number;
}

} // namespace

std::from_chars_result double_from_chars(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars)
    return std::from_chars(first, last, value);
#else
    return double_from_chars_by_strtod(first, last, value);
#endif
}

std::from_chars_result double_from_chars_by_strtod(const char* first, const char* last, double& value) {
    const NumberText number = scan_number(first, last);
    if (number.end == nullptr) return {first, std::errc::invalid_argument};
    // strtod reads the number's own characters only, NUL-terminated. It reads
    // '.' as the decimal point in the C locale, which this program keeps: it
    // never calls setlocale().
    const std::string text(first, number.end);
    const double parsed = std::strtod(text.c_str(), nullptr);
    // Out of range as libstdc++'s std::from_chars says it (strtod's errno differs between
    // systems on tiny results): a finite number whose nearest double is infinite, or a
    // non-zero one whose nearest double is 0. The value is then left as it was.
    if ((std::isinf(parsed) && !number.infinity) || (parsed == 0.0 && number.non_zero))
        return {number.end, std::errc::result_out_of_range};
    value = parsed;
    return {number.end, std::errc()};
}

} // namespace whitted::detail
