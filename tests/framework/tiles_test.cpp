// for_each_tile: every tile once, whatever the thread count, and where its threads run.
#include "whitted/engine/tiles.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <vector>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

using namespace whitted;

namespace {

#if defined(__linux__)
// The processors the calling thread may run on.
cpu_set_t own_processors() {
    cpu_set_t set;
    CPU_ZERO(&set);
    pthread_getaffinity_np(pthread_self(), sizeof set, &set);
    return set;
}

// True when this thread may choose its processors (a sandbox may refuse the call).
bool may_pin() {
    const cpu_set_t set = own_processors();
    return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}
#endif

// How many times each pixel of a width x height image was handed out (and the caller's processors come back).
std::vector<int> pixel_visits(int width, int height, int threads) {
#if defined(__linux__)
    const cpu_set_t before = own_processors();
#endif
    std::vector<std::atomic<int>> visits(static_cast<std::size_t>(width) * height);
    for_each_tile(width, height, threads, [&](int) -> TileFunction {
        return [&](const Tile& tile) {
            for (int y = tile.y0; y < tile.y1; ++y)
                for (int x = tile.x0; x < tile.x1; ++x) ++visits[static_cast<std::size_t>(y) * width + x];
        };
    });
#if defined(__linux__)
    const cpu_set_t after = own_processors();
    EXPECT_TRUE(CPU_EQUAL(&before, &after)) << threads << " threads: the caller kept the processor it was pinned to";
#endif
    std::vector<int> counts;
    for (const auto& v : visits) counts.push_back(v.load());
    return counts;
}

} // namespace

TEST(Tiles, EveryPixelOnceWhateverTheThreadCount) {
    // 37 x 21 is not a multiple of the tile size: the last row and column of tiles are partial.
    for (const int threads : {1, 2, 3, 8})
        for (const int count : pixel_visits(37, 21, threads)) ASSERT_EQ(count, 1) << threads << " threads";
}

TEST(Tiles, NeverMoreThreadsThanTiles) {
    EXPECT_EQ(tile_count(16, 16), 1);
    EXPECT_EQ(tile_threads(16, 16, 8), 1);
    EXPECT_EQ(tile_threads(40, 16, 8), 3);
}

#if defined(__linux__)
TEST(Tiles, EachThreadRunsOnAProcessorOfItsOwnAndTheCallerGetsItsOwnBack) {
    const cpu_set_t before = own_processors();
    const int processors = CPU_COUNT(&before);
    if (processors < 2) GTEST_SKIP() << "this process may run on one processor only";
    if (!may_pin()) GTEST_SKIP() << "this process may not choose its threads' processors";
    std::mutex mutex;
    std::vector<cpu_set_t> placements;
    // As many threads as processors: each gets one (the case of `whitted render` on the whole machine).
    for_each_tile(16 * processors, 16, processors, [&](int) -> TileFunction {
        std::lock_guard lock(mutex);
        placements.push_back(own_processors());
        return [](const Tile&) {};
    });
    ASSERT_EQ(placements.size(), static_cast<std::size_t>(processors));
    std::set<int> cpus;
    for (const cpu_set_t& placement : placements) {
        ASSERT_EQ(CPU_COUNT(&placement), 1) << "a thread of for_each_tile may move between processors";
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &placement)) {
                EXPECT_TRUE(CPU_ISSET(cpu, &before)) << "pinned to processor " << cpu << ", which the process may not use";
                cpus.insert(cpu);
            }
    }
    EXPECT_EQ(cpus.size(), static_cast<std::size_t>(processors)) << "two threads pinned to one processor";
    const cpu_set_t after = own_processors();
    EXPECT_TRUE(CPU_EQUAL(&before, &after)) << "the calling thread kept the one processor it was pinned to";
}

TEST(Tiles, TheCallerGetsItsProcessorsBackWhenATileThrows) {
    // (With as many threads as processors, so that the caller was moved.)
    const cpu_set_t before = own_processors();
    const int threads = CPU_COUNT(&before);
    EXPECT_THROW(for_each_tile(16 * threads, 16, threads,
                               [](int) -> TileFunction { return [](const Tile&) { throw std::runtime_error("stop"); }; }),
                 std::runtime_error);
    const cpu_set_t after = own_processors();
    EXPECT_TRUE(CPU_EQUAL(&before, &after));
}

TEST(Tiles, MoreThreadsThanProcessorsAreNotPinned) {
    // Pinning two threads to one processor would serialise them for good: with
    // more threads than processors the system places them.
    const cpu_set_t before = own_processors();
    const int threads = CPU_COUNT(&before) + 1;
    std::mutex mutex;
    int pinned = 0;
    for_each_tile(16 * threads, 16, threads, [&](int) -> TileFunction {
        const cpu_set_t placement = own_processors();
        std::lock_guard lock(mutex);
        if (CPU_COUNT(&placement) == 1 && CPU_COUNT(&before) > 1) ++pinned;
        return [](const Tile&) {};
    });
    EXPECT_EQ(pinned, 0);
}
#endif
