// The version comes from project() in the top CMakeLists.txt, and the build
// mode from WHITTED_MODE; only this file is compiled with them, so a new
// version number rebuilds nothing else.
#include "version.hpp"

namespace whitted {

std::string version_line() { return std::string("whitted ") + WHITTED_VERSION + " (" + WHITTED_BUILD_MODE + " build)"; }

} // namespace whitted
