// Reading PNG, JPEG, PPM (P6 and P3) and PFM (PF and Pf) files into linear images, and PNG and JPEG files
// into 8-bit pictures (skybox faces). Every malformed file becomes an ImageError "path: what is wrong".
#include "double_from_chars.hpp"
#include "image_format.hpp"
#include "printable.hpp"

#include <stb_image.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <climits>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace whitted {

namespace {

using detail::image_error;

constexpr int kMaxSide = 1 << 15;
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{2} << 30;

/// The whole file as bytes.
std::string read_file(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error) && !error) throw image_error(path, "no such file");
    if (std::filesystem::is_directory(path, error)) throw image_error(path, "is a directory, not an image file");
    if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
        throw image_error(path, "is not a regular file");
    if (const std::uintmax_t size = std::filesystem::file_size(path, error); !error && size > kMaxFileBytes)
        throw image_error(path, "is larger than the 2 GiB an image file may have");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw image_error(path, "cannot open for reading");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw image_error(path, "read failed");
    return bytes;
}

/// A cursor over a PPM / PFM header: whitespace-separated tokens with '#' comments.
class HeaderReader {
  public:
    HeaderReader(std::string_view bytes, const std::filesystem::path& path) : bytes_(bytes), path_(path) {}

    /// The next token, skipping whitespace and comments; throws at the end of the file.
    std::string_view token(const char* what) {
        while (pos_ < bytes_.size()) {
            if (bytes_[pos_] == '#') {
                while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
            } else if (is_space(bytes_[pos_])) {
                ++pos_;
            } else {
                break;
            }
        }
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !is_space(bytes_[pos_]) && bytes_[pos_] != '#') ++pos_;
        if (start == pos_) throw image_error(path_, std::string("truncated: expected ") + what);
        return bytes_.substr(start, pos_ - start);
    }

    /// The next token as an integer in [low, high].
    long integer(const char* what, long low, long high) {
        const std::string_view text = token(what);
        long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < low || value > high) {
            throw image_error(path_, std::string("bad ") + what + " " + detail::quoted_printable(text) + " (expected " +
                                         std::to_string(low) + ".." + std::to_string(high) + ")");
        }
        return value;
    }

    /// The next token as a finite, non-zero real number.
    double real(const char* what) {
        const std::string_view text = token(what);
        double value = 0.0;
        const auto [end, error] = detail::double_from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || value == 0.0) {
            throw image_error(path_, std::string("bad ") + what + " " + detail::quoted_printable(text));
        }
        return value;
    }

    /// Consumes the single whitespace byte that ends a binary header; returns the data that follows.
    std::string_view binary_data() {
        // A comment may still sit between the last header value and the whitespace that ends the header.
        if (pos_ < bytes_.size() && bytes_[pos_] == '#') {
            while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
        }
        if (pos_ >= bytes_.size() || !is_space(bytes_[pos_])) {
            throw image_error(path_, "truncated: no pixel data after the header");
        }
        return bytes_.substr(pos_ + 1);
    }

    /// Bytes not yet consumed.
    std::size_t remaining() const { return bytes_.size() - pos_; }

  private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

    std::string_view bytes_;
    const std::filesystem::path& path_;
    std::size_t pos_ = 0;
};

/// An image's size, read before its pixels are allocated.
struct Size {
    int width = 0;
    int height = 0;
    std::size_t pixels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};

