// double_from_chars(): the doubles and the errors of std::from_chars, on every
// standard library; its std::strtod path (the one for standard libraries
// without std::from_chars for double) gives the same on every input.
#include "double_from_chars.hpp"
#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <system_error>
#include <vector>

using whitted::detail::double_from_chars;
using whitted::detail::double_from_chars_by_strtod;
using whitted::testing_helpers::enough_failures;

namespace {

using Reader = std::from_chars_result (*)(const char*, const char*, double&);

constexpr double kUntouched = -12345.0; // what the value keeps when there is an error
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Case {
    const char* text;
    int used; // characters read
    std::errc error;
    double value;
};

// What libstdc++'s std::from_chars gives (GCC 12).
const Case kCases[] = {
    {"1.5", 3, std::errc(), 1.5},
    {"-0.25e2", 7, std::errc(), -25.0},
    {"0.1", 3, std::errc(), 0.1},
    {"5.", 2, std::errc(), 5.0},
    {".5", 2, std::errc(), 0.5},
    {"1.2.3", 3, std::errc(), 1.2},
    {"1e", 1, std::errc(), 1.0},
    {"1e+", 1, std::errc(), 1.0},
    {"1E+5x", 4, std::errc(), 1e5},
    {"0x10", 1, std::errc(), 0.0},
    {"-0", 2, std::errc(), -0.0},
    {"0e999999", 8, std::errc(), 0.0},
    {"1e-310", 6, std::errc(), 1e-310},
    {"2.5e-324", 8, std::errc(), 0x1p-1074},
    {"2.2250738585072011e-308", 23, std::errc(), 0x0.fffffffffffffp-1022},
    {"1.7976931348623158e308", 22, std::errc(), std::numeric_limits<double>::max()},
    {"infinity", 8, std::errc(), kInfinity},
    {"infinit", 3, std::errc(), kInfinity},
    {"-INF", 4, std::errc(), -kInfinity},
    {"", 0, std::errc::invalid_argument, kUntouched},
    {"-", 0, std::errc::invalid_argument, kUntouched},
    {".", 0, std::errc::invalid_argument, kUntouched},
    {".e1", 0, std::errc::invalid_argument, kUntouched},
    {"+1", 0, std::errc::invalid_argument, kUntouched},
    {" 1", 0, std::errc::invalid_argument, kUntouched},
    {"e5", 0, std::errc::invalid_argument, kUntouched},
    {"1e400", 5, std::errc::result_out_of_range, kUntouched},
    {"-1e400", 6, std::errc::result_out_of_range, kUntouched},
    {"1.7976931348623159e308", 22, std::errc::result_out_of_range, kUntouched},
    {"1e-400", 6, std::errc::result_out_of_range, kUntouched},
    {"2.4e-324", 8, std::errc::result_out_of_range, kUntouched},
    {"1e-99999999999999999999", 23, std::errc::result_out_of_range, kUntouched},
};

// NaNs, compared by their sign (their other bits may differ between libraries).
struct NanCase {
    const char* text;
    int used;
    bool negative;
};
const NanCase kNanCases[] = {{"nan", 3, false}, {"NaN(abc_1)", 10, false}, {"nan(", 3, false}, {"nan(a b)", 3, false},
                             {"-nan", 4, true}};

void expect_cases(Reader read, const char* name) {
    for (const Case& c : kCases) {
        double value = kUntouched;
        const auto result = read(c.text, c.text + std::strlen(c.text), value);
        EXPECT_EQ(result.ptr - c.text, c.used) << name << ": characters read of '" << c.text << "'";
        EXPECT_EQ(result.ec, c.error) << name << ": error for '" << c.text << "'";
        EXPECT_EQ(std::bit_cast<std::uint64_t>(value), std::bit_cast<std::uint64_t>(c.value))
            << name << ": '" << c.text << "' read as " << value << ", expected " << c.value;
    }
    for (const NanCase& c : kNanCases) {
        double value = kUntouched;
        const auto result = read(c.text, c.text + std::strlen(c.text), value);
        EXPECT_EQ(result.ptr - c.text, c.used) << name << ": characters read of '" << c.text << "'";
        EXPECT_EQ(result.ec, std::errc()) << name << ": error for '" << c.text << "'";
        EXPECT_TRUE(std::isnan(value)) << name << ": '" << c.text << "' read as " << value;
        EXPECT_EQ(std::signbit(value), c.negative) << name << ": the sign of '" << c.text << "'";
    }
}

} // namespace

TEST(DoubleFromChars, ReadsWhatStdFromCharsReads) {
    expect_cases(double_from_chars, "double_from_chars");
}

TEST(DoubleFromChars, ItsStrtodPathReadsTheSame) {
    expect_cases(double_from_chars_by_strtod, "double_from_chars_by_strtod");
}

TEST(DoubleFromChars, ItsStrtodPathAgreesWithStdFromCharsOnRandomText) {
#if defined(__cpp_lib_to_chars)
    // Random words of number characters, and random numbers of up to 20 digits that
    // round to every kind of double, subnormal and out of range ones included.
    std::mt19937 random(20240611);
    std::vector<std::string> texts;
    const std::string alphabet = "0123456789.eE+-";
    for (int i = 0; i < 50000; ++i) {
        std::string text;
        const int length = 1 + static_cast<int>(random() % 12);
        for (int k = 0; k < length; ++k) text += alphabet[random() % alphabet.size()];
        texts.push_back(text);
    }
    for (int i = 0; i < 50000; ++i) {
        std::string text = (random() % 2) ? "-" : "";
        const int digits = 1 + static_cast<int>(random() % 20);
        const int point = (random() % 2) ? static_cast<int>(random() % digits) : -1; // the '.' before digit `point`
        for (int k = 0; k < digits; ++k) {
            if (k == point) text += '.';
            text += static_cast<char>('0' + random() % 10);
        }
        texts.push_back(text + "e" + std::to_string(static_cast<int>(random() % 680) - 345));
    }
    for (const std::string& text : texts) {
        double expected = kUntouched, value = kUntouched;
        const auto wanted = std::from_chars(text.data(), text.data() + text.size(), expected);
        const auto got = double_from_chars_by_strtod(text.data(), text.data() + text.size(), value);
        const bool same = got.ptr == wanted.ptr && got.ec == wanted.ec &&
                          std::bit_cast<std::uint64_t>(value) == std::bit_cast<std::uint64_t>(expected);
        EXPECT_TRUE(same) << "'" << text << "': std::from_chars read " << wanted.ptr - text.data() << " characters as "
                          << expected << " (error " << static_cast<int>(wanted.ec) << "), the strtod path "
                          << got.ptr - text.data() << " as " << value << " (error " << static_cast<int>(got.ec) << ")";
        if (enough_failures()) return;
    }
#else
    GTEST_SKIP() << "this standard library has no std::from_chars for double to compare with";
#endif
}
