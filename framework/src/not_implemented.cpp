#include "whitted/not_implemented.hpp"

#include <algorithm>
#include <string>

namespace whitted {
namespace {

// "/home/ana/whitted/labs/02_shadows.cpp" -> "labs/02_shadows.cpp", and the same from
// "C:\Users\ana\whitted\labs\02_shadows.cpp" (Visual Studio names files with backslashes).
std::string short_file_name(std::string path) {
    std::replace(path.begin(), path.end(), '\\', '/');
    const std::size_t labs = path.rfind("labs/");
    if (labs != std::string::npos) return path.substr(labs);
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

} // namespace

void not_implemented(const char* file, int line, const char* function) {
    throw NotImplemented(short_file_name(file) + ":" + std::to_string(line) + ": " + function +
                         "() is not implemented yet");
}

} // namespace whitted
