#include "whitted/render.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace whitted {
namespace {

constexpr int kTileSize = 16;

} // namespace

RenderResult render(const Scene& scene, const RenderSettings& settings, int threads,
                    const ProgressCallback& progress) {
    return render_pixels(scene.camera(), threads, progress, [&](RayStats& stats) -> PixelFunction {
        return [tracer = Tracer(scene, settings, stats)](double x, double y) { return tracer.trace_pixel(x, y); };
    });
}

RenderResult render_pixels(const Camera& camera, int threads, const ProgressCallback& progress,
                           const std::function<PixelFunction(RayStats& stats)>& make_pixel_function) {
    RenderResult result;
    result.image = Image(camera.res_x, camera.res_y);
    const int tiles_x = (camera.res_x + kTileSize - 1) / kTileSize;
    const int tiles_y = (camera.res_y + kTileSize - 1) / kTileSize;
    const int tile_count = tiles_x * tiles_y;
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::max(1, std::min(threads, tile_count));

    std::atomic<int> next_tile{0};
    std::atomic<int> tiles_done{0};
    std::mutex progress_mutex;
    std::vector<RayStats> stats(threads);
    const auto start = std::chrono::steady_clock::now();

    auto render_tiles = [&](int thread_index) {
        const PixelFunction pixel = make_pixel_function(stats[thread_index]);
        for (int tile = next_tile++; tile < tile_count; tile = next_tile++) {
            const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
            const int x1 = std::min(x0 + kTileSize, camera.res_x), y1 = std::min(y0 + kTileSize, camera.res_y);
            for (int row = y0; row < y1; ++row) {
                // Image rows go top-down; the slides' viewport y goes bottom-up.
                const int y = camera.res_y - 1 - row;
                for (int x = x0; x < x1; ++x) result.image.at(x, row) = pixel(x + 0.5, y + 0.5);
            }
            const int done = ++tiles_done;
            if (progress) {
                std::lock_guard lock(progress_mutex);
                progress(static_cast<double>(done) / tile_count);
            }
        }
    };
    // The first exception thrown in any thread (an unfinished lab, say) stops
    // every thread and is rethrown to the caller.
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&](int thread_index) {
        try {
            render_tiles(thread_index);
        } catch (...) {
            std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            next_tile = tile_count; // the other threads stop after their current tile
        }
    };
    std::vector<std::jthread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(worker, i);
    worker(0);
    pool.clear(); // joins
    if (failure) std::rethrow_exception(failure);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.threads = threads;
    for (const RayStats& s : stats) result.stats += s;
    return result;
}

} // namespace whitted
