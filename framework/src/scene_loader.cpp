#include "whitted/scene_loader.hpp"

#include "prefault.hpp"
#include "scene_builder.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <future>
#include <system_error>

namespace whitted {

namespace {

std::string lower_case(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

} // namespace

LoadedScene load_scene(const std::filesystem::path& path, const SceneLimits& limits) {
    const std::string name = path.string();
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw SceneError(name + ": cannot open a directory as a scene file");
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        throw SceneError(name + ": not a regular file (a device, pipe or socket cannot be a scene file)");
    const std::string extension = lower_case(path.extension().string());
    Dialect dialect = Dialect::nff;
    if (extension == ".p3f") {
        dialect = Dialect::p3f;
    } else if (extension.empty()) {
        throw SceneError(name + ": the file name has no extension (expected .nff or .p3f, which tells the format)");
    } else if (extension != ".nff") {
        throw SceneError(name + ": unknown scene format '" + path.extension().string() + "' (expected .nff or .p3f)");
    }
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error && size > limits.max_file_bytes)
        throw SceneError(name + ": the file has " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(limits.max_file_bytes) + " a scene file may have");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw SceneError(name + ": cannot open the file (missing or unreadable)");
    // Read straight into a string of the file's size: big scenes are read, and their memory touched, once.
    std::string text;
    std::future<void> prefaulted; // declared after `text`: ends before it
    if (!error) {
        text.reserve(static_cast<std::size_t>(size));
        prefaulted = detail::prefault_behind(text.data(), text.capacity());
    }
    char buffer[1 << 16];
    while (file.read(buffer, sizeof buffer) || file.gcount() > 0) {
        // A file that grew since its size was read moves the text to a bigger block: the pages being mapped in first.
        if (text.size() + static_cast<std::size_t>(file.gcount()) > text.capacity() && prefaulted.valid()) prefaulted.get();
        text.append(buffer, static_cast<std::size_t>(file.gcount()));
        if (text.size() > limits.max_file_bytes) break; // it grew since: parse_scene says so
    }
    if (file.bad()) throw SceneError(name + ": cannot read the file");
    return parse_scene(text, dialect, name, limits);
}

LoadedScene parse_scene(std::string_view text, Dialect dialect, std::string_view file_name,
                        const SceneLimits& limits) {
    if (text.size() > limits.max_file_bytes)
        throw SceneError(std::string(file_name) + ": the file has " + std::to_string(text.size()) +
                         " bytes, more than the " + std::to_string(limits.max_file_bytes) + " a scene file may have");
    detail::TokenStream tokens(text, file_name, limits.max_token_length);
    return dialect == Dialect::nff ? detail::parse_nff(tokens, limits) : detail::parse_p3f(tokens, limits);
}

} // namespace whitted
