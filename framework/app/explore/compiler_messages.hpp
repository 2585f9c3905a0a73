// The errors in a compiler's output, each with its file and line, for the page to show when a lab does not
// compile.
//
// Why: the build's output is long (the build tool's progress, notes, the lines of code quoted); the student
// needs the first error and where it is. GCC and Clang write "file:line:column: error: message", MSVC
// "file(line,column): error C1234: message"; both are read, and anything else is left to the full output.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace whitted {

struct CompilerError {
    std::string file;   // as the compiler wrote it
    int line = 0;
    int column = 0;     // 0: not given
    std::string message;
    bool operator==(const CompilerError&) const = default;
};

/// The errors of `output` in order, each once (MSBuild repeats them in its summary), at most `limit` of them.
std::vector<CompilerError> compiler_errors(std::string_view output, std::size_t limit = 20);

/// What a failed build shows: its compiler errors, or when there is none (the linker's errors, which have no
/// line), the lines that say "error" or name an undefined function (any case) as messages without a file, each
/// once, at most 10.
std::vector<CompilerError> build_errors(std::string_view output);

} // namespace whitted
