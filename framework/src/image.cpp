// Writing images as PNG, binary PPM (P6) or PFM, and the 8-bit encoding of colours.
#include "image_format.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <limits>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace whitted {

namespace detail {

ImageError image_error(const std::filesystem::path& path, const std::string& what) {
    return ImageError(path.string() + ": " + what);
}

ImageFormat image_format(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".png") return ImageFormat::png;
    if (extension == ".ppm") return ImageFormat::ppm;
    if (extension == ".pfm") return ImageFormat::pfm;
    if (extension == ".jpg" || extension == ".jpeg") return ImageFormat::jpeg;
    if (extension.empty()) throw image_error(path, "the file name has no extension (accepted: .png, .ppm, .pfm; .jpg for reading)");
    throw image_error(path, "unknown image extension '" + path.extension().string() +
                                "' (accepted: .png, .ppm, .pfm; .jpg for reading)");
}

} // namespace detail

namespace {

using detail::image_error;

/// The image's 8-bit RGB samples, top row first.
std::vector<unsigned char> to_bytes(const Image& image, Encoding encoding) {
    std::vector<unsigned char> bytes;
    bytes.reserve(image.pixels.size() * 3);
    for (const Color& c : image.pixels) {
        for (int k = 0; k < 3; ++k) bytes.push_back(to_byte(c[k], encoding));
    }
    return bytes;
}

/// Opens a binary output file, or throws naming the path.
std::ofstream open_for_writing(const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw image_error(path, "cannot open for writing");
    return out;
}

/// Flushes and closes the file, throwing when any write failed (disk full, I/O error).
void finish_writing(std::ofstream& out, const std::filesystem::path& path) {
    out.flush();
    out.close();
    if (!out) throw image_error(path, "write failed");
}

/// Writes a binary PPM (P6, maxval 255).
void write_ppm(const Image& image, const std::filesystem::path& path, Encoding encoding) {
    const std::vector<unsigned char> bytes = to_bytes(image, encoding);
    std::ofstream out = open_for_writing(path);
    out << "P6\n" << image.width << ' ' << image.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    finish_writing(out, path);
}

/// Writes an RGB PFM: little-endian floats (scale -1.0), bottom row first as the format requires.
/// Values beyond the float range are clamped to the largest float, so no infinity is written.
void write_pfm(const Image& image, const std::filesystem::path& path) {
    std::ofstream out = open_for_writing(path);
    out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
    // A row at a time: a buffer of the whole image would cost a page fault per 4 KiB of it.
    std::vector<unsigned char> row;
    row.reserve(static_cast<std::size_t>(image.width) * 12);
    for (int y = image.height - 1; y >= 0; --y) {
        row.clear();
        for (int x = 0; x < image.width; ++x) {
            for (int k = 0; k < 3; ++k) {
                constexpr double kLargestFloat = std::numeric_limits<float>::max();
                const double value = std::clamp(image.at(x, y)[k], -kLargestFloat, kLargestFloat);
                const auto bits = std::bit_cast<std::uint32_t>(static_cast<float>(value));
                for (int shift = 0; shift < 32; shift += 8) row.push_back(static_cast<unsigned char>(bits >> shift));
            }
        }
        out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size()));
    }
    finish_writing(out, path);
}

/// Appends what stb_image_write hands over to the std::string it was given as `context`.
void append_to_string(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

/// An 8-bit RGB PNG of a checked image, encoded by stb_image_write; empty if it could not encode.
std::string encode_png(const Image& image, Encoding encoding) {
    const std::vector<unsigned char> bytes = to_bytes(image, encoding);
    std::string png;
    if (stbi_write_png_to_func(append_to_string, &png, image.width, image.height, 3, bytes.data(), image.width * 3) == 0)
        png.clear();
    return png;
}

/// Writes an 8-bit RGB PNG into a file opened here by its std::filesystem::path, so that any
/// path the platform can name works (non-ASCII on Windows).
void write_png(const Image& image, const std::filesystem::path& path, Encoding encoding) {
    std::ofstream out = open_for_writing(path);
    const std::string png = encode_png(image, encoding);
    if (png.empty()) throw image_error(path, "cannot write PNG file");
    out.write(png.data(), static_cast<std::streamsize>(png.size()));
    finish_writing(out, path);
}

} // namespace

std::size_t count_non_finite(const Image& image) {
    return static_cast<std::size_t>(
        std::count_if(image.pixels.begin(), image.pixels.end(), [](const Color& c) { return !is_finite(c); }));
}

unsigned char to_byte(double value, Encoding encoding) {
    // Clamp to [0, 1]; the negated test also sends NaN to 0, so the cast below is always defined.
    double v = !(value > 0.0) ? 0.0 : std::min(value, 1.0);
    // The sRGB transfer function (OETF): linear near black, a 1/2.4 power above 0.0031308.
    if (encoding == Encoding::srgb) {
        v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    }
    return static_cast<unsigned char>(std::lround(v * 255.0));
}

std::string png_bytes(const Image& image, Encoding encoding) {
    if (image.width <= 0 || image.height <= 0 || image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw ImageError("cannot encode an empty or inconsistent image as PNG");
    if (const std::size_t bad = count_non_finite(image); bad > 0)
        throw ImageError("refusing to encode " + std::to_string(bad) + " pixel(s) with NaN or infinite values as PNG");
    std::string png = encode_png(image, encoding);
    if (png.empty()) throw ImageError("cannot encode the image as PNG");
    return png;
}

void write_image(const Image& image, const std::filesystem::path& path, Encoding encoding) {
    const detail::ImageFormat format = detail::image_format(path);
    if (format == detail::ImageFormat::jpeg)
        throw image_error(path, "JPEG files can be read (skybox faces) but not written (write .png, .ppm or .pfm)");
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height) {
        throw image_error(path, "cannot write an empty or inconsistent image (" + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ", " + std::to_string(image.pixels.size()) +
                                    " pixels)");
    }
    if (const std::size_t bad = count_non_finite(image); bad > 0) {
        throw image_error(path, "refusing to write " + std::to_string(bad) + " pixel(s) with NaN or infinite values");
    }
    switch (format) {
    case detail::ImageFormat::png: write_png(image, path, encoding); break;
    case detail::ImageFormat::ppm: write_ppm(image, path, encoding); break;
    case detail::ImageFormat::pfm: write_pfm(image, path); break;
    case detail::ImageFormat::jpeg: break; // refused above
    }
}

} // namespace whitted