/// Throws unless the image has at most `max_pixels` pixels.
void check_pixel_count(Size size, std::size_t max_pixels, const std::filesystem::path& path) {
    if (size.pixels() > max_pixels) {
        throw image_error(path, "image size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                                    " has more than the " + std::to_string(max_pixels) + " pixels allowed");
    }
}

/// Reads width and height, each in 1..kMaxSide, and checks their product.
Size read_size(HeaderReader& header, std::size_t max_pixels, const std::filesystem::path& path) {
    const int width = static_cast<int>(header.integer("width", 1, kMaxSide));
    const int height = static_cast<int>(header.integer("height", 1, kMaxSide));
    check_pixel_count({width, height}, max_pixels, path);
    return {width, height};
}

/// Throws unless `available` bytes hold `needed` bytes.
void require_bytes(std::size_t available, std::size_t needed, const std::filesystem::path& path) {
    if (available < needed) {
        throw image_error(path, "truncated: " + std::to_string(available) + " bytes of pixel data, expected " +
                                    std::to_string(needed));
    }
}

/// Reads a PPM, P6 (binary, 16-bit big-endian when maxval > 255) or P3 (ASCII), as v / maxval.
Image read_ppm(std::string_view bytes, const std::filesystem::path& path, std::size_t max_pixels) {
    HeaderReader header(bytes, path);
    const std::string_view magic = header.token("the magic number P6 or P3");
    if (magic != "P6" && magic != "P3") throw image_error(path, "not a PPM file (magic number is not P6 or P3)");
    const Size size = read_size(header, max_pixels, path);
    const long maxval = header.integer("maxval", 1, 65535);
    const std::size_t samples = size.pixels() * 3;
    // Each ASCII sample takes a digit and a separator; each binary one 1 or 2 bytes.
    const std::size_t sample_bytes = magic == "P3" ? 2 : (maxval > 255 ? 2 : 1);
    require_bytes(header.remaining(), samples * sample_bytes - (magic == "P3" ? 1 : 0), path);
    Image image(size.width, size.height);
    auto store = [&](std::size_t i, long value) {
        if (value > maxval) {
            throw image_error(path, "sample " + std::to_string(value) + " exceeds maxval " + std::to_string(maxval));
        }
        image.pixels[i / 3][static_cast<int>(i % 3)] = static_cast<double>(value) / static_cast<double>(maxval);
    };
    if (magic == "P3") {
        for (std::size_t i = 0; i < samples; ++i) store(i, header.integer("sample", 0, 65535));
        return image;
    }
    const std::string_view data = header.binary_data();
    require_bytes(data.size(), samples * sample_bytes, path);
    for (std::size_t i = 0; i < samples; ++i) {
        const auto high = static_cast<unsigned char>(data[i * sample_bytes]);
        store(i, sample_bytes == 2 ? high * 256L + static_cast<unsigned char>(data[i * sample_bytes + 1]) : long{high});
    }
    return image;
}

/// Reads a PFM, "PF" (RGB) or "Pf" (grey), either byte order, bottom row first.
Image read_pfm(std::string_view bytes, const std::filesystem::path& path, std::size_t max_pixels) {
    HeaderReader header(bytes, path);
    const std::string_view magic = header.token("the magic number PF or Pf");
    if (magic != "PF" && magic != "Pf") throw image_error(path, "not a PFM file (magic number is not PF or Pf)");
    const int channels = magic == "PF" ? 3 : 1;
    const Size size = read_size(header, max_pixels, path);
    // A negative scale means little-endian floats, a positive one big-endian.
    const bool little_endian = header.real("scale") < 0.0;
    const std::string_view data = header.binary_data();
    require_bytes(data.size(), size.pixels() * channels * 4, path);
    Image image(size.width, size.height);
    std::size_t offset = 0;
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            for (int k = 0; k < channels; ++k, offset += 4) {
                std::uint32_t bits = 0;
                for (int b = 0; b < 4; ++b) {
                    const auto byte = static_cast<unsigned char>(data[offset + (little_endian ? 3 - b : b)]);
                    bits = (bits << 8) | byte;
                }
                const double value = std::bit_cast<float>(bits);
                if (!std::isfinite(value)) {
                    throw image_error(path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                                ") is not a finite number");
                }
                if (channels == 1) image.at(x, y) = Color(value);
                else image.at(x, y)[k] = value;
            }
        }
    }
    return image;
}

/// stb_image's reason for the last failure, when it is a short readable text.
/// (Found by fuzzing: for some corrupt files the system's stb reports bytes
/// that are not text.)
std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    const std::string_view text = reason ? std::string_view(reason, strnlen(reason, 81)) : std::string_view();
    const bool readable = !text.empty() && text.size() <= 80 && std::all_of(text.begin(), text.end(), [](char c) {
        return static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
    });
    return readable ? std::string(text) : "corrupt data";
}

