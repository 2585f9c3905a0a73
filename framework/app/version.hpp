// Which `whitted` this is: `whitted --version`.
#pragma once

#include <string>

namespace whitted {

/// One line with the version and the build, e.g. "whitted 0.16.0 (handout build)".
std::string version_line();

} // namespace whitted
