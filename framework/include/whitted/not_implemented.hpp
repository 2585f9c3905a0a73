// How an unfinished lab function says so.
//
// Why: a stub that returned a default value would render a silently wrong
// picture. Every stub in labs/ is the single line `not_implemented();`, which
// throws an error naming the file, line and function, such as
// "labs/05_refraction.cpp:18: refracted_direction() is not implemented yet".
// The renderer, the tests and the grader all report that message as it is.
#pragma once

#include <stdexcept>
#include <string>

namespace whitted {

/// Thrown by an unfinished lab function.
struct NotImplemented : std::logic_error {
    using std::logic_error::logic_error;
};

/// Throws NotImplemented naming the calling function and its place in the file.
/// (The builtins, unlike std::source_location, work with both g++ and clang 14.)
[[noreturn]] void not_implemented(const char* file = __builtin_FILE(), int line = __builtin_LINE(),
                                  const char* function = __builtin_FUNCTION());

} // namespace whitted
