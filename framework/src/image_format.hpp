// Internal to image.cpp and image_read.cpp: which file format a path names.
#pragma once

#include "whitted/image.hpp"

#include <filesystem>
#include <string>

namespace whitted::detail {

enum class ImageFormat { png, ppm, pfm };

/// The format named by the path's extension (case-insensitive); throws ImageError for any other.
ImageFormat image_format(const std::filesystem::path& path);

/// "path: what" as an ImageError, the one shape of every image error message.
ImageError image_error(const std::filesystem::path& path, const std::string& what);

} // namespace whitted::detail
