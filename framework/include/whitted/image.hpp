// An RGB image of linear colours, and reading / writing it as PNG, PPM or PFM.
//
// Why: the renderer works in linear floating-point colour; files are written
// clamped to [0, 1] and, as in the course and in NFF practice, without gamma
// unless sRGB encoding is asked for. The format follows the file extension.
// Non-finite values (NaN, infinity) never reach a file: writing refuses them.
#pragma once

#include "whitted/math.hpp"

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace whitted {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels; // row-major, top row first

    Image() = default;
    Image(int width_, int height_, Color fill = Color(0.0))
        : width(width_), height(height_), pixels(static_cast<std::size_t>(width_) * height_, fill) {}

    Color& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const Color& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// How colours become 8-bit values in PNG and PPM files (PFM stores floats as they are).
enum class Encoding { linear, srgb };

/// Raised for unreadable or unwritable image files; the message starts with the path.
struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Number of pixels with a NaN or infinite component.
std::size_t count_non_finite(const Image& image);

/// Writes the image; the format comes from the extension (.png, .ppm, .pfm).
/// Throws ImageError for another extension (.jpg is read only), a non-finite pixel or an I/O failure.
void write_image(const Image& image, const std::filesystem::path& path, Encoding encoding = Encoding::linear);

/// The image as the bytes of an 8-bit PNG file (to send rather than write). Throws ImageError for an
/// empty image or a non-finite pixel.
std::string png_bytes(const Image& image, Encoding encoding = Encoding::linear);

/// Reads a .png, .jpg / .jpeg, .ppm (P6 or P3) or .pfm file. 8-bit values v become v / 255
/// (no gamma decoding). Throws ImageError with the reason.
Image read_image(const std::filesystem::path& path);

/// Reads the bytes of a PNG file (as png_bytes gives them); `name` is for messages. Throws ImageError.
Image read_png_bytes(std::string_view bytes, const std::string& name);

/// The 8-bit value written for a linear colour component: clamped to [0, 1],
/// optionally sRGB-encoded, then rounded.
unsigned char to_byte(double value, Encoding encoding);

} // namespace whitted
