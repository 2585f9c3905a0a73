// Lab 7 — anti-aliasing: several jittered samples a pixel, averaged.
#include "whitted/labs.hpp"

namespace whitted {

Vec2 stratified_sample(int index, int count, Vec2 u) {
    // The grid: as square as count allows (3 x 3 for 9, 4 x 2 for 8, 5 x 1 for 5).
    int rows = 1;
    for (int r = 1; r * r <= count; ++r)
        if (count % r == 0) rows = r;
    const int cols = count / rows;
    const int col = index % cols;
    const int row = index / cols;
    // Jittered: anywhere in the cell, so that no two pixels sample the same pattern.
    return Vec2((col + u.x) / cols, (row + u.y) / rows);
}

Color pixel_color(const Tracer& tracer, int x, int y) {
    const int count = tracer.settings().samples_per_pixel;
    Color sum(0.0);
    for (int k = 0; k < count; ++k) {
        const PixelSample sample{x, y, k};
        const Vec2 place = stratified_sample(k, count, sample_numbers(sample, SampleUse::pixel));
        sum += tracer.trace_sample(sample, x + place.x, y + place.y);
    }
    return sum / static_cast<double>(count); // the box filter: every sample counts the same
}

} // namespace whitted
