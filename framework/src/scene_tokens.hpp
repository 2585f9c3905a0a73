// The token stream under both scene dialects, and the reader of an entity's numbers.
//
// Why: NFF and P3F are streams of whitespace-separated words where line breaks
// never matter, so the parsers only see tokens. Each token remembers its line
// and column, and every error goes through `TokenStream::fail`, which gives all
// messages the one shape "file:line:col: expected ..., found ...".
#pragma once

#include "whitted/math.hpp"

#include <string>
#include <string_view>

namespace whitted::detail {

/// One word of the file; an empty `text` marks the end of the file.
struct Token {
    std::string_view text;
    int line = 1;
    int column = 1;

    bool is_end() const { return text.empty(); }
};

/// True when the token is written like a number (including nan, inf and malformed ones such as 1.2.3).
bool looks_like_number(std::string_view text);

/// The shortest text that reads back as the same double (1.5, not 1.500000).
std::string format_number(double value);

/// The word between single quotes: 'word'.
std::string quoted(std::string_view word);

/// The token as an error message names it: 'abc' or "end of file".
std::string describe(const Token& token);

/// Splits scene text into tokens; `#` starts a comment that runs to the end of the line.
class TokenStream {
  public:
    /// Words longer than `max_token_length` characters are an error.
    TokenStream(std::string_view text, std::string_view file_name, std::size_t max_token_length = 1024);

    /// The next token, left in the stream.
    const Token& peek();

    /// The next token, taken from the stream.
    Token next();

    /// True when the next token is written like a number.
    bool next_is_number() { return looks_like_number(peek().text); }

    /// How many tokens next() has taken so far.
    std::size_t taken() const { return taken_; }

    /// "file:line:col" of the token.
    std::string where(const Token& token) const;

    /// The whole text being read.
    std::string_view text() const { return text_; }

    /// The file name the messages give (paths in the file are relative to its folder).
    const std::string& file_name() const { return file_name_; }

    /// Throws the SceneError "file:line:col: message" located at the token.
    [[noreturn]] void fail(const Token& token, const std::string& message) const;

  private:
    // Reads the token after the last one into peeked_ (in place: a token returned
    // and then copied is read back in wider pieces than it was written, which waits).
    void scan();

    std::string_view text_;
    std::string file_name_;
    std::size_t max_token_length_;
    std::size_t pos_ = 0;
    int line_ = 1;
    std::size_t line_start_ = 0; // where line_ starts in text_
    std::size_t taken_ = 0;
    Token last_end_;              // where the end of the file is reported: just after the last token
    Token peeked_;                // the next token, when has_peeked_
    bool has_peeked_ = false;
};

/// Reads the numbers that follow one keyword, so that a short entity reports
/// how many numbers are still missing ("expected 3 more numbers for 's'").
class NumberReader {
  public:
    /// `entity` names the keyword in messages; `count` is how many numbers it takes.
    NumberReader(TokenStream& tokens, std::string entity, long long count);

    /// Announces `count` more numbers, once a count read from the file is known.
    void expect_more(long long count) { remaining_ += count; }

    /// A finite number, described in messages as `what` ("the sphere radius").
    double number(std::string_view what);

    /// A finite number >= 0.
    double non_negative(std::string_view what);

    /// A finite number > 0.
    double positive(std::string_view what);

    /// Three finite numbers.
    Vec3 vec3(std::string_view what);

    /// Three finite numbers >= 0 (a colour or an intensity).
    Color color(std::string_view what);

    /// A whole number in [min, max], written without a fraction or exponent.
    long long integer(std::string_view what, long long min, long long max);

    /// The token of the number read last.
    const Token& last() const { return last_; }

  private:
    // Takes the next token, which must look like a number, into last_ and returns it.
    const Token& take(std::string_view what);

    TokenStream& tokens_;
    std::string entity_;
    long long remaining_;
    Token last_;
};

} // namespace whitted::detail
