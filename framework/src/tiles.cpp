#include "whitted/engine/tiles.hpp"

#include "lab_call.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace whitted {
namespace {

constexpr int kTileSize = 16;

// Keeps each thread of for_each_tile on a processor of its own while it runs.
//
// Why: Linux puts a new thread on its creator's processor, where it waits
// for the creator's time slice to end (about 4 ms here) and shares that
// processor until the system moves one of them, so the two threads of a short
// render often ran on one processor for much of it (measured: two threads of
// 10 ms of work each took 17-18 ms together). When the threads take every
// processor the caller may use, each is created while the caller runs on that
// thread's processor, so it starts there at once and stays there (10.5 ms);
// the caller then takes the first one, and gets its own set back at the end.
// With fewer threads than processors nothing is pinned (every call, in every
// process, would pick the same ones), nor with more.
class ThreadPlacement {
  public:
    /// Plans the processors of `threads` threads: one each, or none when they are not as many as the caller's.
    explicit ThreadPlacement(int threads) {
#if defined(__linux__)
        if (threads < 2 || pthread_getaffinity_np(pthread_self(), sizeof allowed_, &allowed_) != 0) return;
        if (CPU_COUNT(&allowed_) != threads) return;
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &allowed_)) cpus_.push_back(cpu);
#else
        (void)threads;
#endif
    }
    ThreadPlacement(const ThreadPlacement&) = delete;
    ThreadPlacement& operator=(const ThreadPlacement&) = delete;

    /// Moves the calling thread (for_each_tile's caller) to thread `index`'s
    /// processor: a thread it creates now starts there.
    void move_caller_to(int index) const {
#if defined(__linux__)
        if (cpus_.empty()) return;
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(cpus_[static_cast<std::size_t>(index)], &one);
        pthread_setaffinity_np(pthread_self(), sizeof one, &one); // a refusal (a sandbox) only costs speed
#else
        (void)index;
#endif
    }

    /// Gives the calling thread (the caller's, thread 0) back the processors it had.
    ~ThreadPlacement() {
#if defined(__linux__)
        if (!cpus_.empty()) pthread_setaffinity_np(pthread_self(), sizeof allowed_, &allowed_);
#endif
    }

  private:
#if defined(__linux__)
    cpu_set_t allowed_{};
#endif
    std::vector<int> cpus_;
};

// The threads of one for_each_tile call, each joined when the call's block ends,
// whatever ends it: what std::jthread does, which libc++ 14 and the libc++ of the
// Xcode versions students have lack.
class JoiningThreads {
  public:
    JoiningThreads() = default;
    JoiningThreads(const JoiningThreads&) = delete;
    JoiningThreads& operator=(const JoiningThreads&) = delete;

    /// Starts a thread that runs a copy of `function` with `thread_index`.
    template <class Function>
    void start(const Function& function, int thread_index) {
        threads_.emplace_back(function, thread_index);
    }

    /// Waits for every thread started.
    ~JoiningThreads() {
        for (std::thread& thread : threads_) thread.join();
    }

  private:
    std::vector<std::thread> threads_;
};

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
    const ThreadPlacement placement(threads);
    auto worker = [&](int thread_index) {
        const detail::CrashReportStack crash_report_stack; // lab code runs here: a crash must be reported, an overflow too
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
        JoiningThreads pool;
        for (int i = 1; i < threads; ++i) {
            placement.move_caller_to(i); // thread i inherits that processor
            pool.start(worker, i);
        }
        placement.move_caller_to(0);
        worker(0);
    } // joins
    if (failure) std::rethrow_exception(failure);
    return threads;
}

} // namespace whitted