/// Throws unless every chunk before IEND fits in the file. stb_image sizes its
/// buffers by the lengths the chunks claim (found by fuzzing: a 200-byte file
/// claiming a 2 GiB chunk made it allocate 2 GiB), so they are checked first.
void check_png_chunks(std::string_view bytes, const std::filesystem::path& path) {
    auto big_endian = [&](std::size_t at) {
        std::uint32_t value = 0;
        for (int i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
        return value;
    };
    for (std::size_t at = 8; at + 8 <= bytes.size();) {
        const std::uint32_t length = big_endian(at);
        const std::string_view type = bytes.substr(at + 4, 4);
        const std::size_t left = bytes.size() - at - 8;
        if (length > left || left - length < 4) {
            throw image_error(path, "corrupt PNG: chunk " + detail::quoted_printable(type) + " claims " +
                                        std::to_string(length) + " bytes, the file has " + std::to_string(left) + " left");
        }
        if (type == "IEND") return;
        at += 12 + std::size_t{length};
    }
}

/// Decodes a PNG (any bit depth and channel count) or a baseline / progressive
/// JPEG to 8-bit RGB with stb_image.
detail::Rgb8Image decode_with_stb(std::string_view bytes, const std::filesystem::path& path, std::size_t max_pixels,
                                  const std::string& kind) {
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw image_error(path, kind + " file too large");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    // Check the size before decoding, so a hostile header cannot make us allocate gigabytes.
    if (stbi_info_from_memory(data, size, &width, &height, &channels) == 0) {
        throw image_error(path, "not a readable " + kind + " file (" + stb_reason() + ")");
    }
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
        throw image_error(path, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " outside 1.." + std::to_string(kMaxSide) + " per side");
    }
    check_pixel_count({width, height}, max_pixels, path);
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(data, size, &width, &height, &channels, 3), stbi_image_free);
    if (!pixels) throw image_error(path, "cannot decode " + kind + " (" + stb_reason() + ")");
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    return {width, height, std::vector<std::uint8_t>(pixels.get(), pixels.get() + count)};
}

/// The 8-bit picture as linear colour: v / 255.
Image to_image(const detail::Rgb8Image& picture) {
    Image image(picture.width, picture.height);
    for (std::size_t i = 0; i < picture.rgb.size(); ++i) image.pixels[i / 3][static_cast<int>(i % 3)] = picture.rgb[i] / 255.0;
    return image;
}

detail::Rgb8Image decode_png(std::string_view bytes, const std::filesystem::path& path, std::size_t max_pixels) {
    static constexpr std::string_view signature("\x89PNG\r\n\x1a\n", 8);
    if (!bytes.starts_with(signature)) throw image_error(path, "not a PNG file (bad signature)");
    check_png_chunks(bytes, path);
    return decode_with_stb(bytes, path, max_pixels, "PNG");
}

detail::Rgb8Image decode_jpeg(std::string_view bytes, const std::filesystem::path& path, std::size_t max_pixels) {
    static constexpr std::string_view signature("\xff\xd8\xff", 3);
    if (!bytes.starts_with(signature)) throw image_error(path, "not a JPEG file (bad signature)");
    return decode_with_stb(bytes, path, max_pixels, "JPEG");
}

} // namespace

Image detail::decode_image(std::string_view bytes, ImageFormat format, const std::filesystem::path& path,
                           std::size_t max_pixels) {
    if (bytes.empty()) throw image_error(path, "empty file");
    switch (format) {
    case ImageFormat::png: return to_image(decode_png(bytes, path, max_pixels));
    case ImageFormat::ppm: return read_ppm(bytes, path, max_pixels);
    case ImageFormat::pfm: return read_pfm(bytes, path, max_pixels);
    case ImageFormat::jpeg: return to_image(decode_jpeg(bytes, path, max_pixels));
    }
    throw image_error(path, "unknown image format");
}

detail::Rgb8Image detail::read_rgb8(const std::filesystem::path& path) {
    const std::string bytes = read_file(path);
    const ImageFormat format = image_format(path);
    if (bytes.empty()) throw image_error(path, "empty file");
    if (format == ImageFormat::png) return decode_png(bytes, path, kMaxImagePixels);
    if (format == ImageFormat::jpeg) return decode_jpeg(bytes, path, kMaxImagePixels);
    throw image_error(path, "not a PNG or JPEG file (only those hold 8-bit pictures)");
}

Image read_image(const std::filesystem::path& path) {
    const std::string bytes = read_file(path); // first, so that a missing file or a folder is named as such
    return detail::decode_image(bytes, detail::image_format(path), path);
}

Image read_png_bytes(std::string_view bytes, const std::string& name) {
    return detail::decode_image(bytes, detail::ImageFormat::png, name);
}

} // namespace whitted
