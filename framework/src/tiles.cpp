#include "whitted/engine/tiles.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace whitted {
namespace {

constexpr int kTileSize = 16;

} // namespace

int tile_count(int width, int height) {
    return ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
}

int tile_threads(int width, int height, int threads) {
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return std::max(1, std::min(threads, tile_count(width, height)));
}

int for_each_tile(int width, int height, int threads, const std::function<TileFunction(int thread_index)>& for_thread) {
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles = tile_count(width, height);
    threads = tile_threads(width, height, threads);

    std::atomic<int> next_tile{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&](int thread_index) {
        try {
            const TileFunction per_tile = for_thread(thread_index);
            for (int index = next_tile++; index < tiles; index = next_tile++) {
                Tile tile;
                tile.x0 = (index % tiles_x) * kTileSize;
                tile.y0 = (index / tiles_x) * kTileSize;
                tile.x1 = std::min(tile.x0 + kTileSize, width);
                tile.y1 = std::min(tile.y0 + kTileSize, height);
                per_tile(tile);
            }
        } catch (...) {
            std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            next_tile = tiles; // the other threads stop after their current tile
        }
    };
    {
        std::vector<std::jthread> pool;
        for (int i = 1; i < threads; ++i) pool.emplace_back(worker, i);
        worker(0);
    } // joins
    if (failure) std::rethrow_exception(failure);
    return threads;
}

} // namespace whitted
