// The image split into 16 x 16 tiles, handed out to threads.
//
// Why: every pixel loop of the project (the renderer, the diagnostic passes,
// the benchmark's ray traffic) shares one way of splitting the work, so that
// what each thread does stays independent of how many threads there are.
#pragma once

#include <functional>

namespace whitted {

/// The pixels [x0, x1) x [y0, y1) of an image, rows counted from the top.
struct Tile {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// What one thread does with each tile it takes.
using TileFunction = std::function<void(const Tile& tile)>;

/// Runs over every tile of a width x height image on `threads` threads (0: one
/// per hardware thread; never more than there are tiles). `for_thread` is called
/// once in each thread, with its index, and returns what that thread does with
/// each tile. The first exception thrown in any thread stops the others after
/// their current tile and is rethrown here. Returns the number of threads used.
/// When the threads are exactly as many as the processors the caller may use,
/// each runs pinned to one of them (the caller gets its own set back afterwards),
/// so threads that `for_thread` or a tile starts, and nested calls, share that one.
int for_each_tile(int width, int height, int threads, const std::function<TileFunction(int thread_index)>& for_thread);

/// The number of tiles of a width x height image.
int tile_count(int width, int height);

/// The number of threads for_each_tile runs for `threads` (0: one per hardware thread).
int tile_threads(int width, int height, int threads);

/// One thread's own state (its ray counts) in a vector of them, on cache lines of
/// its own: side by side, each thread's writes would send the shared line back
/// and forth between the cores (it cost the benchmark's Embree harness 40 %).
template <class T>
struct alignas(64) PerThread {
    T value{};
};

} // namespace whitted
