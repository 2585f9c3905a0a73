// Internal to image.cpp and image_read.cpp (and the image fuzz target): which
// file format a path names, and decoding a file held in memory.
#pragma once

#include "whitted/image.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace whitted::detail {

enum class ImageFormat { png, ppm, pfm, jpeg }; // JPEG: read only (skybox faces)

/// The format named by the path's extension (case-insensitive); throws ImageError for any other.
ImageFormat image_format(const std::filesystem::path& path);

/// Images larger than this many pixels are refused before anything is allocated
/// (8192 x 8192: 1.5 GiB of linear colour). Renders obey the same limit.
inline constexpr std::size_t kMaxImagePixels = std::size_t{1} << 26;

/// Decodes a whole image file held in memory; `path` names it in messages.
/// Throws ImageError for a malformed file, more than `max_pixels` pixels or a
/// non-finite PFM value.
Image decode_image(std::string_view bytes, ImageFormat format, const std::filesystem::path& path,
                   std::size_t max_pixels = kMaxImagePixels);

/// An 8-bit RGB picture as PNG and JPEG files hold it: row-major, top row first.
struct Rgb8Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb; // width x height x 3 values
};

/// Reads a PNG or JPEG file as 8-bit RGB (a skybox face) straight from its decoder, without the detour
/// through linear colour (a 2048 x 2048 face's 100 MB of doubles). Throws ImageError as read_image does,
/// and for a file of another format.
Rgb8Image read_rgb8(const std::filesystem::path& path);

/// "path: what" as an ImageError, the one shape of every image error message.
ImageError image_error(const std::filesystem::path& path, const std::string& what);

} // namespace whitted::detail
