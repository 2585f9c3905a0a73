// Lab 7 — anti-aliasing: several samples a pixel instead of one ray through its
// centre, spread over the pixel on a jittered grid and averaged.
// Handout: docs/labs/07_anti_aliasing.md. Tests: make test LAB=7
#include "whitted/labs.hpp"

namespace whitted {

// Where sample `index` of `count` lies in its pixel, as (x, y) in [0, 1)^2.
// The pixel is cut into a grid of cols x rows equal cells: rows is the largest
// divisor of count that is at most sqrt(count) (3 for 9, 2 for 8, 1 for 5) and
// cols = count / rows. Cells are numbered row by row from the bottom left;
// sample `index` lies in cell `index`, at the place u (u.x, u.y in [0, 1)) within it.
Vec2 stratified_sample(int index, int count, Vec2 u) {
    not_implemented();
}

// The colour of pixel (x, y): column x from the left, row y from the bottom.
// Average tracer.settings().samples_per_pixel samples. Sample k is the pixel
// sample {x, y, k}: its numbers are sample_numbers(sample, SampleUse::pixel),
// stratified_sample places it in the pixel, and tracer.trace_sample(sample, px, py)
// traces it through viewport position (px, py) (the pixel spans x..x+1, y..y+1).
Color pixel_color(const Tracer& tracer, int x, int y) {
    not_implemented();
}

} // namespace whitted
