#include "whitted/render.hpp"

#include "lab_call.hpp"

#include "whitted/engine/tiles.hpp"
#include "whitted/labs.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <vector>

namespace whitted {

Color sampled_pixel_color(const Tracer& tracer, int x, int y) {
    return detail::call_lab("pixel_color", pixel_color, tracer, x, y);
}

Vec2 sample_position(const PixelSample& sample, int count) {
    const Vec2 numbers = sample_numbers(sample, SampleUse::pixel);
    return Vec2(sample.x, sample.y) + detail::call_lab("stratified_sample", stratified_sample, sample.index, count, numbers);
}

RenderResult render(const Scene& scene, const RenderSettings& settings, int threads,
                    const ProgressCallback& progress) {
    // Whitted ray tracing: one ray through each pixel centre. Distribution ray
    // tracing (lab 7 on, samples asked for): lab 7's pixel_color averages samples.
    const bool distribution = settings.samples_per_pixel > 0 && settings.stage >= stage_number(Stage::anti_aliasing);
    if (distribution)
        return render_pixels(scene.camera(), threads, progress, [&](RayStats& stats) -> PixelFunction {
            return [tracer = Tracer(scene, settings, stats)](double x, double y) {
                return sampled_pixel_color(tracer, static_cast<int>(x), static_cast<int>(y)); // x, y: the pixel's centre
            };
        });
    // Whitted: blocks of 4 x 4 pixels, whose eye rays and shadow feelers go as packets.
    return render_blocks(scene.camera(), threads, progress, [&](RayStats& stats) -> BlockFunction {
        return [tracer = Tracer(scene, settings, stats)](std::span<const Vec2> positions, std::span<Color> colors) {
            tracer.trace_pixels(positions, colors);
        };
    });
}

RenderResult render_pixels(const Camera& camera, int threads, const ProgressCallback& progress,
                           const std::function<PixelFunction(RayStats& stats)>& make_pixel_function) {
    return render_blocks(camera, threads, progress, [&](RayStats& stats) -> BlockFunction {
        return [pixel = make_pixel_function(stats)](std::span<const Vec2> positions, std::span<Color> colors) {
            for (std::size_t i = 0; i < positions.size(); ++i) colors[i] = pixel(positions[i].x, positions[i].y);
        };
    });
}

RenderResult render_blocks(const Camera& camera, int threads, const ProgressCallback& progress,
                           const std::function<BlockFunction(RayStats& stats)>& make_block_function) {
    RenderResult result;
    result.image = Image(camera.res_x, camera.res_y);
    const int tiles = tile_count(camera.res_x, camera.res_y);
    std::atomic<int> tiles_done{0};
    std::mutex progress_mutex;
    threads = tile_threads(camera.res_x, camera.res_y, threads);
    std::vector<PerThread<RayStats>> stats(static_cast<std::size_t>(threads));
    const auto start = std::chrono::steady_clock::now();

    result.threads = for_each_tile(camera.res_x, camera.res_y, threads, [&](int thread_index) -> TileFunction {
        return [&, block = make_block_function(stats[static_cast<std::size_t>(thread_index)].value)](const Tile& tile) {
            constexpr int kBlock = 4;
            Vec2 positions[kBlock * kBlock];
            Color colors[kBlock * kBlock];
            for (int row0 = tile.y0; row0 < tile.y1; row0 += kBlock) {
                for (int x0 = tile.x0; x0 < tile.x1; x0 += kBlock) {
                    const int rows = std::min(kBlock, tile.y1 - row0), columns = std::min(kBlock, tile.x1 - x0);
                    for (int r = 0; r < rows; ++r) {
                        // Image rows go top-down; the slides' viewport y goes bottom-up.
                        const int y = camera.res_y - 1 - (row0 + r);
                        for (int c = 0; c < columns; ++c) positions[r * columns + c] = Vec2(x0 + c + 0.5, y + 0.5);
                    }
                    const auto count = static_cast<std::size_t>(rows * columns);
                    block(std::span(positions, count), std::span(colors, count));
                    for (int r = 0; r < rows; ++r)
                        for (int c = 0; c < columns; ++c) result.image.at(x0 + c, row0 + r) = colors[r * columns + c];
                }
            }
            const int done = ++tiles_done;
            if (progress) {
                std::lock_guard lock(progress_mutex);
                progress(static_cast<double>(done) / tiles);
            }
        };
    });
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const PerThread<RayStats>& s : stats) result.stats += s.value;
    return result;
}

} // namespace whitted
