#include "scene_tokens.hpp"
#include "double_from_chars.hpp"
#include "printable.hpp"

#include "whitted/scene_loader.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace whitted::detail {

namespace {

constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// What the scanner does at a byte: one table lookup instead of seven comparisons a byte.
enum class ByteKind : unsigned char { word, blank, newline, comment };
constexpr std::array<ByteKind, 256> kByteKinds = [] {
    std::array<ByteKind, 256> kinds{};
    for (int c = 0; c < 256; ++c)
        kinds[c] = c == '\n' ? ByteKind::newline : c == '#' ? ByteKind::comment
                 : is_space(static_cast<char>(c)) ? ByteKind::blank : ByteKind::word;
    return kinds;
}();
ByteKind kind_of(char c) { return kByteKinds[static_cast<unsigned char>(c)]; }

bool starts_with_word(std::string_view text, std::string_view word) {
    if (text.size() < word.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) != word[i]) return false;
    return true;
}

/// Drops one leading '+', which std::from_chars does not accept.
std::string_view without_plus(std::string_view text) {
    if (text.size() > 1 && text[0] == '+' && text[1] != '+' && text[1] != '-') text.remove_prefix(1);
    return text;
}

enum class Parsed { ok, malformed, not_finite };

/// Parses the whole token as a double; values too small for a double become 0 (or a subnormal).
Parsed parse_double(std::string_view text, double& value) {
    text = without_plus(text);
    const auto [end, error] = double_from_chars(text.data(), text.data() + text.size(), value);
    if (end != text.data() + text.size()) return Parsed::malformed;
    if (error == std::errc::result_out_of_range) {
        // from_chars reports underflow and overflow alike; strtod tells them apart.
        value = std::strtod(std::string(text).c_str(), nullptr);
        if (std::isinf(value)) return Parsed::not_finite;
    } else if (error != std::errc()) {
        return Parsed::malformed;
    }
    return std::isfinite(value) ? Parsed::ok : Parsed::not_finite;
}

// Larger numbers would overflow lengths and areas (their squares must stay finite).
constexpr double kLargestNumber = 1e15;

std::string numbers_phrase(long long count) {
    return count == 1 ? "1 more number" : std::to_string(count) + " more numbers";
}

} // namespace

