// The version comes from project() in the top CMakeLists.txt, and the build
// mode from WHITTED_MODE; only this file is compiled with them, so a new
// version number rebuilds nothing else.
#include "version.hpp"

#include "whitted/engine/wide_bvh.hpp"

namespace whitted {

std::string version_line() {
    return std::string("whitted ") + WHITTED_VERSION + " (" + WHITTED_BUILD_MODE + " build; BVH box tests in " +
           (WideBvh::cpu_has_avx2() ? "AVX2" : "SSE2") + " on this CPU)";
}

} // namespace whitted
