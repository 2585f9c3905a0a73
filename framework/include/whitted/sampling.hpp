// The random numbers of distribution ray tracing, the same in every run.
//
// Why: a pixel sample's position, its point on the lens and its point on an
// area light all start from numbers in [0, 1). Here they are a pure function
// of which pixel, which of its samples, what they are for and which one: no
// generator state, so the picture is bit for bit the same whatever the number
// of threads or the order of the calls, and a correct student's picture equals
// the reference picture. The labs only map these numbers to positions.
#pragma once

#include "whitted/math.hpp"

#include <cstdint>

namespace whitted {

/// What a pair of numbers is for: the same sample draws independent numbers for each use.
enum class SampleUse : std::uint32_t { pixel = 1, lens = 2, light = 3 };

/// One sample of one pixel: the pixel's column x (from the left) and row y
/// (from the bottom, like the viewport), and which of its samples (0, 1, ...).
struct PixelSample {
    int x = 0;
    int y = 0;
    int index = 0;

    friend bool operator==(const PixelSample&, const PixelSample&) = default;
};

/// Two numbers in [0, 1) for this sample and use; `n` tells apart several pairs
/// of one use (the samples of several lights). Well spread and independent.
Vec2 sample_numbers(const PixelSample& sample, SampleUse use, std::uint32_t n = 0);

} // namespace whitted
