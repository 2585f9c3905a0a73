// Options that `whitted render` and `whitted trace` share: the image size, the
// output path and --min-weight, checked where they are parsed.
#pragma once

#include "whitted/camera.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <utility>

namespace whitted {

/// The image size: the scene file's, unless --width/--height say otherwise
/// (one of them alone keeps the file's aspect ratio).
std::pair<int, int> output_size(const Camera& camera, std::optional<int> width, std::optional<int> height);

/// An explanation when the size is over the limits (16384 per side, SceneLimits::max_pixels), else empty.
std::string check_output_size(int width, int height);

/// Checks an image path before rendering (extension, folder, permission); empty when it is fine.
std::string check_output_path(const std::string& path);

/// Accepts a number from 0 to 1 written in full (0.5abc is not 0.5).
CLI::Validator min_weight_validator();

/// Accepts a file path whose folder exists and is writable ("-" too, for the standard output).
CLI::Validator writable_file_validator();

} // namespace whitted
