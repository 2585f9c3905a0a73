// What the fuzz targets check beyond "no crash": the shared property tests.
//
// Why: a sanitizer finds memory errors and undefined behaviour by itself, but
// not a wrong answer. Each target also demands that an error message is one
// line naming the input, that accepted scenes hold only finite numbers, and
// that a tiny render of an accepted scene has no NaN pixel and gives the same
// image, bit for bit, through the fast leaf kernels and through the labs' code.
// A broken property aborts with a message, which libFuzzer reports as a crash.
#pragma once

#include "whitted/scene_loader.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace whitted::fuzz {

/// Aborts with "fuzz property broken: what" on stderr.
[[noreturn]] void broken(std::string_view what);

/// Loads the bytes as a scene of the dialect and renders what it accepts at 8x6 pixels.
void check_scene_input(const std::uint8_t* data, std::size_t size, Dialect dialect);

/// Decodes the bytes as an image (the format sniffed from the first bytes).
void check_image_input(const std::uint8_t* data, std::size_t size);

} // namespace whitted::fuzz
