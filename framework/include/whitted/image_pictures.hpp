// Pictures that explain an image comparison to a person: broken pixels made
// visible, the difference, and a heat map of the error. Used by `whitted
// render` and `whitted diff`, by the image tests and, through them, by the
// grader's report.
#pragma once

#include "whitted/image.hpp"

namespace whitted {

/// A copy of the image with NaN and infinite pixels shown as magenta.
Image with_broken_pixels_marked(const Image& image);

/// |a - b| per channel in 8-bit steps (linear encoding), 16 times brighter; NaN or infinite pixels are magenta.
Image difference_picture(const Image& a, const Image& b);

/// Each pixel's largest channel error in 8-bit steps on a fixed colour scale:
/// black (0), dark blue up to the gate's tolerance (4), then green (5),
/// yellow (16), red (64) and white (255). NaN or infinite pixels are magenta.
Image heat_picture(const Image& reference, const Image& test, Encoding encoding = Encoding::linear);

} // namespace whitted
