// Internal to the scene and image readers: a double read from text, on every standard library.
//
// Why: std::from_chars for double is C++17, but some standard libraries
// students use lack it: LLVM's libc++ until recent releases (Debian 12's
// libc++ 14, the libc++ of the Xcode versions students have) declares it
// deleted. Where the library has it (it then defines __cpp_lib_to_chars) the
// readers use it; elsewhere std::strtod reads the same text into the same
// double (both round correctly), behind a scan that accepts exactly what
// std::from_chars accepts and errors decided as libstdc++ decides them.
#pragma once

#include <charconv>

namespace whitted::detail {

/// Reads a double at the front of [first, last) as std::from_chars does (general format: no '+', no hex).
std::from_chars_result double_from_chars(const char* first, const char* last, double& value);

/// The same result through std::strtod: what double_from_chars() does where std::from_chars has no double.
std::from_chars_result double_from_chars_by_strtod(const char* first, const char* last, double& value);

} // namespace whitted::detail
