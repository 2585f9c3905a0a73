#include "whitted/image_pictures.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace whitted {
namespace {

const Color kMagenta(1.0, 0.0, 1.0);

// The heat map's fixed scale: error in 8-bit steps -> colour, linear in between.
struct HeatStop {
    double steps;
    Color color;
};
const std::array<HeatStop, 6> kHeatScale = {{{0.0, Color(0.0, 0.0, 0.0)},
                                             {4.0, Color(0.0, 0.0, 0.55)},
                                             {5.0, Color(0.0, 0.8, 0.0)},
                                             {16.0, Color(1.0, 1.0, 0.0)},
                                             {64.0, Color(1.0, 0.0, 0.0)},
                                             {255.0, Color(1.0, 1.0, 1.0)}}};

Color heat_color(double steps) {
    for (std::size_t i = 1; i < kHeatScale.size(); ++i) {
        if (steps <= kHeatScale[i].steps) {
            const HeatStop& low = kHeatScale[i - 1];
            const HeatStop& high = kHeatScale[i];
            const double t = (steps - low.steps) / (high.steps - low.steps);
            return low.color + (high.color - low.color) * t;
        }
    }
    return kHeatScale.back().color;
}

} // namespace

Image with_broken_pixels_marked(const Image& image) {
    Image shown = image;
    for (Color& c : shown.pixels)
        if (!is_finite(c)) c = kMagenta;
    return shown;
}

Image difference_picture(const Image& a, const Image& b) {
    // From the 8-bit values the files hold, so that images that match exactly give black.
    Image diff(a.width, a.height);
    for (std::size_t i = 0; i < diff.pixels.size(); ++i) {
        if (!is_finite(a.pixels[i]) || !is_finite(b.pixels[i])) {
            diff.pixels[i] = kMagenta;
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            const int steps = std::abs(int(to_byte(a.pixels[i][c], Encoding::linear)) - int(to_byte(b.pixels[i][c], Encoding::linear)));
            diff.pixels[i][c] = std::min(1.0, steps * 16.0 / 255.0);
        }
    }
    return diff;
}

Image heat_picture(const Image& reference, const Image& test, Encoding encoding) {
    Image heat(test.width, test.height);
    for (std::size_t i = 0; i < heat.pixels.size(); ++i) {
        const Color& r = reference.pixels[i];
        const Color& t = test.pixels[i];
        if (!is_finite(r) || !is_finite(t)) {
            heat.pixels[i] = kMagenta;
            continue;
        }
        int steps = 0;
        for (int c = 0; c < 3; ++c)
            steps = std::max(steps, std::abs(int(to_byte(r[c], encoding)) - int(to_byte(t[c], encoding))));
        heat.pixels[i] = heat_color(steps);
    }
    return heat;
}

} // namespace whitted
