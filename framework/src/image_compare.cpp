#include "whitted/image_compare.hpp"

#include <cmath>
#include <cstdio>

namespace whitted {

std::string ImageDifference::summary() const {
    if (!same_size) return "the images have different sizes";
    char line[256];
    std::snprintf(line, sizeof line,
                  "%zu of %zu pixels off by more than the tolerance (%.3f %%), mean error %.2f/255, "
                  "max error %.0f/255 at (%d, %d), PSNR %.1f dB, %zu NaN/Inf pixels: %s",
                  failing_pixels, pixel_count, 100.0 * failing_fraction, 255.0 * mean_error, 255.0 * max_error,
                  worst_x, worst_y, psnr, non_finite_pixels, passed ? "pass" : "FAIL");
    return line;
}

ImageDifference compare_images(const Image& reference, const Image& test, const ImageGate& gate, Encoding encoding) {
    ImageDifference d;
    d.same_size = reference.width == test.width && reference.height == test.height;
    if (!d.same_size) return d;
    d.pixel_count = test.pixels.size();
    double error_sum = 0.0, squared_sum = 0.0;
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            const Color& r = reference.at(x, y);
            const Color& t = test.at(x, y);
            double error = 1.0; // a NaN or infinite pixel counts as fully wrong, never cast to 8 bits
            if (is_finite(t) && is_finite(r)) {
                error = 0.0;
                for (int c = 0; c < 3; ++c) {
                    const double e = std::abs(int(to_byte(r[c], encoding)) - int(to_byte(t[c], encoding))) / 255.0;
                    error = std::max(error, e);
                    squared_sum += e * e;
                }
            } else {
                ++d.non_finite_pixels;
                squared_sum += 3.0;
            }
            error_sum += error;
            if (error > gate.pixel_tolerance) ++d.failing_pixels;
            if (error > d.max_error) {
                d.max_error = error;
                d.worst_x = x;
                d.worst_y = y;
            }
        }
    }
    const double n = static_cast<double>(d.pixel_count);
    d.failing_fraction = n > 0 ? d.failing_pixels / n : 0.0;
    d.mean_error = n > 0 ? error_sum / n : 0.0;
    const double mse = n > 0 ? squared_sum / (3.0 * n) : 0.0;
    d.psnr = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : kInfinity;
    d.passed = d.non_finite_pixels == 0 && d.failing_fraction <= gate.max_failing_fraction &&
               d.mean_error <= gate.max_mean_error;
    return d;
}

} // namespace whitted
