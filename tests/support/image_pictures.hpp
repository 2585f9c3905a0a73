// The gate's numbers as JSON, read by `whitted grade` for partial credit and
// its HTML report. The pictures themselves come from the framework
// (whitted/image_pictures.hpp).
#pragma once

#include "whitted/image_compare.hpp"
#include "whitted/image_pictures.hpp"

#include <filesystem>
#include <string>

namespace whitted::testing_helpers {

using whitted::difference_picture;
using whitted::heat_picture;
using whitted::with_broken_pixels_marked;

/// Writes the gate's numbers as a small JSON object (errors as fractions of
/// full scale; PSNR is null for identical images).
void write_gate_numbers(const ImageDifference& difference, const std::string& scene, int stage,
                        const std::filesystem::path& file);

} // namespace whitted::testing_helpers
