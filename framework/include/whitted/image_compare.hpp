// Comparing a rendered image with a reference, as the tests and the grader do.
//
// Why: a student's renderer and the reference differ by rounding in a few
// pixels even when both are right, and a wrong one differs in many pixels or
// by a lot. The gate therefore counts pixels whose 8-bit value is off by more
// than a few steps, and also bounds the mean error. PSNR and the worst pixel
// are reported to help, never used to decide.
//
// Calibration (instructor/scripts/calibrate-gate.sh): the reference was compared with
// correct variants of itself on every lab scene, hidden scene and the classic
// scene. -O0 and clang builds match bit for bit; a secondary-ray offset 100
// times larger or smaller stays below 0.1 % failing pixels; an implementation
// computing primary rays and spheres in float fails up to 0.59 % of the pixels
// (paths that flip at grazing and total-internal-reflection boundaries) with a
// mean error of at most 0.21/255. The gate sits a few times above: 2 % and 1/255.
#pragma once

#include "whitted/image.hpp"

#include <cstddef>
#include <string>

namespace whitted {

/// The thresholds of the image gate; errors are in 8-bit steps divided by 255.
struct ImageGate {
    double pixel_tolerance = 4.0 / 255.0; // a pixel fails when its largest channel error exceeds this
    double max_failing_fraction = 0.02;   // at most 2 % of the pixels may fail...
    double max_mean_error = 1.0 / 255.0;  // ...and the mean error must stay below this
};

struct ImageDifference {
    bool same_size = false;
    std::size_t pixel_count = 0;
    std::size_t failing_pixels = 0;
    std::size_t non_finite_pixels = 0; // in the test image; they always fail
    double failing_fraction = 0.0;
    double mean_error = 0.0;           // mean over pixels of the largest channel error
    double max_error = 0.0;
    int worst_x = 0, worst_y = 0;      // where max_error is (first such pixel, top row 0)
    double psnr = 0.0;                 // in dB over all channels; infinite for identical images
    bool passed = false;

    /// One line with the numbers, for test output and reports.
    std::string summary() const;
};

/// Compares `test` with `reference` after quantising both to 8 bits as
/// `encoding` would write them.
ImageDifference compare_images(const Image& reference, const Image& test, const ImageGate& gate = {},
                               Encoding encoding = Encoding::linear);

} // namespace whitted
