// Pictures and numbers that explain an image comparison to a person: the
// difference, a heat map of the error, and the gate's numbers as JSON (read by
// `whitted grade` for partial credit and its HTML report).
#pragma once

#include "whitted/image.hpp"
#include "whitted/image_compare.hpp"

#include <filesystem>
#include <string>

namespace whitted::testing_helpers {

/// A copy of the image with NaN and infinite pixels shown as magenta.
Image with_broken_pixels_marked(const Image& image);

/// |a - b| per channel, 16 times brighter (both images must be finite and of one size).
Image difference_picture(const Image& a, const Image& b);

/// Each pixel's largest channel error in 8-bit steps on a fixed colour scale:
/// black (0), dark blue up to the gate's tolerance (4), then green (5),
/// yellow (16), red (64) and white (255). NaN or infinite pixels are magenta.
Image heat_picture(const Image& reference, const Image& test, Encoding encoding = Encoding::linear);

/// Writes the gate's numbers as a small JSON object (errors as fractions of
/// full scale; PSNR is null for identical images).
void write_gate_numbers(const ImageDifference& difference, const std::string& scene, int stage,
                        const std::filesystem::path& file);

} // namespace whitted::testing_helpers
