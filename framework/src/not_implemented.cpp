#include "whitted/not_implemented.hpp"

#include <string_view>

namespace whitted {
namespace {

// "std::optional<Vec3> whitted::refracted_direction(const Vec3&, ...)" -> "refracted_direction"
std::string_view short_function_name(std::string_view signature) {
    const std::size_t open = signature.find('(');
    std::string_view name = signature.substr(0, open);
    const std::size_t scope = name.rfind("::");
    if (scope != std::string_view::npos) name.remove_prefix(scope + 2);
    const std::size_t space = name.rfind(' ');
    if (space != std::string_view::npos) name.remove_prefix(space + 1);
    return name;
}

// "/home/ana/whitted/labs/02_shadows.cpp" -> "labs/02_shadows.cpp"
std::string_view short_file_name(std::string_view path) {
    const std::size_t labs = path.rfind("labs/");
    if (labs != std::string_view::npos) return path.substr(labs);
    const std::size_t slash = path.rfind('/');
    return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

} // namespace

void not_implemented(std::source_location where) {
    throw NotImplemented(std::string(short_file_name(where.file_name())) + ":" + std::to_string(where.line()) + ": " +
                         std::string(short_function_name(where.function_name())) + "() is not implemented yet");
}

} // namespace whitted
