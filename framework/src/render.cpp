#include "whitted/render.hpp"

#include "whitted/engine/tiles.hpp"
#include "whitted/labs.hpp"

#include <atomic>
#include <chrono>
#include <mutex>
#include <vector>

namespace whitted {

RenderResult render(const Scene& scene, const RenderSettings& settings, int threads,
                    const ProgressCallback& progress) {
    // Whitted ray tracing: one ray through each pixel centre. Distribution ray
    // tracing (lab 7 on, samples asked for): lab 7's pixel_color averages samples.
    const bool distribution = settings.samples_per_pixel > 0 && settings.stage >= stage_number(Stage::anti_aliasing);
    return render_pixels(scene.camera(), threads, progress, [&](RayStats& stats) -> PixelFunction {
        if (distribution)
            return [tracer = Tracer(scene, settings, stats)](double x, double y) {
                return pixel_color(tracer, static_cast<int>(x), static_cast<int>(y)); // x, y: the pixel's centre
            };
        return [tracer = Tracer(scene, settings, stats)](double x, double y) { return tracer.trace_pixel(x, y); };
    });
}

RenderResult render_pixels(const Camera& camera, int threads, const ProgressCallback& progress,
                           const std::function<PixelFunction(RayStats& stats)>& make_pixel_function) {
    RenderResult result;
    result.image = Image(camera.res_x, camera.res_y);
    const int tiles = tile_count(camera.res_x, camera.res_y);
    std::atomic<int> tiles_done{0};
    std::mutex progress_mutex;
    threads = tile_threads(camera.res_x, camera.res_y, threads);
    std::vector<RayStats> stats(static_cast<std::size_t>(threads));
    const auto start = std::chrono::steady_clock::now();

    result.threads = for_each_tile(camera.res_x, camera.res_y, threads, [&](int thread_index) -> TileFunction {
        return [&, pixel = make_pixel_function(stats[static_cast<std::size_t>(thread_index)])](const Tile& tile) {
            for (int row = tile.y0; row < tile.y1; ++row) {
                // Image rows go top-down; the slides' viewport y goes bottom-up.
                const int y = camera.res_y - 1 - row;
                for (int x = tile.x0; x < tile.x1; ++x) result.image.at(x, row) = pixel(x + 0.5, y + 0.5);
            }
            const int done = ++tiles_done;
            if (progress) {
                std::lock_guard lock(progress_mutex);
                progress(static_cast<double>(done) / tiles);
            }
        };
    });
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const RayStats& s : stats) result.stats += s;
    return result;
}

} // namespace whitted
