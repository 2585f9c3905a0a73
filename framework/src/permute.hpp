// Moving the items of an array into a new order where they stand.
//
// Why: the scene's primitives (tens of megabytes in a big scene) and the BVH
// builder's boxes must follow the order the builder chose; a second array to copy
// them into would double their memory. Following the permutation's cycles moves
// each item once, with one item set aside per cycle.
//
// Why in two passes: along a cycle, the next item to move is wherever the
// permutation says, so in a big array each move waits for a cache miss, and the
// one after it cannot start until that miss is known. The first pass walks the
// cycles in the permutation alone (four bytes an item, mostly in the cache) and
// writes down the positions in the order the moves will visit them (four bytes
// an item more, where the scene's primitives take 96); the second moves the
// items, asking for each one from memory a few moves before it is needed.
#pragma once

#include "prefetch.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace whitted::detail {

/// Rearranges `items` so that items[k] becomes what items[from[k]] was (`from` is a permutation of its
/// indices); throws std::length_error for more than 2^31 - 1 items.
template <class T>
void permute_in_place(std::span<T> items, std::span<const std::uint32_t> from) {
    constexpr std::uint32_t kCycleStart = 0x80000000u; // marks a position that starts a cycle
    constexpr std::uint32_t kPosition = kCycleStart - 1;
    const std::size_t count = items.size();
    if (count > kPosition) throw std::length_error("permute_in_place: more than 2^31 - 1 items");
    // The visiting order: each cycle's positions, start first, skipping items already in place.
    std::vector<std::uint32_t> visits;
    visits.reserve(count);
    std::vector<bool> placed(count);
    for (std::size_t start = 0; start < count; ++start) {
        if (placed[start] || from[start] == start) continue;
        std::size_t k = start;
        visits.push_back(static_cast<std::uint32_t>(start) | kCycleStart);
        placed[k] = true;
        for (k = from[k]; k != start; k = from[k]) {
            visits.push_back(static_cast<std::uint32_t>(k));
            placed[k] = true;
        }
    }
    constexpr std::size_t kAhead = 16; // moves between asking for an item and moving it
    const auto ask = [&](std::size_t j) {
        if (j >= visits.size()) return;
        const char* item = reinterpret_cast<const char*>(&items[visits[j] & kPosition]);
        prefetch(item);
        prefetch(item + sizeof(T) - 1); // an item may straddle two cache lines
    };
    for (std::size_t j = 0; j < kAhead; ++j) ask(j);
    std::size_t j = 0;
    while (j < visits.size()) {
        const std::size_t start = visits[j] & kPosition;
        T first = std::move(items[start]);
        std::size_t k = start;
        for (ask(j + kAhead), ++j; j < visits.size() && !(visits[j] & kCycleStart); ask(j + kAhead), ++j) {
            items[k] = std::move(items[visits[j]]);
            k = visits[j];
        }
        items[k] = std::move(first);
    }
}

} // namespace whitted::detail
