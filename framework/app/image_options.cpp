#include "image_options.hpp"
#include "platform.hpp"

#include "whitted/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace whitted {

std::pair<int, int> output_size(const Camera& camera, std::optional<int> width, std::optional<int> height) {
    if (width && height) return {*width, *height};
    if (width) return {*width, std::max(1, static_cast<int>(std::lround(*width * double(camera.res_y) / camera.res_x)))};
    if (height) return {std::max(1, static_cast<int>(std::lround(*height * double(camera.res_x) / camera.res_y))), *height};
    return {camera.res_x, camera.res_y};
}

std::string check_output_size(int width, int height) {
    // One of --width/--height with the scene's aspect ratio can ask for a huge other side.
    if (width <= 16384 && height <= 16384 && static_cast<std::size_t>(width) * height <= SceneLimits{}.max_pixels)
        return {};
    return "the image would be " + std::to_string(width) + " x " + std::to_string(height) +
           " pixels; the limit is 16384 per side and " + std::to_string(SceneLimits{}.max_pixels) + " in all";
}

std::string check_output_path(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) return "the image is a folder: " + path;
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png" && extension != ".ppm" && extension != ".pfm")
        return "the image must end in .png, .ppm or .pfm: " + path;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && std::filesystem::exists(folder, error) && !std::filesystem::is_directory(folder, error))
        return "not a folder, so the image cannot go in it: " + folder.string();
    if (!folder.empty() && !std::filesystem::is_directory(folder, error))
        return "no such folder for the image: " + folder.string();
    // Found now rather than after the whole render.
    const bool exists = std::filesystem::exists(path, error);
    if (exists && !std::filesystem::is_regular_file(path, error))
        return "not a regular file (a device or pipe cannot hold the image): " + path;
    if (!may_write(exists ? std::filesystem::path(path) : (folder.empty() ? "." : folder)))
        return "cannot write the image (no permission): " + path;
    return {};
}

CLI::Validator min_weight_validator() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double value = -1.0;
            std::size_t used = 0;
            try {
                value = std::stod(text, &used);
            } catch (...) {
            }
            const bool ok = used == text.size() && value >= 0.0 && value <= 1.0;
            return ok ? "" : "expected a number from 0 to 1, found " + text;
        },
        "0..1");
}

CLI::Validator writable_file_validator() {
    return CLI::Validator(
        [](const std::string& path) -> std::string {
            if (path == "-") return {};
            std::error_code error;
            if (std::filesystem::is_directory(path, error)) return "this is a folder, not a file: " + path;
            const std::filesystem::path folder = std::filesystem::path(path).parent_path();
            if (!folder.empty() && !std::filesystem::is_directory(folder, error)) return "no such folder: " + folder.string();
            const bool exists = std::filesystem::exists(path, error);
            if (!may_write(exists ? std::filesystem::path(path) : (folder.empty() ? "." : folder)))
                return "cannot write (no permission): " + path;
            return {};
        },
        "FILE");
}

} // namespace whitted
