// Rendering a whole image: the pixel loop, split into tiles over threads.
//
// Why: each pixel is computed on its own from the read-only scene, so the
// image is bit-for-bit the same whatever the number of threads or the order in
// which tiles finish. Threads only take the next tile number from a counter.
#pragma once

#include "whitted/image.hpp"
#include "whitted/tracer.hpp"

#include <functional>

namespace whitted {

struct RenderResult {
    Image image;
    RayStats stats;
    double seconds = 0.0;   // wall-clock time of the pixel loop
    int threads = 1;        // threads that rendered
};

/// Called now and then from the rendering threads with the fraction of tiles done (0..1).
using ProgressCallback = std::function<void(double fraction_done)>;

/// Renders the scene's camera view at the camera's resolution with `threads`
/// threads (0: one per hardware thread).
RenderResult render(const Scene& scene, const RenderSettings& settings, int threads = 0,
                    const ProgressCallback& progress = {});

/// The colour render() gives pixel (x, y) (column, and row from the bottom) when the tracer's settings
/// ask for samples (lab 7, anti-aliasing): the labs' pixel_color().
Color sampled_pixel_color(const Tracer& tracer, int x, int y);

/// Where the handout's pixel_color() traces `sample` of its pixel when the pixel has `count` samples:
/// the viewport position (x, y) + stratified_sample(index, count, sample_numbers(sample, SampleUse::pixel)).
/// For whitted trace: lab 7's pixel_color() places its samples itself (grading refuses a lab 7 that calls this).
Vec2 sample_position(const PixelSample& sample, int count);

/// The colour of the pixel whose centre is at viewport position (x, y) (see primary_ray).
using PixelFunction = std::function<Color(double x, double y)>;

/// The same pixel loop for any per-pixel computation (the diagnostic passes):
/// `make_pixel_function` is called once per thread with that thread's ray
/// counts and returns the function that computes its pixels.
RenderResult render_pixels(const Camera& camera, int threads, const ProgressCallback& progress,
                           const std::function<PixelFunction(RayStats& stats)>& make_pixel_function);

/// The colours of the pixels whose centres are at positions[i], into colors[i].
using BlockFunction = std::function<void(std::span<const Vec2> positions, std::span<Color> colors)>;

/// render_pixels() for computations that do a block of neighbouring pixels
/// (at most 4 x 4) at once: the same pixels, in the same tiles.
RenderResult render_blocks(const Camera& camera, int threads, const ProgressCallback& progress,
                           const std::function<BlockFunction(RayStats& stats)>& make_block_function);

} // namespace whitted