bool looks_like_number(std::string_view text) {
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
    if (text.empty()) return false;
    if (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.') return true;
    return starts_with_word(text, "nan") || starts_with_word(text, "inf");
}

std::string format_number(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string quoted(std::string_view word) {
    std::string text;
    text.reserve(word.size() + 2);
    text += '\'';
    text += word;
    text += '\'';
    return text;
}

std::string describe(const Token& token) {
    return token.is_end() ? "end of file" : quoted_printable(token.text);
}

TokenStream::TokenStream(std::string_view text, std::string_view file_name, std::size_t max_token_length)
    : text_(text), file_name_(file_name), max_token_length_(max_token_length) {
    // Editors on some systems start UTF-8 files with a byte-order mark: skip it.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = line_start_ = 3; // columns count from after it
    // Others save "Unicode" text as UTF-16, which has a NUL byte beside every letter.
    if (text_.starts_with("\xFF\xFE") || text_.starts_with("\xFE\xFF"))
        fail(Token{}, "expected a text file in ASCII or UTF-8, found UTF-16 (save the file as UTF-8)");
}

const Token& TokenStream::peek() {
    if (!has_peeked_) {
        scan();
        has_peeked_ = true;
    }
    return peeked_;
}

Token TokenStream::next() {
    peek();
    has_peeked_ = false;
    ++taken_;
    return peeked_;
}

void TokenStream::scan() {
    // Skip blanks and comments, counting lines as we go; a column is its byte's distance from the line's start.
    const std::size_t size = text_.size();
    while (pos_ < size) {
        const ByteKind kind = kind_of(text_[pos_]);
        if (kind == ByteKind::blank) {
            ++pos_;
        } else if (kind == ByteKind::newline) {
            line_start_ = ++pos_;
            ++line_;
        } else if (kind == ByteKind::comment) {
            const std::size_t end = text_.find('\n', pos_);
            pos_ = end == std::string_view::npos ? size : end;
        } else {
            break;
        }
    }
    if (pos_ == size) {
        peeked_ = last_end_;
        return;
    }
    peeked_.line = line_;
    peeked_.column = static_cast<int>(pos_ - line_start_) + 1;
    const std::size_t start = pos_;
    while (pos_ < size && kind_of(text_[pos_]) == ByteKind::word) ++pos_;
    peeked_.text = text_.substr(start, pos_ - start);
    if (peeked_.text.size() > max_token_length_)
        fail(peeked_, "expected a word or number of at most " + std::to_string(max_token_length_) +
                          " characters, found one of " + std::to_string(peeked_.text.size()) + " (is this a scene file?)");
    last_end_.line = line_;
    last_end_.column = static_cast<int>(pos_ - line_start_) + 1;
}

std::string TokenStream::where(const Token& token) const {
    return file_name_ + ":" + std::to_string(token.line) + ":" + std::to_string(token.column);
}

void TokenStream::fail(const Token& token, const std::string& message) const {
    throw SceneError(where(token) + ": " + message);
}

NumberReader::NumberReader(TokenStream& tokens, std::string entity, long long count)
    : tokens_(tokens), entity_(std::move(entity)), remaining_(count) {}

const Token& NumberReader::take(std::string_view what) {
    const Token& token = tokens_.peek();
    if (token.is_end())
        tokens_.fail(token, "expected " + numbers_phrase(remaining_) + " for " + entity_ + ", found end of file");
    if (!looks_like_number(token.text))
        tokens_.fail(token, "expected a number for " + std::string(what) + ", found " + describe(token));
    --remaining_;
    last_ = tokens_.next();
    return last_;
}

double NumberReader::number(std::string_view what) {
    const Token& token = take(what);
    double value = 0.0;
    switch (parse_double(token.text, value)) {
    case Parsed::ok:
        if (std::abs(value) > kLargestNumber)
            tokens_.fail(token, "expected a number between -1e15 and 1e15 for " + std::string(what) + ", found " +
                                    describe(token));
        return value;
    case Parsed::not_finite:
        tokens_.fail(token, "expected a finite number for " + std::string(what) + ", found " + describe(token));
    case Parsed::malformed: break;
    }
    tokens_.fail(token, "expected a number for " + std::string(what) + ", found " + describe(token));
}

double NumberReader::non_negative(std::string_view what) {
    const double value = number(what);
    if (value < 0.0)
        tokens_.fail(last_, "expected a non-negative number for " + std::string(what) + ", found " + describe(last_));
    return value;
}

double NumberReader::positive(std::string_view what) {
    const double value = number(what);
    if (!(value > 0.0))
        tokens_.fail(last_, "expected a positive number for " + std::string(what) + ", found " + describe(last_));
    return value;
}

Vec3 NumberReader::vec3(std::string_view what) {
    const double x = number(what);
    const double y = number(what);
    return {x, y, number(what)};
}

Color NumberReader::color(std::string_view what) {
    const double r = non_negative(what);
    const double g = non_negative(what);
    return {r, g, non_negative(what)};
}

long long NumberReader::integer(std::string_view what, long long min, long long max) {
    const Token& token = take(what);
    const std::string_view text = without_plus(token.text);
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (end != text.data() + text.size() || error == std::errc::invalid_argument)
        tokens_.fail(token, "expected a whole number for " + std::string(what) + ", found " + describe(token));
    // Too long for any integer: out of range, like a huge value that fits.
    if (error == std::errc::result_out_of_range)
        value = text.starts_with('-') ? std::numeric_limits<long long>::min() : std::numeric_limits<long long>::max();
    if (value < min || value > max)
        tokens_.fail(token, "expected a whole number from " + std::to_string(min) + " to " + std::to_string(max) +
                                " for " + std::string(what) + ", found " + describe(token));
    return value;
}

} // namespace whitted::detail
