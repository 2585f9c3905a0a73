#include "whitted/not_implemented.hpp"

#include <string_view>

namespace whitted {
namespace {

// "/home/ana/whitted/labs/02_shadows.cpp" -> "labs/02_shadows.cpp"
std::string_view short_file_name(std::string_view path) {
    const std::size_t labs = path.rfind("labs/");
    if (labs != std::string_view::npos) return path.substr(labs);
    const std::size_t slash = path.rfind('/');
    return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

} // namespace

void not_implemented(const char* file, int line, const char* function) {
    throw NotImplemented(std::string(short_file_name(file)) + ":" + std::to_string(line) + ": " + function +
                         "() is not implemented yet");
}

} // namespace whitted
